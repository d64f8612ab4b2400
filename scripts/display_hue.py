#!/usr/bin/env python3
"""How far the 8-bit picture's colours are from the rendered radiance's (docs/rendering.md,
"Output and tone mapping"): renders one perspective view into the sun over the Grenoble DEM at
several sun elevations, as PNG (exposure, tone curve, sRGB, dither: what users see) and as EXR
(the linear radiance), and compares their CIE 1931 xy per pixel, over the pixels where no channel
is clipped (code 255). Pixels whose darkest channel is below code 32 are counted apart: there
the 8-bit rounding alone moves xy by up to ~0.01.

Usage: scripts/display_hue.py [--terrashade PATH] [--csv OUT.csv] [--keep DIR]
Needs oiiotool (OpenImageIO's tool, to read the EXR) and python3 with numpy and GDAL.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
from osgeo import gdal

ELEVATIONS = [0, 2, 5, 10, 20, 40, 70]
# RGB (Rec. 709 primaries, linear) -> CIE XYZ.
RGB_TO_XYZ = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722], [0.0193, 0.1192, 0.9505]])


def srgb_eotf(code):
    c = code / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def xy(rgb):
    xyz = rgb @ RGB_TO_XYZ.T
    s = xyz.sum(axis=-1, keepdims=True)
    return xyz[..., :2] / np.maximum(s, 1e-30)


def read(path):
    ds = gdal.Open(path)
    return np.stack([ds.GetRasterBand(b + 1).ReadAsArray() for b in range(3)], axis=-1).astype(np.float64)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--terrashade", default=os.path.join(here, "..", "build", "release", "app", "terrashade"))
    p.add_argument("--dem", default=os.path.join(here, "..", "data", "grenoble_500px.tif"))
    p.add_argument("--csv", help="write the table here")
    p.add_argument("--keep", help="keep the pictures in this folder")
    a = p.parse_args()
    work = a.keep or tempfile.mkdtemp(prefix="display_hue_")
    os.makedirs(work, exist_ok=True)
    rows = []
    for el in ELEVATIONS:
        base = os.path.join(work, f"sun{el:02d}")
        cmd = [a.terrashade, "render", a.dem, "--view", "perspective", "--camera", "5.62,45.33,3000,270,4,62",
               "--size", "480x270", "--sun-azimuth", "270", "--sun-elevation", str(el)]
        for ext in ("png", "exr"):
            subprocess.run(cmd + ["--out", f"{base}.{ext}"], check=True, stdout=subprocess.DEVNULL)
        subprocess.run(["oiiotool", f"{base}.exr", "-d", "float", "-o", f"{base}_exr.tif"], check=True)
        codes = read(f"{base}.png")
        radiance = read(f"{base}_exr.tif")
        unclipped = (codes.max(axis=-1) < 255) & (radiance.max(axis=-1) > 0)
        bright = unclipped & (codes.min(axis=-1) >= 32)
        d = np.linalg.norm(xy(srgb_eotf(codes)) - xy(radiance), axis=-1)
        row = {"sun_elevation": el, "unclipped": int(unclipped.sum()), "clipped": int((codes.max(axis=-1) == 255).sum())}
        for name, mask in (("all", unclipped), ("bright", bright)):
            v = d[mask]
            row[f"{name}_pixels"] = int(v.size)
            row[f"{name}_median"] = float(np.median(v)) if v.size else float("nan")
            row[f"{name}_p99"] = float(np.percentile(v, 99)) if v.size else float("nan")
            row[f"{name}_over_0.02"] = float((v > 0.02).mean()) if v.size else float("nan")
        # The same radiance through the curve applied to each channel on its own (before
        # terrashade kept the hue), with the same automatic exposure, for comparison.
        lum = radiance @ RGB_TO_XYZ[1]
        scale = 0.18 / np.exp(np.mean(np.log(np.maximum(lum, 0) + 1e-6)))
        x = np.maximum(radiance * scale, 0)
        curve = np.clip(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0, 1)
        before = np.round(255 * np.where(curve <= 0.0031308, 12.92 * curve, 1.055 * curve ** (1 / 2.4) - 0.055))
        kept = (before.max(axis=-1) < 255) & (radiance.max(axis=-1) > 0)
        v = np.linalg.norm(xy(srgb_eotf(before)) - xy(radiance), axis=-1)[kept]
        row["per_channel_median"] = float(np.median(v))
        row["per_channel_p99"] = float(np.percentile(v, 99))
        row["per_channel_over_0.02"] = float((v > 0.02).mean())
        rows.append(row)
        print(f"sun {el:2d} deg: {row['clipped']} px clipped; unclipped: xy off by median {row['all_median']:.4f}, "
              f"p99 {row['all_p99']:.4f}, {100 * row['all_over_0.02']:.2f}% over 0.02; darkest channel >= 32: "
              f"median {row['bright_median']:.4f}, p99 {row['bright_p99']:.4f}, "
              f"{100 * row['bright_over_0.02']:.2f}% over 0.02; a curve per channel: median "
              f"{row['per_channel_median']:.4f}, p99 {row['per_channel_p99']:.4f}, "
              f"{100 * row['per_channel_over_0.02']:.1f}% over 0.02", flush=True)
    if a.csv:
        with open(a.csv, "w") as f:
            keys = list(rows[0])
            f.write(",".join(keys) + "\n")
            for r in rows:
                f.write(",".join(f"{r[k]:.5g}" if isinstance(r[k], float) else str(r[k]) for k in keys) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
