#!/usr/bin/env bash
# Renders docs/gallery/: the Gresivaudan valley (Grenoble, looking south-east from above the
# Chartreuse) at dawn, noon and dusk of the June solstice, under an overcast sky and under an HDR
# environment map, a close-up, into the setting sun under Preetham's sky and the physical one (the default), and as maps
# (default colours, grey, winter, overcast), from
# data/grenoble_500px.tif. Each perspective PNG is 640x360, each map 240x240
# (every file < 200 KB; the perspective views are dithered, docs/rendering.md).
# Usage: scripts/gallery.sh [path/to/terrashade]   (default: the release build)
set -euo pipefail
cd "$(dirname "$0")/.."
ts=${1:-build/release/app/terrashade}
dem=data/grenoble_500px.tif
out=docs/gallery
mkdir -p "$out"
# The same camera for every picture: lon,lat,height (m),heading,pitch,fov.
view=(--view perspective --camera 5.62,45.33,3000,150,-8,62 --size 640x360)

# Local time is UTC+2 in June: sunrise ~05:55, solar noon ~13:38, sunset ~21:20.
$ts render "$dem" "${view[@]}" --time 2025-06-21T04:40:00Z --out "$out/dawn.png"
$ts render "$dem" "${view[@]}" --time 2025-06-21T11:40:00Z --out "$out/noon.png"
$ts render "$dem" "${view[@]}" --time 2025-06-21T18:45:00Z --out "$out/dusk.png"
$ts render "$dem" "${view[@]}" --time 2025-06-21T11:40:00Z --sky overcast --out "$out/overcast.png"
$ts render "$dem" "${view[@]}" --time 2025-06-21T11:40:00Z --sky data/sunset_synthetic.hdr --out "$out/hdr.png"
# Looking west into the setting sun (5 degrees up) from the same place: Preetham's sky beside
# the physical one, the default (docs/lighting.md, "Physical clear sky").
sunset=(--view perspective --camera 5.62,45.33,3000,300,-3,62 --size 640x360)
$ts render "$dem" "${sunset[@]}" --time 2025-06-21T18:45:00Z --sky preetham --out "$out/sunset_preetham.png"
$ts render "$dem" "${sunset[@]}" --time 2025-06-21T18:45:00Z --out "$out/sunset_physical.png"
# Close up, low over the Vercors foothills south-west of Grenoble at 07:00 UTC (texels of
# 160 x 220 m spanning tens of pixels): shaded at the DEM's resolution (docs/rendering.md,
# "Perspective views at the DEM's resolution").
$ts render "$dem" --view perspective --camera 5.70,45.20,2400,60,-25,50 --size 640x360 \
    --time 2025-06-21T07:00:00Z --out "$out/closeup.png"
# The same noon as a map (the whole DEM, top-down), downsampled to 240x240 to stay small
# (400x400 gave 298 KB: a map has far more detail per pixel than the hazy perspective views).
$ts render "$dem" --time 2025-06-21T11:40:00Z --size 240x240 --out "$out/noon_map.png"
# Colours by design (docs/colors.md): the same map on uniform grey (the relief alone), a winter
# map with snow above 1800 m, and the default map under an overcast sky.
$ts render "$dem" --time 2025-06-21T11:40:00Z --size 240x240 --colors grey --out "$out/noon_map_grey.png"
$ts render "$dem" --time 2025-06-21T11:40:00Z --size 240x240 --snow-line 1800 --out "$out/noon_map_winter.png"
$ts render "$dem" --time 2025-06-21T11:40:00Z --size 240x240 --sky overcast --out "$out/overcast_map.png"
# The mesh pictures (the Cessna and the milk truck with their shadows).
scripts/gallery_mesh_shadow.sh "$ts"
ls -l "$out"
