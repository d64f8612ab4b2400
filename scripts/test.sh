#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: every test in the release build, the core/
# tests again under AddressSanitizer and UBSan, then the DEM readers fuzzed for a bounded time
# (scripts/fuzz.sh, libFuzzer + ASan + UBSan; TS_FUZZ_SECONDS per reader, default 30).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh test
ctest --preset release -j"$(nproc)"
cmake --preset asan >/dev/null
cmake --build --preset asan -j"$(nproc)" --target ts_core_tests
ctest --preset asan -j"$(nproc)"
bash scripts/fuzz.sh "${TS_FUZZ_SECONDS:-30}"
