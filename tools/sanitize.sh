#!/usr/bin/env bash
# Builds the unit tests with AddressSanitizer and UBSan (the `sanitize` preset, build-sanitize/)
# and runs them: any out-of-bounds access, use after free, leak or undefined behaviour fails.
# Extra arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ ! -f build-sanitize/CMakeCache.txt ]]; then
  cmake --preset sanitize >/dev/null
fi
cmake --build --preset sanitize
ctest --preset sanitize "$@"
