#!/usr/bin/env bash
# Runs one terrashade tiles, relight or insolation job as a Slurm job array of N shards, then merges the
# shards in a job that starts only when every shard succeeded (docs/scale.md).
#
#   scripts/slurm_shards.sh --shards N [--max-parallel K] [--work DIR] [--terrashade BIN]
#       [--sbatch "OPTIONS"] -- tiles DEM... --zoom 0-12 --out ALL.mbtiles [tile options]
#   scripts/slurm_shards.sh --shards N -- relight DEM --times ... --exposure 13 --out FRAMES/
#   scripts/slurm_shards.sh --shards N -- insolation DEM --year 2024 --out YEAR.tif
#
# What it submits:
#   sbatch --array=0-(N-1)%K WORK/shard.sbatch   each task: terrashade ... --shard ID/N [--resume]
#                                                --out WORK/shard_ID(.mbtiles|.tif)
#   sbatch --dependency=afterok:ARRAY WORK/merge.sbatch   terrashade merge WORK/shard_* --out OUT
# It prints "array JOBID" and "merge JOBID". The shard number is given explicitly (--shard ID/N),
# so one shard resubmitted alone (sbatch --array=3 WORK/shard.sbatch) is still shard 3 of N, and
# --resume makes it keep the tiles it finished before it was killed; then resubmit the merge
# (sbatch WORK/merge.sbatch). The batch files stay in WORK for that.
set -euo pipefail

shards="" max_parallel="" work="" bin="" extra_sbatch=""
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) shards="$2"; shift 2 ;;
    --max-parallel) max_parallel="$2"; shift 2 ;;
    --work) work="$2"; shift 2 ;;
    --terrashade) bin="$2"; shift 2 ;;
    --sbatch) extra_sbatch="$2"; shift 2 ;;
    --) shift; break ;;
    *) echo "slurm_shards.sh: unknown option $1 (see the header of this script)" >&2; exit 2 ;;
  esac
done
[ $# -gt 0 ] || { echo "slurm_shards.sh: give the terrashade command after --" >&2; exit 2; }
case "$shards" in ''|*[!0-9]*|0) echo "slurm_shards.sh: --shards N, N >= 1" >&2; exit 2 ;; esac
[ -n "$max_parallel" ] || max_parallel="$shards"
case "$max_parallel" in ''|*[!0-9]*|0) echo "slurm_shards.sh: --max-parallel K, K >= 1" >&2; exit 2 ;; esac
[ -n "$bin" ] || bin=$(command -v terrashade || true)
[ -x "$bin" ] || { echo "slurm_shards.sh: terrashade not found: give --terrashade BIN" >&2; exit 2; }
bin=$(realpath "$bin")
command="$1"; shift
case "$command" in tiles|relight|insolation) ;; *) echo "slurm_shards.sh: the command is tiles, relight or insolation, not $command" >&2; exit 2 ;; esac

# The user's --out becomes the merge's; each shard writes its own under WORK.
args=() out=""
while [ $# -gt 0 ]; do
  case "$1" in
    -o|--out) out="$2"; shift 2 ;;
    --out=*) out="${1#--out=}"; shift ;;
    --shard|--shard=*|--resume) echo "slurm_shards.sh: leave $1 to the script" >&2; exit 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
[ -n "$out" ] || { echo "slurm_shards.sh: the command needs --out" >&2; exit 2; }
out=$(realpath -m "$out")
[ -n "$work" ] || work="$out.shards"
mkdir -p "$work/log"
work=$(realpath "$work")
ext=""
[ "$command" = tiles ] && [ "${out%.mbtiles}" != "$out" ] && ext=".mbtiles"
[ "$command" = insolation ] && ext=".${out##*.}"  # the map's own extension (.tif, .tiff)

quoted=$(printf ' %q' "${args[@]}")
# Tiles resume what a killed shard committed; a relight shard redoes its block of frames, an
# insolation shard its rows.
resume=""
[ "$command" = tiles ] && resume=" --resume"
cat >"$work/shard.sbatch" <<SBATCH
#!/usr/bin/env bash
#SBATCH --job-name=terrashade-$command
#SBATCH --output=$work/log/shard_%a.out
set -euo pipefail
cd $(printf '%q' "$PWD")
exec $(printf '%q' "$bin") $command$quoted --shard "\$SLURM_ARRAY_TASK_ID/$shards"$resume \\
    --out $(printf '%q' "$work")/shard_"\$SLURM_ARRAY_TASK_ID"$ext
SBATCH
inputs=""
for ((k = 0; k < shards; k++)); do inputs+=" $(printf '%q' "$work/shard_$k$ext")"; done
cat >"$work/merge.sbatch" <<SBATCH
#!/usr/bin/env bash
#SBATCH --job-name=terrashade-merge
#SBATCH --output=$work/log/merge.out
set -euo pipefail
exec $(printf '%q' "$bin") merge$inputs --out $(printf '%q' "$out")
SBATCH

# shellcheck disable=SC2086  # extra_sbatch is a list of options
array=$(sbatch --parsable $extra_sbatch --array="0-$((shards - 1))%$max_parallel" "$work/shard.sbatch")
array=${array%%;*}
# shellcheck disable=SC2086
merge=$(sbatch --parsable $extra_sbatch --dependency="afterok:$array" "$work/merge.sbatch")
merge=${merge%%;*}
echo "array $array"
echo "merge $merge"
