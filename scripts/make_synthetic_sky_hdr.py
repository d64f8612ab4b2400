#!/usr/bin/python3
"""Writes data/sunset_synthetic.hdr: a procedural equirectangular sunset sky (256x128, Radiance
RGBE, flat scanlines), for the gallery's "HDR map" picture and as a --sky example. No photograph
is involved, so it has no licence strings attached; it is regenerated bit for bit by this script.

Layout (docs/lighting.md): row 0 = zenith, last row = nadir; the centre column faces north and
azimuth grows to the right (east at u = 0.75, west at u = 0.25). The sun is a bright blob 4 deg
above the western horizon (azimuth 265), so with `--sky data/sunset_synthetic.hdr` it lights
from the west-south-west; the sky is blue overhead, orange towards the sun, the ground a dim
brown-green. Units: kcd/m^2-like, as the analytic skies (zenith ~1, sun blob ~1500).
Usage: /usr/bin/python3 scripts/make_synthetic_sky_hdr.py [OUT]
"""
import math
import os
import sys

import numpy as np

W, H = 256, 128
SUN_AZ, SUN_EL = 265.0, 4.0


def sky_image():
    u = (np.arange(W) + 0.5) / W
    v = (np.arange(H) + 0.5) / H
    az = np.radians((u - 0.5) * 360.0)[None, :]          # clockwise from north
    el = np.radians(90.0 - v * 180.0)[:, None]
    # ENU direction of each pixel and of the sun.
    d = np.stack([np.cos(el) * np.sin(az), np.cos(el) * np.cos(az), np.sin(el) * np.ones_like(az)], -1)
    s_az, s_el = math.radians(SUN_AZ), math.radians(SUN_EL)
    s = np.array([math.cos(s_el) * math.sin(s_az), math.cos(s_el) * math.cos(s_az), math.sin(s_el)])
    cos_gamma = np.clip(d @ s, -1.0, 1.0)
    gamma = np.arccos(cos_gamma)
    up = np.clip(d[..., 2], 0.0, 1.0)

    zenith = np.array([0.25, 0.45, 1.0])          # deep blue
    horizon = np.array([1.6, 1.0, 0.7])           # pale warm haze
    glow = np.array([6.0, 2.4, 0.6])              # orange around the sun
    t = np.power(1.0 - up, 3.0)[..., None]
    img = zenith * (1 - t) + horizon * t
    img = img + glow * (np.exp(-gamma / 0.35) * (0.4 + 0.6 * t[..., 0]))[..., None]
    # Sun: a blob about 1.5 pixels wide, very bright, warm.
    img = img + np.array([1500.0, 1100.0, 700.0]) * np.exp(-(gamma / math.radians(1.2)) ** 2)[..., None]
    # Ground below the horizon: dim, lit a little from the west.
    ground = np.array([0.12, 0.11, 0.07]) * (1.0 + 0.5 * np.clip(d[..., 0] * -1.0, 0, 1))[..., None]
    below = (d[..., 2] < 0)[..., None]
    return np.where(below, ground, img).astype(np.float64)


def to_rgbe(img):
    v = img.max(-1)
    m, e = np.frexp(v)
    scale = np.where(v > 1e-32, m * 256.0 / np.where(v > 1e-32, v, 1.0), 0.0)
    rgbe = np.zeros(img.shape[:2] + (4,), np.uint8)
    rgbe[..., :3] = np.clip(np.floor(img * scale[..., None]), 0, 255).astype(np.uint8)
    rgbe[..., 3] = np.where(v > 1e-32, e + 128, 0).astype(np.uint8)
    # A flat scanline must not start like an RLE one (2, 2, <128): nudge such a first pixel.
    first = rgbe[:, 0]
    clash = (first[:, 0] == 2) & (first[:, 1] == 2) & (first[:, 2] < 128)
    first[clash, 0] = 3
    return rgbe


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "data", "sunset_synthetic.hdr")
    rgbe = to_rgbe(sky_image())
    header = f"#?RADIANCE\n# terrashade scripts/make_synthetic_sky_hdr.py\nFORMAT=32-bit_rle_rgbe\n\n-Y {H} +X {W}\n"
    with open(out, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(rgbe.tobytes())
    print(f"wrote {out} ({os.path.getsize(out)} bytes)")


if __name__ == "__main__":
    main()
