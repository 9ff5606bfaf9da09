#!/usr/bin/env bash
# Installs what is missing, builds everything and runs the whole test suite with CTest
# (unit, gpu on lavapipe with validation, sample end-to-end), then the unit tests under
# sanitizers and the file readers' fuzz targets. Extra arguments go to the first ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
tools/build.sh
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-/tmp}"
# lavapipe: fixed thread count so GPU timings are comparable between runs.
export LP_NUM_THREADS="${LP_NUM_THREADS:-2}"
ctest --preset default "$@"
# The unit tests again under AddressSanitizer and UBSan, then every file reader fuzzed for a
# fixed time (libFuzzer, ASan, UBSan): each is its own build (build-sanitize/, build-fuzz/).
tools/sanitize.sh
tools/fuzz.sh
