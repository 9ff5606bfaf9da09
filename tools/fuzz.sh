#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz: every file format the project reads, under ASan and
# UBSan, with clang) into build-fuzz/ and runs each for a fixed time from its seed corpus.
# CLOUDSCAPE_FUZZ_SECONDS (default 15) sets the time per target; extra arguments go to ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${CLOUDSCAPE_FUZZ_SECONDS:-15}"
cmake -S tests/fuzz -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCLOUDSCAPE_FUZZ_SECONDS="$seconds" \
  >/dev/null
cmake --build build-fuzz -j 2
ctest --test-dir build-fuzz --output-on-failure "$@"
