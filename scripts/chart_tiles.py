#!/usr/bin/env python3
"""docs/tiles.md figures from scripts/tiles_figures.sh's work directory:
tiles_gdaldem_vs_relief.png (a 2x2 block of z10 tiles over Grenoble, classic vs relief) and
tiles_relief_vs_reference.png (relief, the ray-traced reference, their difference in sRGB codes) and
tiles_relief_contrast.png (relief at --relief-contrast 1, 1.5 and 2)."""
import math
import sys
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

work, docs = Path(sys.argv[1]), Path(sys.argv[2])
# The block's centre: Grenoble's valleys and the Vercors, Chartreuse and Belledonne around them,
# north enough that all four tiles lie on the DEM (it ends at 45 N).
LON, LAT, Z = 5.72, 45.45, 10


def tile_xy(lon, lat, z):
    n = 2 ** z
    x = (lon + 180) / 360 * n
    y = (1 - math.asinh(math.tan(math.radians(lat))) / math.pi) / 2 * n
    return x, y


def grey(path):
    """A tile as grey over a paper colour where transparent (missing tile: paper)."""
    paper = np.full((256, 256), 0.96)
    if not path.exists():
        return paper
    a = plt.imread(path).astype(float)
    if a.ndim == 2:
        return a
    g = a[..., 0]
    alpha = a[..., -1] if a.shape[-1] in (2, 4) else np.ones_like(g)
    return g * alpha + paper * (1 - alpha)


def block(folder, lon=LON, lat=LAT, z=Z):
    fx, fy = tile_xy(lon, lat, z)
    x0, y0 = int(fx - 0.5), int(fy - 0.5)
    rows = [np.hstack([grey(folder / str(z) / str(x) / f"{y}.png") for x in (x0, x0 + 1)]) for y in (y0, y0 + 1)]
    return np.vstack(rows), (x0, y0)


def contrast_figure():
    """Relief at three contrasts: Grenoble's z10 block and, if rendered, Anatolia at z12."""
    places = [("grenoble", LON, LAT, Z, "Grenoble z10")]
    if (work / "contrast_anatolia_1").exists():
        places.append(("anatolia", 40.60, 39.42, 12, "Anatolia z12 (90 m DEM)"))
    ks = ("1", "1.5", "2")
    crop = 320  # the block's centre, drawn one tile pixel per figure pixel
    dpi = 100
    fig, axes = plt.subplots(len(places), 3, figsize=(3 * (crop + 24) / dpi, len(places) * (crop + 40) / dpi + 0.3),
                             dpi=dpi, squeeze=False)
    for row, (name, lon, lat, z, label) in enumerate(places):
        for col, k in enumerate(ks):
            img, _ = block(work / f"contrast_{name}_{k}", lon, lat, z)
            o = (img.shape[0] - crop) // 2
            ax = axes[row][col]
            ax.imshow(img[o:o + crop, o:o + crop], cmap="gray", vmin=0, vmax=1, interpolation="nearest")
            ax.set_title(f"{label}, K = {k}" + (" (default)" if k == "1" else ""), fontsize=9)
            ax.set_xticks([]), ax.set_yticks([])
    fig.suptitle("--relief-contrast K: stops about open flat ground times K (flat ground unchanged)", fontsize=10)
    fig.tight_layout()
    fig.savefig(docs / "tiles_relief_contrast.png")


classic, (x0, y0) = block(work / "classic")
relief, _ = block(work / "relief")
fig, axes = plt.subplots(1, 2, figsize=(10, 5.3), dpi=110)
for ax, img, title in zip(axes, (classic, relief),
                          ("gdaldem hillshade + gdal2tiles.py", "terrashade tiles --style relief")):
    ax.imshow(img, cmap="gray", vmin=0, vmax=1, interpolation="nearest")
    ax.set_title(title, fontsize=11)
    ax.set_xticks([]), ax.set_yticks([])
fig.suptitle(f"The same four z{Z} tiles ({x0}-{x0 + 1}/{y0}-{y0 + 1}) north of Grenoble, light from 315 deg at 45 deg",
             fontsize=11)
fig.tight_layout(rect=(0, 0, 1, 0.96))
fig.savefig(docs / "tiles_gdaldem_vs_relief.png")

if (work / "contrast_grenoble_1").exists():
    contrast_figure()
if not (work / "ref").exists():
    print("wrote", docs / "tiles_gdaldem_vs_relief.png")
    sys.exit(0)
got = plt.imread(work / "ref" / "relief.png").astype(float) * 255
ref = plt.imread(work / "ref" / "reference.png").astype(float) * 255
err = got - ref
lim = max(4.0, float(np.percentile(np.abs(err), 99.5)))
stats = (work / "reference.txt").read_text().splitlines()
line = next((l for l in stats if "codes rmse" in l), "")
fig, axes = plt.subplots(1, 3, figsize=(12, 4.4), dpi=110)
for ax, img, title in zip(axes[:2], (got, ref), ("relief (renderer: log-SH sky, sun sweep)",
                                                 "ray-traced reference (720 azimuths)")):
    ax.imshow(img, cmap="gray", vmin=0, vmax=255, interpolation="nearest")
    ax.set_title(title, fontsize=10)
    ax.set_xticks([]), ax.set_yticks([])
im = axes[2].imshow(err, cmap="RdBu_r", vmin=-lim, vmax=lim, interpolation="nearest")
axes[2].set_title("relief - reference (sRGB codes)", fontsize=10)
axes[2].set_xticks([]), axes[2].set_yticks([])
fig.colorbar(im, ax=axes[2], fraction=0.046, pad=0.04)
rmse = math.sqrt(float(np.mean(err ** 2)))
fig.suptitle(f"96 x 96 DEM texels (200 m) around Grenoble at z{Z}: code RMSE {rmse:.2f}, "
             f"p95 |e| {np.percentile(np.abs(err), 95):.0f}", fontsize=11)
fig.tight_layout()
fig.savefig(docs / "tiles_relief_vs_reference.png")
print("wrote", docs / "tiles_gdaldem_vs_relief.png", "and", docs / "tiles_relief_vs_reference.png")
