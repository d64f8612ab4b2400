#!/usr/bin/env bash
# The stored Blender Cycles references of tests/cli/cycles_reference_cli_test.cpp
# (docs/accuracy.md, "Against Blender Cycles"): a 64 x 64 crop of the Anatolia SRTM3 tile in a
# local transverse Mercator at 90 m (1714 m of relief) and Cycles' luminance on it, grey Lambert
# albedo 0.3, 4 bounces, 1024 samples, under terrashade's clear sky (the physical one), Preetham's
# sky, both with the sun 20 degrees up at azimuth 135, and its overcast sky (each sky's ground
# albedo 0.3). About 1.5 minutes.
# Usage: scripts/make_cycles_reference.sh [BUILD_DIR]   (needs blender, oiiotool, python3-gdal)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build=${1:-$root/build/release}
dest="$root/tests/render/reference"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$dest"

"$root/scripts/cycles_held_out_dem.sh" "$work/anatolia_tm90.tif"
gdal_translate -q -srcwin 40 552 64 64 -co COMPRESS=DEFLATE -co PREDICTOR=3 "$work/anatolia_tm90.tif" \
  "$dest/anatolia_tm90_64.tif"

for sky in clear preetham overcast; do
  "$build/tests/light/sky_equirect_dump" "$sky:albedo=0.3" 135 20 1024 "$work/sky_$sky" >/dev/null
  blender -b --factory-startup -P "$root/scripts/cycles_reference.py" -- "$dest/anatolia_tm90_64.tif" \
    "$work/cycles_$sky.tif" --sky map --sky-map "$work/sky_$sky" --albedo 0.3 --bounces 4 --samples 1024 \
    | grep cycles_seconds
  # Rec. 709 luminance, one float32 channel.
  oiiotool "$work/cycles_$sky.tif" --chsum:weight=0.2126,0.7152,0.0722 -d float --compression zip \
    -o "$dest/cycles_${sky}_e20_a0.3_b4.exr"
done
ls -l "$dest"
