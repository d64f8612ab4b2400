#!/usr/bin/env bash
# Sets up, builds and runs the main job on the shipped default DEM; outputs go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
ts=build/release/app/terrashade
dem=data/grenoble_500px.tif

echo "== the DEM"
$ts info "$dem"
$ts info "$dem" --json > out/info.json

echo "== classic hillshade (the baseline)"
$ts hillshade "$dem" --out out/hillshade.png
$ts hillshade "$dem" --out out/hillshade.tif

echo "== height-field visibility: exact horizons, 32 azimuths"
$ts visibility "$dem" --directions 32 --method exact \
    --svf out/svf.tif --sky-visible out/sky_visible.tif --horizons out/horizons.tif --sh out/visibility_sh.tif
$ts visibility "$dem" --directions 32 --svf out/svf.png

echo "== the sun over Grenoble at the June solstice, 12:00 CEST (solar noon is ~13:38 there)"
$ts sun --time 2025-06-21T12:00:00+02:00 --lat 45.19 --lon 5.72 --height-m 212

echo "demo: outputs in out/: $(ls out | tr '\n' ' ')"
