#!/usr/bin/env bash
# Renders docs/gallery/cessna_shadow.png: the Cessna 172 (../shared/data/meshes/c172p.ac, scaled
# x120 so its shadow spans a few texels of the 156 x 222 m Grenoble grid; at scale 1 it is a tenth
# of a texel) flying over the Gresivaudan valley on a June evening, sun 8 degrees up in the
# west-north-west: its crisp sun shadow lies on the west-facing slope of Belledonne, its soft sky
# shadow on the valley floor below it. A map of a 0.15 x 0.10 degree crop, resampled 8x.
# Usage: scripts/gallery_mesh_shadow.sh [path/to/terrashade]   (default: the release build)
set -euo pipefail
cd "$(dirname "$0")/.."
ts=${1:-build/release/app/terrashade}
mkdir -p docs/gallery
$ts render data/grenoble_500px.tif --crop 5.76,45.16,5.91,45.26 --time 2025-06-21T18:30:00Z \
  --mesh ../shared/data/meshes/c172p.ac --at 5.80,45.21,500agl --hpr 60,0,0 --scale 120 \
  --size 600x400 --out docs/gallery/cessna_shadow.png
ls -l docs/gallery/cessna_shadow.png
