#!/usr/bin/env bash
# docs/flythrough/shadow_detail_pixel.png and _texel.png: one close cockpit frame over the SRTM
# tile N39E040 (90 m texels, ../shared/data/dem) with the sun 13 degrees up in the west-north-west,
# the sun's shadows placed inside texels (--shadow-detail pixel, the default) and the texels'
# visible shares blended (texel) (docs/flythrough.md, "Sun shadows inside texels"). Needs a built
# terrashade and a Vulkan device (lavapipe will do).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ts="${TERRASHADE:-$root/build/release/app/terrashade}"
dem="$root/../shared/data/dem/srtm3_N39E040_1000px.tif"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
for detail in pixel texel; do
  "$ts" fly "$dem" --path "$root/docs/flythrough/n39e040_close_path.csv" --camera cockpit \
      --time 2024-06-21T15:30:00Z --frames 1 --size 480x270 --shadow-detail "$detail" --out "$work/$detail" > /dev/null
  cp "$work/$detail/frame_0000.png" "$root/docs/flythrough/shadow_detail_$detail.png"
done
ls -l "$root"/docs/flythrough/shadow_detail_*.png
