#!/usr/bin/env python3
"""Compares terrashade's linear map with Blender Cycles' on the same crop (docs/accuracy.md,
"Against Blender Cycles"): Pearson correlation of luminance and relative RMSE = RMSE / mean(Cycles).

    /usr/bin/python3 scripts/cycles_compare.py CYCLES.tif TERRASHADE.tif [--terrashade-scale S] [--border B]
        [--dem CROP.tif --sun-azimuth AZ --sun-elevation EL] [--alternative CYCLES_ALT.tif [--undecided F]]

Both are float RGB rasters of the same size (Cycles' GeoTIFF from scripts/cycles_reference.py,
terrashade's .exr converted to a float TIFF). --terrashade-scale multiplies terrashade's radiance
(the albedo ratio: terrashade's grey is albedo 0.18 and, with no interreflection, its radiance is
linear in the albedo). --border drops that many texels on each side: Cycles' mesh ends at the
crop, so its border texels see open ground beyond where the DEM has more terrain, and terrashade's
one-sided border normals are not Cycles' triangles there. With --dem and the sun, the texels in
the terrain's cast shadow (facing the sun, the whole disc below the horizon in its azimuth,
marched on the DEM) are measured on their own as well: cast_shadow_relative_rmse is their RMSE
over their mean Cycles radiance. With --alternative, a second Cycles render of the same scene
that differs only in a convention the scene does not decide (scripts/cycles_reference.py
--terminator-offset 0: whether a texel whose smooth normal faces the sun is shadowed by the facet
it sits on): texels where the two differ by more than --undecided (default 0.02) of the mean
Cycles radiance are undecided, and the measures are given again over the rest (*_decided).
Prints one JSON object.
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


def cast_shadow_mask(dem_path, azimuth_deg, elevation_deg):
    """Texels that face the sun and see none of its 0.53 degree disc over the terrain (no
    curvature, as the Cycles scene has none), a quarter degree of margin beyond the disc's edge."""
    ds = gdal.Open(dem_path)
    z = ds.ReadAsArray().astype(np.float64)
    gt = ds.GetGeoTransform()
    px, py = abs(gt[1]), abs(gt[5])
    az, el = np.radians(azimuth_deg), np.radians(elevation_deg)
    east, north = np.sin(az), np.cos(az)
    s_vec = np.array([np.cos(el) * east, np.cos(el) * north, np.sin(el)])
    # Normals by central differences (the grid's own), then the sun side.
    dzdx = np.gradient(z, px, axis=1)
    dzdy = -np.gradient(z, py, axis=0)  # rows run south
    n = np.stack([-dzdx, -dzdy, np.ones_like(z)])
    n /= np.linalg.norm(n, axis=0)
    facing = np.tensordot(s_vec, n, axes=1) > 0.05
    rows, cols = np.mgrid[0 : z.shape[0], 0 : z.shape[1]].astype(np.float64)
    step_c, step_r = east * 0.5, -north * 0.5  # half a texel towards the sun
    step_m = 0.5 * np.hypot(east * px, north * py)
    highest = np.full(z.shape, -np.inf)
    for k in range(1, 4 * max(z.shape)):
        c, r = cols + k * step_c, rows + k * step_r
        inside = (c >= 0) & (c <= z.shape[1] - 1) & (r >= 0) & (r <= z.shape[0] - 1)
        if not inside.any():
            break
        c0 = np.clip(np.floor(c).astype(int), 0, z.shape[1] - 2)
        r0 = np.clip(np.floor(r).astype(int), 0, z.shape[0] - 2)
        fc, fr = np.clip(c - c0, 0, 1), np.clip(r - r0, 0, 1)
        h = (z[r0, c0] * (1 - fc) * (1 - fr) + z[r0, c0 + 1] * fc * (1 - fr) + z[r0 + 1, c0] * (1 - fc) * fr
             + z[r0 + 1, c0 + 1] * fc * fr)
        angle = np.arctan2(h - z, k * step_m)
        highest = np.where(inside, np.maximum(highest, angle), highest)
    return facing & (highest > el + np.radians(0.265 + 0.25))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("cycles")
    p.add_argument("terrashade")
    p.add_argument("--terrashade-scale", type=float, default=1.0)
    p.add_argument("--border", type=int, default=4)
    p.add_argument("--dem", help="the crop both rendered, to measure the cast shadows on their own")
    p.add_argument("--sun-azimuth", type=float, help="degrees clockwise from north")
    p.add_argument("--sun-elevation", type=float, help="degrees")
    p.add_argument("--alternative", help="Cycles under the other terminator convention, to find undecided texels")
    p.add_argument("--undecided", type=float, default=0.02,
                   help="texels where the two Cycles renders differ by more than this fraction of the mean")
    a = p.parse_args()
    cycles, terrashade = luminance(a.cycles), a.terrashade_scale * luminance(a.terrashade)
    result = compare(cycles, terrashade, a.border)
    b = a.border
    inner = np.zeros(cycles.shape, bool)
    inner[b : cycles.shape[0] - b, b : cycles.shape[1] - b] = True
    decided = inner.copy()
    if a.alternative:
        alternative = luminance(a.alternative)
        if alternative.shape != cycles.shape:
            sys.exit(f"cycles_compare: sizes differ, {cycles.shape} and {alternative.shape}")
        undecided = np.abs(alternative - cycles) > a.undecided * cycles[inner].mean()
        decided &= ~undecided
        c, t = cycles[decided], terrashade[decided]
        result["undecided_texels"] = int((inner & undecided).sum())
        result["relative_rmse_decided"] = float(np.sqrt(np.mean((t - c) ** 2)) / cycles[inner].mean())
    if a.dem:
        if a.sun_azimuth is None or a.sun_elevation is None:
            sys.exit("cycles_compare: --dem needs --sun-azimuth and --sun-elevation")
        mask = cast_shadow_mask(a.dem, a.sun_azimuth, a.sun_elevation) & inner
        c, t = cycles[mask], terrashade[mask]
        result["cast_shadow_texels"] = int(mask.sum())
        if mask.any():
            result["cast_shadow_relative_rmse"] = float(np.sqrt(np.mean((t - c) ** 2)) / c.mean())
            result["cast_shadow_bias"] = float((t - c).mean() / c.mean())
        if a.alternative and (mask & decided).any():
            # Over the same mean as the whole cast shadow, so that the two figures compare.
            d = mask & decided
            result["cast_shadow_relative_rmse_decided"] = float(
                np.sqrt(np.mean((terrashade[d] - cycles[d]) ** 2)) / c.mean())
    print(json.dumps({k: round(v, 6) if isinstance(v, float) else v for k, v in result.items()}))


if __name__ == "__main__":
    main()
