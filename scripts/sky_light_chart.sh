#!/usr/bin/env bash
# The sky's light, speed against accuracy (docs/rendering.md, "The sky's light over the horizons"):
# --sky-light sh and horizons with 4, 8, 16 (default) and 32 sectors. Accuracy: the stored
# 64 x 64 Anatolia crop against Blender Cycles' stored renders (tests/render/reference/, 4
# bounces, sun 20 degrees up: the physical clear sky, Preetham's, overcast), relative RMSE of
# the luminance over the inner 56 x 56 as the CLI test measures it. Speed: `bench relight --cpu`
# on data/grenoble_500px.tif (250,000 texels, 24 frames, 2 threads): the per-frame time and the
# one-time cost. Writes docs/charts/sky_light.csv and docs/charts/sky_light.png (~2 minutes).
# Usage: scripts/sky_light_chart.sh [BUILD_DIR]   (needs oiiotool and python3-gdal, matplotlib)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build=${1:-$root/build/release}
ts="$build/app/terrashade"
ref="$root/tests/render/reference"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
csv="$root/docs/charts/sky_light.csv"

for sky in clear preetham overcast; do oiiotool "$ref/cycles_${sky}_e20_a0.3_b4.exr" -d float -o "$work/cycles_$sky.tif"; done
echo "mode,sectors,clear_rel_rmse,preetham_rel_rmse,overcast_rel_rmse,frame_ms,shading_ms,one_time_s" >"$csv"
for variant in sh:0 horizons:4 horizons:8 horizons:16 horizons:32; do
  mode=${variant%:*} sectors=${variant#*:}
  args=(--sky-light "$mode")
  [ "$mode" = horizons ] && args+=(--sky-sectors "$sectors")
  errors=()
  for sky in clear preetham overcast; do
    "$ts" render "$ref/anatolia_tm90_64.tif" --colors grey:0.3 --sky "$sky:albedo=0.3" --sun-azimuth 135 \
      --sun-elevation 20 --no-curvature --cpu --threads 2 "${args[@]}" -o "$work/ts.exr" >/dev/null
    oiiotool "$work/ts.exr" -d float -o "$work/ts.tif"
    errors+=("$(/usr/bin/python3 - "$work/cycles_$sky.tif" "$work/ts.tif" <<'PY'
import sys
import numpy as np
from osgeo import gdal
def lum(path):
    d = gdal.Open(path)
    if d.RasterCount == 1:
        return d.GetRasterBand(1).ReadAsArray().astype(float)
    a = np.stack([d.GetRasterBand(i + 1).ReadAsArray().astype(float) for i in range(3)], -1)
    return a @ [0.2126, 0.7152, 0.0722]
c, t = lum(sys.argv[1])[4:-4, 4:-4], lum(sys.argv[2])[4:-4, 4:-4]
print("%.5f" % (np.sqrt(((t - c) ** 2).mean()) / c.mean()))
PY
)")
  done
  bench=$("$ts" bench relight "$root/data/grenoble_500px.tif" --cpu --threads 2 "${args[@]}" 2>&1)
  frame=$(echo "$bench" | sed -n 's/^per frame: .*shading \([0-9.]*\) ms, total \([0-9.]*\) ms.*/\2/p')
  shading=$(echo "$bench" | sed -n 's/^per frame: .*shading \([0-9.]*\) ms, total.*/\1/p')
  once=$(echo "$bench" | sed -n 's/^one-time: .*) \([0-9.]*\) s + transfer vectors .*) \([0-9.]*\) s (.*/\1 \2/p' |
    awk '{print $1 + $2}')
  echo "$mode,$sectors,${errors[0]},${errors[1]},${errors[2]},$frame,$shading,$once" | tee -a "$csv"
done
/usr/bin/python3 "$root/scripts/chart_sky_light.py" "$csv" "$root/docs/charts/sky_light.png"
echo "wrote $csv and docs/charts/sky_light.png"
