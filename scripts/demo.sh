#!/usr/bin/env bash
# Sets up, builds and runs the main job on the shipped default DEM; outputs go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
mkdir -p out
ts=build/release/app/terrashade
dem=data/grenoble_500px.tif
$ts info "$dem"
$ts info "$dem" --json > out/info.json
$ts hillshade "$dem" --out out/hillshade.png
$ts hillshade "$dem" --out out/hillshade.tif
echo "demo: outputs in out/: $(ls out | tr '\n' ' ')"
