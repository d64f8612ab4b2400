#!/usr/bin/env bash
# Renders the gallery's mesh pictures (docs/blockers.md), all over data/grenoble_500px.tif, most with
# the meshes scaled x120 so their shadows span a few of its 156 x 222 m texels (at scale 1 the
# Cessna is a tenth of a texel: only a perspective view's per-pixel shadows show it):
#  cessna_shadow.png       the Cessna 172 over the Gresivaudan valley on a June evening, sun 8 deg
#                          up in the west-north-west: a map of its soft sky shadow on the valley
#                          floor and its sun shadow on the foot of Belledonne.
#  cessna_view.png         the Cessna itself in a perspective view, 300 m above the foot of the
#                          west-facing Belledonne slope under a low afternoon sun (25 deg, west):
#                          lit per vertex by the sky and sun the terrain leaves it, its sun shadow
#                          with the aircraft's outline on the slope beside it (found per pixel).
#  cessna_real_size.png    the Cessna at its own size (9.6 m) 30 m above the valley floor, seen
#                          from 150 m: the shadow of a tenth of a texel, per pixel.
#  milk_truck_overcast.png the milk truck on the valley floor under an overcast sky: a map of its
#                          soft sky shadow (no sun shadow: an overcast sky has no sun).
#  milk_truck_view.png     the same truck and shadow in a perspective view.
# Usage: scripts/gallery_mesh_shadow.sh [path/to/terrashade]   (default: the release build)
set -euo pipefail
cd "$(dirname "$0")/.."
ts=${1:-build/release/app/terrashade}
dem=data/grenoble_500px.tif
cessna=../shared/data/meshes/c172p.ac
truck=../shared/data/meshes/CesiumMilkTruck/CesiumMilkTruck.gltf
mkdir -p docs/gallery
$ts render "$dem" --crop 5.76,45.16,5.91,45.26 --time 2025-06-21T18:30:00Z \
  --mesh "$cessna" --at 5.80,45.21,500agl --hpr 60,0,0 --scale 120 \
  --size 600x400 --out docs/gallery/cessna_shadow.png
$ts render "$dem" --crop 5.70,45.10,5.98,45.32 --sun-azimuth 280 --sun-elevation 25 \
  --mesh "$cessna" --at 5.845,45.215,300agl --hpr 30,0,0 --scale 120 \
  --view perspective --camera 5.835,45.19,1700,15,-22,45 --size 800x450 --out docs/gallery/cessna_view.png
$ts render "$dem" --crop 5.70,45.10,5.98,45.32 --sun-azimuth 280 --sun-elevation 25 \
  --mesh "$cessna" --at 5.845,45.215,30agl --hpr 30,0,0 \
  --view perspective --camera 5.8437,45.2140,330,50,-22,40 --size 640x360 --out docs/gallery/cessna_real_size.png
$ts render "$dem" --crop 5.76,45.16,5.91,45.26 --time 2025-06-21T12:00:00Z --sky overcast \
  --mesh "$truck" --mesh-forward +x --at 5.80,45.21,0agl --hpr 60,0,0 --scale 120 \
  --size 600x400 --out docs/gallery/milk_truck_overcast.png
$ts render "$dem" --crop 5.70,45.10,5.98,45.32 --time 2025-06-21T12:00:00Z --sky overcast \
  --mesh "$truck" --mesh-forward +x --at 5.80,45.21,0agl --hpr 60,0,0 --scale 120 \
  --view perspective --camera 5.787,45.195,2000,31,-42,40 --size 800x450 --out docs/gallery/milk_truck_view.png
ls -l docs/gallery/cessna_shadow.png docs/gallery/cessna_view.png docs/gallery/cessna_real_size.png \
  docs/gallery/milk_truck_overcast.png \
  docs/gallery/milk_truck_view.png
