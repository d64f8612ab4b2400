#!/usr/bin/env bash
# The screenshots of docs/web-map.md: the time-of-day page in headless Chromium at 05:30, 11:30 and
# 18:30 UTC on 21 June 2024 over the Grenoble crop, and the hours-of-sun layer, halved to 512 px.
#   bash scripts/web_map_figures.sh [BUILD_DIR]      (default build/release)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$repo/build/release}
shots=$(mktemp -d)
trap 'rm -rf "$shots"' EXIT
LIGHTABLE_SCREENSHOTS=$shots node "$repo/docs/tiles/check_lightable_page.mjs" "$build/app/terrashade" \
  "$repo/data/grenoble_500px.tif"
mkdir -p "$repo/docs/web-map"
for f in "$shots"/*.png; do
  gdal_translate -q -of PNG -outsize 512 512 -r average "$f" "$repo/docs/web-map/$(basename "$f")"
  rm -f "$repo/docs/web-map/$(basename "$f").aux.xml"
done
ls -l "$repo/docs/web-map"
