#!/usr/bin/env python3
"""Charts of the mesh blockers against the ray-traced triangles (docs/blockers.md).

Input: the CSV of `terrashade bench blockers --csv FILE` (scripts/bench_blockers.sh).
Output: OUT_DIR/blockers_accuracy.png, three panels against the sphere count:
  left:   error of the sky-visibility change the mesh makes (spheres - triangles): RMSE over the
          sky footprint and over the texels either changes by > 0.01, and the largest;
  middle: the sun shadow's IoU with the triangles' shadow, and the RMSE of the visible disc,
          cast by the spheres and (the default) by the triangles where the spheres shadow;
  right:  time of the sky accumulation and of one frame's sun shadow.
Usage: chart_blockers.py CSV OUT_DIR
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: chart_blockers.py CSV OUT_DIR")
    rows = list(csv.DictReader(open(sys.argv[1])))
    if not rows:
        sys.exit("chart_blockers.py: no rows in " + sys.argv[1])
    n = [int(r["spheres"]) for r in rows]
    col = lambda k: [float(r[k]) for r in rows]  # noqa: E731

    fig, (a1, a2, a3) = plt.subplots(1, 3, figsize=(13, 4))
    a1.plot(n, col("sky_rmse"), "o-", label="RMSE, sky footprint")
    a1.plot(n, col("shaded_rmse"), "s-", label="RMSE, texels changed > 0.01")
    a1.plot(n, col("sky_max_error"), "^--", label="largest error")
    a1.set_yscale("log")
    a1.set_ylabel("sky visibility change: spheres - triangles")
    a1.set_title("Sky (cosine-weighted, terrain horizons + mesh)", fontsize=9)
    a2.plot(n, col("sun_iou"), "o-", label="IoU, cast by the spheres")
    a2.plot(n, col("sun_rmse"), "s--", label="RMSE of the visible disc, spheres")
    a2.plot(n, col("triangles_sun_iou"), "o-", label="IoU, cast by the triangles (default)")
    a2.plot(n, col("triangles_sun_rmse"), "s--", label="RMSE of the visible disc, triangles")
    a2.axhline(0.9, color="grey", lw=0.8, ls=":", label="goal IoU 0.9 at 64")
    a2.set_ylim(0, 1.05)
    a2.set_title("Sun shadow on the terrain (shadow: less than half the disc)", fontsize=9)
    a3.plot(n, [1e3 * x for x in col("sky_s")], "o-", label="sky accumulation (footprint)")
    a3.plot(n, [1e3 * x for x in col("sun_s")], "s-", label="sun shadow by the spheres, one frame")
    a3.plot(n, [1e3 * x for x in col("triangles_sun_s")], "^-", label="sun shadow by the triangles, one frame")
    a3.set_yscale("log")
    a3.set_ylabel("ms, 2 threads")
    a3.set_title("Time", fontsize=9)
    for a in (a1, a2, a3):
        a.set_xscale("log", base=2)
        a.set_xticks(n)
        a.set_xticklabels([str(x) for x in n])
        a.set_xlabel("spheres")
        a.grid(alpha=0.3)
        a.legend(fontsize=7, loc="center right" if a is a2 else "best")
    fig.suptitle("Cessna 172 (x200, 600 m above the ground) over the Anatolia crop: spheres vs its 2,535 triangles",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(sys.argv[2] + "/blockers_accuracy.png", dpi=110)


if __name__ == "__main__":
    main()
