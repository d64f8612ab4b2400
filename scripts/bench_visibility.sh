#!/usr/bin/env bash
# Benchmarks behind docs/visibility.md: every shared DEM against the raymarch reference, then
# the SAGA side-by-side on a projected (UTM) crop of the Anatolia DEM; charts follow.
# Usage: scripts/bench_visibility.sh [BUILD_DIR]   (default build/); writes docs/charts/vis_*.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
bin=$build/app/terrashade
data=${TS_SHARED_DATA:-$root/../shared/data}
out=$root/docs/charts
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# 1. Accuracy and time per method on a centred 200x200 window of every real DEM, with Earth
#    curvature, against a 128-azimuth raymarch; plus exact and pyramid on each whole DEM.
"$bin" bench visibility --threads 2 --window 200 --reference-directions 128 --directions 8,16,32,64 \
  --methods exact,pyramid,raymarch --exact-variants 0:1,1:1,2:1,2:2,4:1 --pyramid-schedules fast,balanced,fine \
  --full --csv "$out/vis_bench.csv" \
  "$data/dem/N00E010.hgt" "$data/dem/N00E011.hgt.zip" "$data/dem/srtm3_N39E040_1000px.tif" \
  "$data/dem/copernicus_N45E005_grenoble_500px.tif" "$data/dem/etopo1_global_1deg.tif"

# 2. SAGA (saga_cmd ta_lighting 3) needs a projected DEM: a 250x250 crop of the Anatolia DEM
#    reprojected to UTM 37N at 90 m, flat Earth for everyone (SAGA has no curvature).
gdal_translate -q -srcwin 375 375 250 250 "$data/dem/srtm3_N39E040_1000px.tif" "$tmp/crop.tif"
gdalwarp -q -t_srs EPSG:32637 -tr 90 90 -r bilinear -ot Float32 -dstnodata -32768 "$tmp/crop.tif" "$tmp/anatolia_utm37n.tif"
"$bin" bench visibility --threads 2 --window 400 --reference-directions 128 --directions 8,16,32,64 \
  --methods exact --no-curvature --saga --csv "$out/vis_saga.csv" "$tmp/anatolia_utm37n.tif"

/usr/bin/python3 "$root/scripts/chart_visibility.py" "$out/vis_bench.csv" "$out/vis_saga.csv" "$out"
