#!/usr/bin/env bash
# The pictures of docs/flythrough.md, each one frame of `terrashade fly --frames` (commands as
# the page gives them): the chase views over Grenoble and the SRTM tile N39E040, the HUD, the
# Cessna's shadow on a slope, and one close cockpit frame over N39E040 with the sun 13 degrees
# up with the sun's shadows placed inside texels (--shadow-detail pixel, the default) and the
# texels' shares blended (texel) ("Sun shadows inside texels"). Needs a built terrashade and a
# Vulkan device (lavapipe will do). The GIF is not remade (it needs ffmpeg: the page says how).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ts="${TERRASHADE:-$root/build/release/app/terrashade}"
dem="$root/../shared/data/dem"
out="$root/docs/flythrough"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cessna=(--mesh "$root/../shared/data/meshes/c172p.ac" --mesh-forward -x)
grenoble=("$dem/copernicus_N45E005_grenoble_500px.tif" --path "$out/grenoble_path.csv" --time 2024-06-21T16:30:00Z)
"$ts" fly "${grenoble[@]}" "${cessna[@]}" --frames 3 --size 480x270 --out "$work/chase" > /dev/null
cp "$work/chase/frame_0001.png" "$out/grenoble_chase.png"
"$ts" fly "${grenoble[@]}" "${cessna[@]}" --frames 3 --size 960x540 --hud on --out "$work/hud" > /dev/null
cp "$work/hud/frame_0002.png" "$out/hud_chase.png"
"$ts" fly "$dem/srtm3_N39E040_1000px.tif" --path "$out/n39e040_path.csv" --time 2024-06-21T14:00:00Z \
    --frames 3 --size 480x270 --out "$work/srtm" > /dev/null
cp "$work/srtm/frame_0001.png" "$out/srtm_n39e040_chase.png"
"$ts" fly "$dem/copernicus_N45E005_grenoble_500px.tif" --path "$out/grenoble_slope_path.csv" \
    --time 2024-06-21T15:30:00Z "${cessna[@]}" --frames 3 --size 640x360 --out "$work/shadow" > /dev/null
cp "$work/shadow/frame_0001.png" "$out/grenoble_shadow.png"
for detail in pixel texel; do
  "$ts" fly "$dem/srtm3_N39E040_1000px.tif" --path "$out/n39e040_close_path.csv" --camera cockpit \
      --time 2024-06-21T15:30:00Z --frames 1 --size 480x270 --shadow-detail "$detail" --out "$work/$detail" > /dev/null
  cp "$work/$detail/frame_0000.png" "$out/shadow_detail_$detail.png"
done
ls -l "$out"/*.png
