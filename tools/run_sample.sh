#!/usr/bin/env bash
# Installs what is missing, builds, and runs the sample: in a window when a display is
# available, otherwise a headless run of 48 frames whose last is captured into out/. Extra
# arguments go to the sample (see `build/bin/sample_game --help`).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
tools/build.sh --target sample_game
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp}"
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then
  exec build/bin/sample_game "$@"
fi
# 48 frames: the clouds (Medium) refresh each pixel once in 16 frames, so the last frame, the
# one captured, has converged.
echo "run_sample: no display: rendering 48 frames headless and capturing the last (converged"
echo "  clouds: every pixel traced three times) into out/"
exec build/bin/sample_game --headless --frames 48 --capture out "$@"
