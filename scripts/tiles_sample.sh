#!/usr/bin/env bash
# Remakes docs/tiles/sample (relief tiles of data/grenoble_500px.tif, zooms 7-10, ~0.9 MB, with
# the viewer `tiles` writes beside them: tiles.json, index.html) and the sample page's
# screenshot docs/tiles_viewer.png. Needs a built terrashade and scripts/setup.sh.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ts="${TERRASHADE:-$root/build/release/app/terrashade}"
rm -rf "$root/docs/tiles/sample"
"$ts" tiles "$root/data/grenoble_500px.tif" --zoom 7-10 --style relief \
    --name "Grenoble relief" --attribution "Copernicus DEM © DLR/Airbus (data/SOURCES.md)" --out "$root/docs/tiles/sample"
node "$root/docs/tiles/check_page.mjs" "$root/docs/tiles_viewer.png"
