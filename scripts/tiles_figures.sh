#!/usr/bin/env bash
# The figures of docs/tiles.md: the same z10 tiles over Grenoble from the classic pipeline
# (gdaldem hillshade + gdal2tiles.py) and as terrashade relief, and relief against the
# ray-traced reference with its error, and relief at three --relief-contrast values (Grenoble
# z10 and, with ../shared beside the checkout, Anatolia z12). Needs a built terrashade and scripts/setup.sh.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ts="${TERRASHADE:-$root/build/release/app/terrashade}"
dem="$root/data/grenoble_500px.tif"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

gdaldem hillshade -q -compute_edges -s 111120 "$dem" "$work/hillshade.tif"
gdal2tiles.py -q --xyz -z 10 -w none -r bilinear "$work/hillshade.tif" "$work/classic" > /dev/null
"$ts" tiles "$dem" --zoom 10 --style relief --out "$work/relief" > /dev/null
"$ts" bench tiles "$dem" --zoom 10 --reference 5.72,45.19 --reference-texels 96 --reference-out "$work/ref" \
  | tee "$work/reference.txt"
for k in 1 1.5 2; do
  "$ts" tiles "$dem" --zoom 10 --style relief --relief-contrast "$k" --out "$work/contrast_grenoble_$k" > /dev/null
done
anatolia="$root/../shared/data/dem/srtm3_N39E040_1000px.tif"
if [[ -f "$anatolia" ]]; then
  for k in 1 1.5 2; do
    "$ts" tiles "$anatolia" --zoom 12 --style relief --relief-contrast "$k" --out "$work/contrast_anatolia_$k" > /dev/null
  done
fi
python3 "$root/scripts/chart_tiles.py" "$work" "$root/docs"
