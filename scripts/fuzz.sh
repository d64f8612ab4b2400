#!/usr/bin/env bash
# Fuzzes the DEM readers and the mesh import: configures build/fuzz with clang (TERRASHADE_FUZZ=ON: libFuzzer,
# ASan, UBSan), builds the targets of tests/fuzz and runs each for a bounded time from its
# seed corpus. Exits non-zero when any target finds a crash (or a leak, an out-of-memory or
# a timeout); libFuzzer then leaves the input as build/fuzz/artifacts/<reader>/crash-*: fix
# the reader, copy the input to tests/fuzz/regressions/<reader>/ (tests/dem and tests/mesh
# replay them).
#
#   scripts/fuzz.sh [seconds per target, default 60] [target ...]
#   (hgt hgt_zip geotiff mesh_file mesh_scene)
#
# New inputs that reach new code are written to build/fuzz/corpus/<reader>/, not to the
# committed seeds. FUZZ_JOBS=N runs N processes per target (default 1); the targets share
# FUZZ_PARALLEL cores (default: every core), each target fuzzed for its seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET="${1:-60}"
shift || true
READERS=("$@")
[ "${#READERS[@]}" -gt 0 ] || READERS=(hgt hgt_zip geotiff mesh_file mesh_scene)
JOBS="${FUZZ_JOBS:-1}"
CC_BIN="${FUZZ_CC:-clang-14}"
CXX_BIN="${FUZZ_CXX:-clang++-14}"
command -v "$CXX_BIN" >/dev/null || { echo "fuzz: $CXX_BIN not found (scripts/setup.sh installs clang-14)" >&2; exit 1; }

ROOT="$PWD"
BUILD="$ROOT/build/fuzz"
# -O1 with line tables, as libFuzzer's documentation builds its targets (-g -O1): file and line in
# every report, and the readers compile in less time than at the release build's -O2 -g.
cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
  -DCMAKE_C_COMPILER="$CC_BIN" -DCMAKE_CXX_COMPILER="$CXX_BIN" \
  -DTERRASHADE_FUZZ=ON -DTERRASHADE_BUILD_GPU=OFF -DTERRASHADE_BUILD_TESTS=OFF >/dev/null
targets=()
for r in "${READERS[@]}"; do targets+=("fuzz_$r"); done
cmake --build "$BUILD" --target "${targets[@]}" -j"${FUZZ_BUILD_JOBS:-$(nproc)}"

# One run of a target for SECONDS; its lines go to the terminal as whole lines, its log to
# build/fuzz/fuzz_R.log (a target run in two pieces appends the second).
fuzz_one() {
  local r="$1" seconds="$2"
  corpus="$BUILD/corpus/$r"
  artifacts="$BUILD/artifacts/$r"
  mkdir -p "$corpus" "$artifacts"
  log="$BUILD/fuzz_$r.log"
  echo "fuzz: $r for ${seconds}s (log $log)"
  # -timeout: one input taking over 10 s is a hang. The readers' memory guard is capped at
  # 32 MB while fuzzing (dem_fuzz_inputs.hpp), so one allocation over 128 MB is a reader
  # spending before it checked (-malloc_limit_mb), and 2 GB resident a leak (-rss_limit_mb).
  args=(-max_total_time="$seconds" -timeout=10 -malloc_limit_mb=128 -rss_limit_mb=2048 -print_final_stats=1
        -artifact_prefix="$artifacts/")
  # Several jobs log to fuzz-N.log in the current folder: run them from the artifacts folder.
  # mesh_file imports each input in a child process (core/util/isolated_call.hpp), which
  # libFuzzer's malloc/free balance counts as a possible leak, and the leak check then run
  # after every input took ~1 s; leaks in the parent's part are fuzzed by mesh_scene.
  # Inputs that crashed or hung assimp in its child process are an error message, not a fuzzer
  # crash; they are kept in artifacts/mesh_file/isolated/ for tests/fuzz/regressions/mesh_file/.
  if [ "$r" = mesh_file ]; then args+=(-detect_leaks=0); export TS_FUZZ_ISOLATED_DIR="$artifacts/isolated"; fi
  if [ -f "tests/fuzz/$r.dict" ]; then args+=(-dict="$ROOT/tests/fuzz/$r.dict"); fi
  if [ "$JOBS" -gt 1 ]; then args+=(-jobs="$JOBS" -workers="$JOBS"); fi
  if ! (cd "$artifacts" && "$BUILD/tests/fuzz/fuzz_$r" "${args[@]}" "$corpus" "$ROOT/tests/fuzz/corpus/$r") \
      >>"$log" 2>&1; then
    echo "fuzz: $r FAILED; inputs in $artifacts:" >&2
    ls -1 "$artifacts" | grep -E "^(crash|leak|oom|timeout|slow-unit)-" >&2 || true
    grep -m1 -E "ERROR: |runtime error" "$log" >&2 || tail -5 "$log" >&2
    return 1
  else
    grep -E "stat::number_of_executed_units|cov: " "$log" | tail -2 | sed "s/^/fuzz: $r: /"
  fi
}

# The targets share the cores (FUZZ_PARALLEL, default the core count) so that each fuzzes for its
# seconds and the cores end together: laid end to end on one timeline cut into equal spans, one
# span a core (McNaughton's wrap-around rule). A target cut at a span's end runs its two pieces on
# two cores at times that do not overlap, the second from the corpus the first grew. Five targets
# on two cores: 2.5 targets' time, not 3 rounds with one core idle in the last.
PARALLEL="${FUZZ_PARALLEL:-$(nproc)}"
count="${#READERS[@]}"
[ "$PARALLEL" -le "$count" ] || PARALLEL="$count"
span=$(( (count * SECONDS_PER_TARGET + PARALLEL - 1) / PARALLEL ))
status_dir="$BUILD/status"
rm -rf "$status_dir" && mkdir -p "$status_dir"
for r in "${READERS[@]}"; do : > "$BUILD/fuzz_$r.log"; done
for ((core = 0; core < PARALLEL; ++core)); do
  (
    from=$(( core * span )); to=$(( (core + 1) * span ))
    for ((i = 0; i < count; ++i)); do
      begin=$(( i * SECONDS_PER_TARGET )); end=$(( (i + 1) * SECONDS_PER_TARGET ))
      (( begin < from )) && begin=$from
      (( end > to )) && end=$to
      (( end > begin )) || continue
      r="${READERS[$i]}"
      if fuzz_one "$r" $(( end - begin )); then :; else echo 1 > "$status_dir/$r.$core"; fi
    done
  ) &
done
wait
status=0
for r in "${READERS[@]}"; do
  if compgen -G "$status_dir/$r.*" >/dev/null; then status=1; fi
done
exit "$status"
