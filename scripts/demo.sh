#!/usr/bin/env bash
# Installs what the demo needs (scripts/setup.sh demo: no test-only package), builds terrashade
# and runs the main job on the shipped default DEM; outputs go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh demo terrashade terrashade_image_io
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

echo "== shaded renders: real sun (June solstice, 09:00 CEST), clear sky, sun shadows (on the default device choice; terrashade devices says which)"
$ts render "$dem" --time 2025-06-21T07:00:00Z --out out/render_map.png --sun-visibility out/sun_visibility.tif
$ts render "$dem" --time 2025-06-21T07:00:00Z --out out/render_map.tif
$ts render "$dem" --time 2025-06-21T07:00:00Z --extent 601125,5637278,690181,5732404 --extent-crs EPSG:3857 --out out/render_extent_3857.png
$ts render "$dem" --time 2025-06-21T07:00:00Z --view perspective --camera 5.62,45.33,3000,150,-8,62 --out out/render_perspective.png
$ts render "$dem" --time 2025-06-21T07:00:00Z --sky overcast --out out/render_overcast.png

echo "== relit sequence: visibility once, one frame every 3 hours of the solstice (UTC)"
# --overwrite: a second demo run replaces the series it wrote before (a folder holding frames is
# otherwise refused, so that two series never mix).
$ts relight "$dem" --times 2025-06-21T04:00:00Z/2025-06-21T19:00:00Z/PT3H --out out/relight --overwrite

echo "== a year of clear-sky sun: irradiation (kWh/m2) and hours of direct sun per texel, from the same horizons"
$ts insolation "$dem" --year 2025 --out out/insolation_2025.tif --quicklook out/insolation_2025.png

echo "demo: outputs in out/: $(ls out | tr '\n' ' ')"
