#!/usr/bin/env bash
# End to end on a real single-node Slurm (tests/scale/slurm_fixture.sh):
#  1. tiles as a 3-shard job array (scripts/slurm_shards.sh) + the dependent merge job: the
#     merged MBTiles equals a single-process run (metadata rows and the SHA-256 of every tile);
#  2. the same as XYZ folders with shard 1 cancelled mid-way (scancel): the merge job never runs,
#     `merge` by hand reports the unfinished shard (exit 2), shard 1 resubmitted alone resumes
#     (its log counts as resumed exactly the tiles it had written, whose files are untouched),
#     and the merged folder equals a single-process run file for file.
# Usage: slurm_shards_test.sh TERRASHADE_BIN SOURCE_DIR. Fails (exit 1) if Slurm cannot start.
set -euo pipefail
bin=$(realpath "$1")
src=$(realpath "$2")
dem="$src/data/grenoble_500px.tif"
hashes="python3 $src/tests/scale/tile_hashes.py"

tmp=$(mktemp -d /tmp/terrashade-slurm.XXXXXX)
source "$src/tests/scale/slurm_fixture.sh"
cleanup() { slurm_fixture_stop; rm -rf "$tmp"; }
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; for f in "$tmp"/*/log/*.out; do [ -f "$f" ] && { echo "--- $f" >&2; cat "$f" >&2; }; done; exit 1; }

slurm_fixture_start "$tmp/slurm"
echo "slurm up: $(sinfo -h -o '%P %a %D %T')"

# Waits until job $1 has left the queue (done, failed or cancelled); fails after $2 seconds.
wait_gone() {
  local job=$1 limit=$2 t=0
  while squeue -h -j "$job" 2>/dev/null | grep -q .; do
    if squeue -h -j "$job" -o '%r' 2>/dev/null | grep -q DependencyNeverSatisfied; then
      return 3
    fi
    sleep 0.5; t=$((t + 1))
    [ "$t" -lt $((2 * limit)) ] || fail "job $job still queued after $limit s: $(squeue -j "$job")"
  done
}

tile_flags=(--zoom 0-12 --style hillshade --threads 1)

echo "== 1. MBTiles: 3 shards as a job array, merged by a dependent job"
"$bin" tiles "$dem" "${tile_flags[@]}" --out "$tmp/single.mbtiles" >"$tmp/single.log"
jobs=$(bash "$src/scripts/slurm_shards.sh" --shards 3 --max-parallel 2 --work "$tmp/mb" --terrashade "$bin" \
  -- tiles "$dem" "${tile_flags[@]}" --out "$tmp/merged.mbtiles")
echo "$jobs"
array=$(awk '/^array/ {print $2}' <<<"$jobs")
merge=$(awk '/^merge/ {print $2}' <<<"$jobs")
wait_gone "$array" 120 || fail "array $array"
wait_gone "$merge" 60 || fail "the merge job $merge never started (a shard failed)"
[ -f "$tmp/merged.mbtiles" ] || fail "no merged.mbtiles"
grep -h '^tiles:' "$tmp"/mb/log/shard_*.out
cat "$tmp/mb/log/merge.out"
$hashes "$tmp/single.mbtiles" >"$tmp/single.txt"
$hashes "$tmp/merged.mbtiles" >"$tmp/merged.txt"
n=$(grep -c '^tile ' "$tmp/single.txt")
[ "$n" -gt 100 ] || fail "only $n tiles in the single run"
diff "$tmp/single.txt" "$tmp/merged.txt" >&2 || fail "merged MBTiles differs from the single-process run"
for k in 0 1 2; do
  grep -q "^shard $k/3" "$tmp/mb/log/shard_$k.out" || fail "shard_$k.out does not say shard $k/3"
done
echo "merged MBTiles equals the single run: $n tiles, metadata equal"

echo "== 2. XYZ: shard 1 cancelled mid-way, resubmitted with --resume"
xyz_flags=(--zoom 0-14 --style hillshade)
"$bin" tiles "$dem" "${xyz_flags[@]}" --threads 2 --out "$tmp/single_xyz" >"$tmp/single_xyz.log"
jobs=$(bash "$src/scripts/slurm_shards.sh" --shards 3 --max-parallel 2 --work "$tmp/xyz" --terrashade "$bin" \
  -- tiles "$dem" "${xyz_flags[@]}" --threads 1 --out "$tmp/merged_xyz")
array=$(awk '/^array/ {print $2}' <<<"$jobs")
merge=$(awk '/^merge/ {print $2}' <<<"$jobs")
shard1="$tmp/xyz/shard_1"
count_pngs() { find "$1" -name '*.png' 2>/dev/null | wc -l; }
t=0
until [ "$(count_pngs "$shard1")" -ge 40 ]; do
  sleep 0.1; t=$((t + 1))
  [ "$t" -lt 1200 ] || fail "shard 1 wrote no tiles in 120 s"
  [ -f "$shard1/.terrashade-shard" ] && fail "shard 1 finished before it could be cancelled: give it more tiles"
done
scancel "${array}_1"
wait_gone "${array}_1" 60 || true
[ -f "$shard1/.terrashade-shard" ] && fail "shard 1 finished before scancel reached it: give it more tiles"
sleep 0.5
before=$(count_pngs "$shard1")
find "$shard1" -name '*.png' -printf '%P %T@\n' | sort >"$tmp/before_mtimes.txt"
echo "shard 1 cancelled with $before tiles written"
wait_gone "$array" 120 || fail "array $array"
# The merge depends on every shard succeeding: it must not have run.
if wait_gone "$merge" 5; then fail "the merge job ran although shard 1 was cancelled"; fi
scancel "$merge"
[ ! -e "$tmp/merged_xyz" ] || fail "merged_xyz exists after a failed shard"
set +e
"$bin" merge "$tmp"/xyz/shard_{0,1,2} --out "$tmp/merged_xyz" 2>"$tmp/merge_err.txt"
rc=$?
set -e
cat "$tmp/merge_err.txt"
[ "$rc" -eq 2 ] || fail "merge of an unfinished shard exited $rc, not 2"
grep -q "shard_1: is not a finished shard" "$tmp/merge_err.txt" || fail "merge did not name the unfinished shard"
[ ! -e "$tmp/merged_xyz" ] || fail "a refused merge left merged_xyz"

rerun=$(sbatch --parsable --array=1 --output="$tmp/xyz/log/shard_1_again.out" "$tmp/xyz/shard.sbatch")
wait_gone "${rerun%%;*}" 120 || fail "resubmitted shard 1"
cat "$tmp/xyz/log/shard_1_again.out"
resumed=$(sed -n 's/^tiles: [0-9]* written, \([0-9]*\) resumed.*/\1/p' "$tmp/xyz/log/shard_1_again.out")
[ -n "$resumed" ] || fail "no tile count in the resubmitted shard's log"
# Tiles whose file existed were kept: as many resumed as there were files (without data ones are
# not files, and a cancelled run leaves only whole files).
[ "$resumed" -ge "$before" ] || fail "resumed $resumed tiles, but $before were written before the cancel"
find "$shard1" -name '*.png' -printf '%P %T@\n' | sort | join - "$tmp/before_mtimes.txt" |
  awk '$2 != $3 {bad++} END {exit bad > 0}' || fail "a tile finished before the cancel was written again"
