#!/usr/bin/env bash
# Blender Cycles' own noise in docs/charts/cycles_bench.csv: the same case rendered with two
# seeds and compared like terrashade (scripts/cycles_compare.py). One render's relative noise
# is the pair's relative RMSE / sqrt(2); the pair's correlation is the most terrashade's could
# reach against one Cycles render at that sample count. Appends to docs/charts/cycles_noise.csv.
# Usage: scripts/cycles_noise.sh BUILD_DIR CROP.tif SKY ALBEDO BOUNCES SAMPLES   (CROP as cycles_bench.sh makes)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build=$1 crop=$2 sky=$3 albedo=$4 bounces=$5 samples=$6
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
csv="$root/docs/charts/cycles_noise.csv"
[ -f "$csv" ] || echo "sky,albedo,bounces,samples,pair_correlation,pair_relative_rmse,one_render_relative_noise" >"$csv"
"$build/tests/light/sky_equirect_dump" "$sky:albedo=$albedo" 135 20 1024 "$work/sky" >/dev/null
for seed in 1 2; do
  blender -b --factory-startup -t 2 -P "$root/scripts/cycles_reference.py" -- "$crop" "$work/seed$seed.tif" \
    --sky map --sky-map "$work/sky" --albedo "$albedo" --bounces "$bounces" --samples "$samples" --seed "$seed" \
    --threads 2 >/dev/null 2>&1
done
/usr/bin/python3 "$root/scripts/cycles_compare.py" "$work/seed1.tif" "$work/seed2.tif" | /usr/bin/python3 -c "
import json, math, sys
r = json.load(sys.stdin)
print('$sky,$albedo,$bounces,$samples,%.6f,%.6f,%.6f' % (r['correlation'], r['relative_rmse'], r['relative_rmse'] / math.sqrt(2)))" | tee -a "$csv"
