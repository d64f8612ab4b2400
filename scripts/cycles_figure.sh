#!/usr/bin/env bash
# docs/gallery/cycles_vs_terrashade.png: terrashade beside Blender Cycles (4 bounces) on the held-out
# Anatolia crop of docs/accuracy.md ("Against Blender Cycles"): grey albedo 0.3 with the sun 20
# degrees up in the south-east and the clear sky (top row), the overcast sky (middle row), and
# snow (albedo 0.8) under the overcast sky (bottom row, where bounced light matters most);
# Cycles, terrashade (its default: one bounce), and terrashade's relative difference (blue
# darker, red brighter, +-10%). Both pictures of a row share one exposure (Cycles' mean at 0.45
# before the sRGB curve).
# Usage: scripts/cycles_figure.sh [BUILD_DIR] [SAMPLES]   (needs scripts/setup_reference.sh)
#   CYCLES_WORK=DIR: reuse the Cycles renders scripts/cycles_bench.sh kept there
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build=${1:-$root/build/release}
samples=${2:-256}
if [ -n "${CYCLES_WORK:-}" ]; then work=$CYCLES_WORK; else  # scripts/cycles_bench.sh's renders
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  "$root/scripts/cycles_held_out_dem.sh" "$work/anatolia_tm90.tif"
  gdal_translate -q -srcwin 20 480 160 160 "$work/anatolia_tm90.tif" "$work/crop.tif"
fi
for case in clear:0.3 overcast:0.3 overcast:0.8; do
  REUSE_CYCLES=${REUSE_CYCLES:-$([ -n "${CYCLES_WORK:-}" ] && echo 1 || echo 0)} \
    "$root/scripts/cycles_reference.sh" "$build" "$work/crop.tif" "$work/out" "${case%:*}" "${case#*:}" 4 "$samples" 135 20
done
/usr/bin/python3 - "$work/out" "$root/docs/gallery/cycles_vs_terrashade.png" <<'PY'
import sys
import numpy as np
from osgeo import gdal

out, png = sys.argv[1], sys.argv[2]
rec709 = np.array([0.2126, 0.7152, 0.0722])

def lum(path, scale=1.0):
    return scale * np.tensordot(rec709, gdal.Open(path).ReadAsArray().astype(np.float64)[:3], axes=1)

def srgb(x):
    x = np.clip(x, 0, 1)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * np.power(x, 1 / 2.4) - 0.055)

rows = []
for sky, albedo in (("clear", "0.3"), ("overcast", "0.3"), ("overcast", "0.8")):
    tag = f"{sky}_e20_a{albedo}_b4"
    cy = lum(f"{out}/cycles_{tag}.tif")
    ts = lum(f"{out}/terrashade_{tag}.tif")
    k = 0.45 / cy.mean()
    grey = lambda v: np.repeat((255 * srgb(k * v))[None], 3, axis=0)
    d = np.clip((ts - cy) / cy.mean() / 0.10, -1, 1)  # +-10% of Cycles' mean
    diff = np.stack([np.where(d > 0, 1, 1 + d), 1 - np.abs(d), np.where(d < 0, 1, 1 - d)]) * 255
    gap = np.full((3, cy.shape[0], 8), 255.0)
    rows.append(np.concatenate([grey(cy), gap, grey(ts), gap, diff], axis=2))
sep = np.full((3, 8, rows[0].shape[2]), 255.0)
img = np.concatenate([rows[0], sep, rows[1], sep, rows[2]], axis=1).round().astype(np.uint8)
# Twice the size: one texel as 2 x 2 pixels.
img = img.repeat(2, axis=1).repeat(2, axis=2)
mem = gdal.GetDriverByName("MEM").Create("", img.shape[2], img.shape[1], 3, gdal.GDT_Byte)
for b in range(3):
    mem.GetRasterBand(b + 1).WriteArray(img[b])
gdal.GetDriverByName("PNG").CreateCopy(png, mem)
print(f"wrote {png}")
PY