[ -f "$shard1/.terrashade-shard" ] || fail "the resubmitted shard 1 did not finish"
merge_again=$(sbatch --parsable "$tmp/xyz/merge.sbatch")
wait_gone "${merge_again%%;*}" 60 || fail "merge job"
cat "$tmp/xyz/log/merge.out"
$hashes "$tmp/single_xyz" >"$tmp/single_xyz.txt"
$hashes "$tmp/merged_xyz" >"$tmp/merged_xyz.txt"
n=$(grep -c '\.png ' "$tmp/single_xyz.txt")
if ! diff "$tmp/single_xyz.txt" "$tmp/merged_xyz.txt" >&2; then
  # What the difference is, for the log: the tiles' sizes, where their bytes first differ, and
  # whether shard 1 wrote the tile before the cancel (its mtime is in before_mtimes.txt).
  { diff "$tmp/single_xyz.txt" "$tmp/merged_xyz.txt" || true; } | sed -n 's/^< file \([^ ]*\) .*/\1/p' | while read -r f; do
    echo "differing tile $f: single $(stat -c %s "$tmp/single_xyz/$f") bytes, merged $(stat -c %s "$tmp/merged_xyz/$f")" \
      "bytes, first differences (offset, octal): $(cmp -l "$tmp/single_xyz/$f" "$tmp/merged_xyz/$f" 2>&1 | head -3 | tr '\n' ' ')" \
      "; written by shard 1 before the cancel: $(grep -c "^$f " "$tmp/before_mtimes.txt" || true)" >&2
  done
  # Which side is the odd one: shard 1 again, uninterrupted, into a third folder; and whether
  # the pixels differ or only the PNG bytes, and then whether the rows' filters or only the deflate
  # stream (tile_hashes.py --pixels decodes them). A run of 2026-12-05 found the single run the odd one
  # (12/2110/1473: the same pixels and size, other bytes; shard 1 again equalled the resumed tile).
  # Without Slurm: of 6 runs of `tiles grenoble_500px.tif --zoom 0-14 --style hillshade --threads 2`,
  # one differed from --threads 1 in 2 tiles (7/66/46, 10/529/368): the same filtered rows, other
  # deflate bytes; encode_png alone on those pixels, from two threads at once, always gives the
  # --threads 1 bytes. Cause (fixed): igzip's level-1 kernel hashed the input's third byte from the
  # address of its stream structure, then on the calling thread's stack; core/raster/igzip_stream_home.hpp
  # keeps it at an address with a fixed hash. After the fix 8 such runs gave 0 differing tiles of 4221.
  "$bin" tiles "$dem" "${xyz_flags[@]}" --threads 1 --shard 1/3 --out "$tmp/shard1_again" >/dev/null 2>&1 || true
  { diff "$tmp/single_xyz.txt" "$tmp/merged_xyz.txt" || true; } | sed -n 's/^< file \([^ ]*\) .*/\1/p' | while read -r f; do
    echo "tile $f: uninterrupted shard 1 again equals the single run: $(cmp -s "$tmp/single_xyz/$f" "$tmp/shard1_again/$f" && echo yes || echo no)," \
      "equals the merged (resumed) tile: $(cmp -s "$tmp/merged_xyz/$f" "$tmp/shard1_again/$f" && echo yes || echo no);" \
      "pixels: $(python3 "$src/tests/scale/tile_hashes.py" --pixels "$tmp/single_xyz/$f" "$tmp/merged_xyz/$f")" >&2
  done
  fail "merged XYZ differs from the single-process run"
