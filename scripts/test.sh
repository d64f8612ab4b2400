#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite:
#   1. the release build: terrashade, terrashade-bench and every test that is not a core test
#      (ts_release_tests: the command line, Vulkan, fly, Slurm, the browser page, the CLI fuzzer);
#   2. the core/ tests, built once, under AddressSanitizer and UBSan (preset asan: clang-14, -O1):
#      the same tests and checks with the memory and UB checks on;
#   3. the DEM readers and the mesh import fuzzed for a bounded time (scripts/fuzz.sh,
#      libFuzzer + ASan + UBSan; TS_FUZZ_SECONDS per target, default 20; longer runs: fuzz.sh).
# `ctest --preset release` after a full build (scripts/build.sh test) runs everything unsanitized.
# Each pass prints its wall time (docs/building.md has the figures).
set -euo pipefail
cd "$(dirname "$0")/.."
pass() { echo "test.sh: $1 took $((SECONDS - start)) s"; start=$SECONDS; }
start=$SECONDS
bash scripts/build.sh test ts_release_tests
pass "the release build"
ctest --preset release -j"$(nproc)" -LE core
pass "the release tests"
cmake --preset asan >/dev/null
cmake --build --preset asan -j"$(nproc)" --target ts_core_tests
pass "the sanitizer build"
ctest --preset asan -j"$(nproc)"
pass "the core tests under ASan+UBSan"
bash scripts/fuzz.sh "${TS_FUZZ_SECONDS:-20}"
pass "fuzzing"
echo "test.sh: all passed in $SECONDS s"
