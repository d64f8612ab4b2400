#!/usr/bin/python3
"""Chart for docs/insolation.md from `terrashade bench insolation --maps`.

usage: chart_insolation.py MAPS.tif OUT.png
MAPS.tif: the bench's 5 bands (terrashade beam, r.sun beam with the r.horizon maps, with the
maps raised to 0 deg, with r.sun's own shadowing, all Wh/m2 over the day; open terrain 1/0).
Writes one small PNG: terrashade's and r.sun's (maps raised to 0) beam side by side on one
scale, the map of r.sun / terrashade - 1, and the histograms of that ratio for each r.sun
variant on open terrain and elsewhere.
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from osgeo import gdal  # noqa: E402


def bands(path):
    ds = gdal.Open(path)  # kept open while its bands are read
    if ds is None or ds.RasterCount != 5:
        sys.exit(f"chart_insolation: {path}: not the 5-band --maps output of bench insolation")
    return [ds.GetRasterBand(i + 1).ReadAsArray().astype(np.float64) for i in range(5)]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    ts, hz, zero, own, open_mask = bands(sys.argv[1])
    valid = np.isfinite(ts) & (ts > 0) & np.isfinite(open_mask)
    is_open = valid & (open_mask > 0.5)
    rest = valid & (open_mask < 0.5)

    fig = plt.figure(figsize=(10.5, 6.6), dpi=80)
    grid = fig.add_gridspec(2, 6)
    ax_ts, ax_rsun, ax_map = (fig.add_subplot(grid[0, 2 * i:2 * i + 2]) for i in range(3))
    ax_open, ax_rest = fig.add_subplot(grid[1, 0:3]), fig.add_subplot(grid[1, 3:6])
    lo, hi = np.nanpercentile(np.where(valid, ts, np.nan), [1, 99]) / 1000
    for ax, b, title in ((ax_ts, ts, "terrashade beam"), (ax_rsun, zero, "r.sun beam (maps raised to 0)")):
        shown = ax.imshow(np.where(valid, b / 1000, np.nan), cmap="inferno", vmin=lo, vmax=hi, interpolation="nearest")
        ax.set_title(f"{title}, 21 June 2024", fontsize=8)
        ax.set_xticks([])
        ax.set_yticks([])
        cbar = fig.colorbar(shown, ax=ax, fraction=0.046, pad=0.03)
        cbar.set_label("kWh/m2 over the day", fontsize=7)
        cbar.ax.tick_params(labelsize=7)
    rel = np.where(valid, zero / np.where(valid, ts, 1) - 1, np.nan) * 100
    im = ax_map.imshow(rel, cmap="RdBu_r", vmin=-5, vmax=5, interpolation="nearest")
    ax_map.contour(np.where(np.isfinite(open_mask), open_mask, 0), levels=[0.5], colors="k", linewidths=0.4)
    ax_map.set_title("r.sun (maps raised to 0) / terrashade - 1", fontsize=8)
    ax_map.set_xticks([])
    ax_map.set_yticks([])
    cb = fig.colorbar(im, ax=ax_map, fraction=0.046, pad=0.03)
    cb.set_label("beam difference (%); black: open terrain", fontsize=7)
    cb.ax.tick_params(labelsize=7)

    bins = np.linspace(-20, 10, 121)
    series = [("r.horizon maps", hz, "tab:red"), ("maps raised to 0", zero, "tab:blue"),
              ("own shadowing", own, "tab:green")]
    for ax, mask, title in ((ax_open, is_open, "open terrain"), (ax_rest, rest, "elsewhere")):
        for name, b, colour in series:
            d = (b[mask] / ts[mask] - 1) * 100
            d = d[np.isfinite(d)]
            within = np.mean(np.abs(d) <= 2) * 100 if d.size else np.nan
            ax.hist(np.clip(d, bins[0], bins[-1]), bins=bins, histtype="step", color=colour,
                    label=f"{name}: median {np.median(d):+.2f}%, {within:.0f}% within 2%",
                    weights=np.full(d.size, 100.0 / max(d.size, 1)))
        ax.axvspan(-2, 2, color="0.9", zorder=0)
        ax.set_title(f"r.sun beam / terrashade - 1, {title} ({mask.sum()} texels)", fontsize=8)
        ax.set_xlabel("%  (clipped to -20..10)", fontsize=7)
        ax.set_ylabel("% of texels", fontsize=7)
        ax.tick_params(labelsize=7)
        ax.legend(fontsize=6, loc="upper left", frameon=False)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=80)
    try:  # a noisy map compresses badly as RGB: a 64-colour palette keeps the PNG small
        from PIL import Image
        Image.open(sys.argv[2]).convert("RGB").quantize(64).save(sys.argv[2], optimize=True)
    except ImportError:
        pass


if __name__ == "__main__":
    main()
