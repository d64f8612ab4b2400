#!/usr/bin/env bash
# docs/tiles_etopo1_z2_color.png and _relief.png: ETOPO1 (1 degree, ../shared/data/dem) as
# zoom-2 color and relief tiles, halved: the sea floor in bathymetric tints, no streaks near the poles
# (docs/tiles.md, "Global DEMs"). Needs a built terrashade and Node.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ts="${TERRASHADE:-$root/build/release/app/terrashade}"
dem="$root/../shared/data/dem/etopo1_global_1deg.tif"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for style in color relief; do
  "$ts" tiles "$dem" --zoom 2 --style "$style" --out "$work/$style" > /dev/null
  node "$root/scripts/mosaic_tiles.mjs" "$work/$style" 2 "$work/$style.png"
  gdal_translate -q -of PNG -outsize 512 512 -r average "$work/$style.png" "$root/docs/tiles_etopo1_z2_$style.png"
  rm -f "$root/docs/tiles_etopo1_z2_$style.png.aux.xml"
done
ls -l "$root"/docs/tiles_etopo1_z2_*.png
