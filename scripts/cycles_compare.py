#!/usr/bin/env python3
"""Compares terrashade's linear map with Blender Cycles' on the same crop (docs/accuracy.md,
"Against Blender Cycles"): Pearson correlation of luminance and relative RMSE = RMSE / mean(Cycles).

    /usr/bin/python3 scripts/cycles_compare.py CYCLES.tif TERRASHADE.tif [--terrashade-scale S] [--border B]

Both are float RGB rasters of the same size (Cycles' GeoTIFF from scripts/cycles_reference.py,
terrashade's .exr converted to a float TIFF). --terrashade-scale multiplies terrashade's radiance
(the albedo ratio: terrashade's grey is albedo 0.18 and, with no interreflection, its radiance is
linear in the albedo). --border drops that many texels on each side: Cycles' mesh ends at the
crop, so its border texels see open ground beyond where the DEM has more terrain, and terrashade's
one-sided border normals are not Cycles' triangles there. Prints one JSON object.
"""
import argparse
import json
import sys

import numpy as np
from osgeo import gdal

REC709 = np.array([0.2126, 0.7152, 0.0722])


def luminance(path):
    ds = gdal.Open(path)
    if ds is None:
        sys.exit(f"cycles_compare: cannot open {path}")
    rgb = ds.ReadAsArray().astype(np.float64)[:3]
    return np.tensordot(REC709, rgb, axes=1)


def compare(cycles, terrashade, border):
    if cycles.shape != terrashade.shape:
        sys.exit(f"cycles_compare: sizes differ, {cycles.shape} and {terrashade.shape}")
    inner = (slice(border, cycles.shape[0] - border), slice(border, cycles.shape[1] - border))
    c, t = cycles[inner].ravel(), terrashade[inner].ravel()
    rmse = float(np.sqrt(np.mean((t - c) ** 2)))
    fit = float(np.dot(t, c) / np.dot(t, t))  # least-squares scale of terrashade onto Cycles
    return {
        "texels": int(c.size),
        "correlation": float(np.corrcoef(c, t)[0, 1]),
        "relative_rmse": rmse / float(c.mean()),
        "bias": float((t - c).mean() / c.mean()),
        "p99_relative_error": float(np.percentile(np.abs(t - c) / np.maximum(c, 1e-12), 99)),
        "mean_cycles": float(c.mean()),
        "mean_terrashade": float(t.mean()),
        "fitted_scale": fit,
        "relative_rmse_after_fit": float(np.sqrt(np.mean((fit * t - c) ** 2)) / c.mean()),
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("cycles")
    p.add_argument("terrashade")
    p.add_argument("--terrashade-scale", type=float, default=1.0)
    p.add_argument("--border", type=int, default=4)
    a = p.parse_args()
    result = compare(luminance(a.cycles), a.terrashade_scale * luminance(a.terrashade), a.border)
    print(json.dumps({k: round(v, 6) if isinstance(v, float) else v for k, v in result.items()}))


if __name__ == "__main__":
    main()