fi
echo "merged XYZ equals the single run: $n tiles; shard 1 resumed $resumed of its tiles"

echo "== 3. relight: 5 frames as a 2-shard array, merged"
relight_flags=(--times 2025-06-21T05:00Z/2025-06-21T17:00Z/PT3H --exposure 13 --directions 8 --threads 1)
"$bin" relight "$dem" "${relight_flags[@]}" --out "$tmp/single_frames" >"$tmp/single_frames.log"
jobs=$(bash "$src/scripts/slurm_shards.sh" --shards 2 --work "$tmp/fr" --terrashade "$bin" \
  -- relight "$dem" "${relight_flags[@]}" --out "$tmp/merged_frames")
array=$(awk '/^array/ {print $2}' <<<"$jobs")
merge=$(awk '/^merge/ {print $2}' <<<"$jobs")
wait_gone "$array" 180 || fail "relight array $array"
wait_gone "$merge" 60 || fail "the relight merge job $merge never started (a shard failed)"
cat "$tmp/fr/log/merge.out"
$hashes "$tmp/single_frames" >"$tmp/single_frames.txt"
$hashes "$tmp/merged_frames" >"$tmp/merged_frames.txt"
n=$(grep -c '\.png ' "$tmp/single_frames.txt")
[ "$n" -eq 5 ] || fail "$n frames in the single relight, expected 5"
diff "$tmp/single_frames.txt" "$tmp/merged_frames.txt" >&2 || fail "merged relight folder differs from the single run"
echo "merged relight folder equals the single run: $n frames and times.csv"

echo "== 4. insolation: a month's map of a crop as a 2-shard array, merged"
insolation_flags=(--crop 5.70,45.15,5.85,45.25 --from 2025-06-01 --to 2025-06-30 --step 15 --directions 16 --threads 1)
"$bin" insolation "$dem" "${insolation_flags[@]}" --out "$tmp/single_map.tif" >"$tmp/single_map.log"
jobs=$(bash "$src/scripts/slurm_shards.sh" --shards 2 --work "$tmp/ins" --terrashade "$bin" \
  -- insolation "$dem" "${insolation_flags[@]}" --out "$tmp/merged_map.tif")
array=$(awk '/^array/ {print $2}' <<<"$jobs")
merge=$(awk '/^merge/ {print $2}' <<<"$jobs")
wait_gone "$array" 120 || fail "insolation array $array"
wait_gone "$merge" 60 || fail "the insolation merge job $merge never started (a shard failed)"
cat "$tmp/ins/log/merge.out"
cmp "$tmp/single_map.tif" "$tmp/merged_map.tif" || fail "merged insolation map differs from the single run"
echo "merged insolation map equals the single run byte for byte"
