#!/usr/bin/env bash
# The sun sweep against the exact sun pass on three shared DEMs (500x500 centres) for near
# fields of 2, 4 and 8 texels: docs/charts/sun_bench.csv and docs/charts/sun_sweep.png.
# Usage: scripts/bench_sun.sh [path/to/terrashade]   (default: the release build; ~30 s)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ts=${1:-$root/build/release/app/terrashade}
D="$root/../shared/data/dem"
out="$root/docs/charts"
"$ts" bench sun "$D/copernicus_N45E005_grenoble_500px.tif" "$D/srtm3_N39E040_1000px.tif" "$D/N00E010.hgt" \
  --max-size 500 --near-field 2,4,8 --frames 3 --threads 2 --csv "$out/sun_bench.csv"
/usr/bin/python3 "$root/scripts/chart_sun.py" "$out/sun_bench.csv" "$out"
