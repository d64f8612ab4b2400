#!/usr/bin/env bash
# The held-out DEM of the Cycles comparisons (docs/accuracy.md, "Against Blender Cycles"): the
# Anatolia SRTM3 tile of ../shared reprojected to a transverse Mercator centred on it at 90 m
# (scale factor 1 at the centre, so grid metres are ground metres: Cycles' mesh needs square
# metric texels). Callers crop it with gdal_translate -srcwin.
# Usage: scripts/cycles_held_out_dem.sh OUT.tif
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ $# -eq 1 ] || { sed -n 2,6p "$0"; exit 2; }
gdalwarp -q -t_srs '+proj=tmerc +lat_0=39.5833333 +lon_0=40.4166667 +k=1 +datum=WGS84 +units=m' \
  -tr 90 90 -r cubic -ot Float32 -dstnodata -32768 "$root/../shared/data/dem/srtm3_N39E040_1000px.tif" "$1"
