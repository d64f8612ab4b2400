#!/usr/bin/env python3
"""Charts of the per-frame sun visibility, sweep against exact (docs/accuracy.md).

Input: the CSV of `terrashade bench sun ... --near-field 2,4,8 --csv FILE` (scripts/bench_sun.sh).
Output: OUT_DIR/sun_sweep.png, two panels:
  left:  cost per frame against the worst shadow-mask IoU over the sun positions, one curve per
         DEM through the near-field lengths, with the exact path's cost for comparison;
  right: the shadow-mask IoU (mean over azimuths) against the sun's elevation at each near field.
Usage: chart_sun.py CSV OUT_DIR
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: chart_sun.py CSV OUT_DIR")
    rows = list(csv.DictReader(open(sys.argv[1])))
    if not rows:
        sys.exit("chart_sun.py: no rows in " + sys.argv[1])
    by_dem = defaultdict(lambda: defaultdict(list))  # dem -> near field -> rows
    for r in rows:
        by_dem[r["dem"].split(".")[0].replace("copernicus_", "")][float(r["near_field"])].append(r)

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, (dem, fields) in enumerate(sorted(by_dem.items())):
        c = colours[k % len(colours)]
        nf = sorted(fields)
        ms = [sum(float(r["sweep_ms"]) for r in fields[f]) / len(fields[f]) for f in nf]
        worst = [min(float(r["iou_min"]) for r in fields[f]) for f in nf]
        exact_ms = sum(float(r["exact_ms"]) for f in nf for r in fields[f]) / sum(len(fields[f]) for f in nf)
        ax1.plot(ms, worst, "o-", color=c, label=dem)
        for x, y, f in zip(ms, worst, nf):
            ax1.annotate(f"near {f:g}", (x, y), textcoords="offset points", xytext=(4, -10), fontsize=7, color=c)
        ax1.plot([exact_ms], [1.0], "s", color=c, mfc="none")
        for j, f in enumerate(nf):
            el = [float(r["elevation_deg"]) for r in fields[f]]
            iou = [float(r["iou_mean"]) for r in fields[f]]
            ax2.plot(el, iou, ["s:", "^--", "o-"][j % 3], color=c, ms=4, label=f"{dem}, near {f:g}")
    ax1.axhline(0.99, color="grey", lw=0.8, ls="--")
    ax1.set_xscale("log")
    ax1.set_xlabel("ms per 500x500 frame, 2 threads (squares: the exact path, IoU 1 by definition)")
    ax1.set_ylabel("worst shadow-mask IoU vs exact (70 suns)")
    ax1.set_title("Sun sweep: cost against its worst mask error", fontsize=10)
    ax1.legend(fontsize=7, loc="lower right")
    ax2.set_xscale("log")
    ax2.set_xlabel("sun elevation (degrees)")
    ax2.set_ylabel("shadow-mask IoU vs exact, mean over 10 azimuths")
    ax2.set_title("By sun elevation and near-field length (texels)", fontsize=10)
    ax2.legend(fontsize=6, ncol=2, loc="lower right")
    fig.tight_layout()
    out = sys.argv[2].rstrip("/") + "/sun_sweep.png"
    fig.savefig(out, dpi=90)
    print("wrote", out)


if __name__ == "__main__":
    main()
