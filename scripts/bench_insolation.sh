#!/usr/bin/env bash
# The speed and beam comparison in docs/insolation.md: terrashade insolation (a day and the year)
# against GRASS r.sun (with its own shadowing, with 32 r.horizon maps) and SAGA ta_lighting 2
# on a centred 360x360 crop of the SRTM tile N00E010, then the chart.
# Needs scripts/setup.sh bench (grass-core, saga, gdal-bin, python3-gdal, matplotlib).
# Usage: scripts/bench_insolation.sh [BUILD_DIR]   (default build/); writes
# docs/charts/insolation_bench.csv and docs/insolation_rsun_beam.png.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
bin=$build/app/terrashade
data=${TS_SHARED_DATA:-$root/../shared/data}
mkdir -p "$root/docs/charts"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "load before: $(uptime)"
"$bin" bench insolation "$data/dem/N00E010.hgt" --window 360 --date 2024-06-21 --linke 3 --albedo 0.2 \
  --step 0.5 --horizons 32 --threads 2 --csv "$root/docs/charts/insolation_bench.csv" --maps "$tmp/beam_maps.tif"
echo "load after: $(uptime)"
/usr/bin/python3 "$root/scripts/chart_insolation.py" "$tmp/beam_maps.tif" "$root/docs/insolation_rsun_beam.png"
