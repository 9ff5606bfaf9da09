#!/usr/bin/env bash
# Installs what is missing, builds, and runs the sample: in a window when a display is
# available, otherwise a headless capture of a few frames into out/. Extra arguments go to
# the sample (see `build/bin/sample_game --help`).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
tools/build.sh --target sample_game
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp}"
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then
  exec build/bin/sample_game "$@"
fi
echo "run_sample: no display, rendering a headless capture into out/"
exec build/bin/sample_game --headless --frames 5 --capture out "$@"
