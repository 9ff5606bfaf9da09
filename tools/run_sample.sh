#!/usr/bin/env bash
# Installs what is missing, builds, and runs the sample: in a window when a display is
# available, otherwise a headless run of 48 frames whose last is captured into out/. Extra
# arguments go to the sample (see `build/bin/sample_game --help`).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
tools/build.sh --target sample_game
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp}"
# Without a display the sample itself runs headless: 48 frames (converged clouds), the last
# captured into out/.
exec build/bin/sample_game "$@"
