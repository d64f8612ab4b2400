#!/usr/bin/python3
"""Charts for docs/accuracy.md from `terrashade bench render --csv` (renderer vs the ray-traced
reference, issue 6).

usage: chart_render.py render_bench.csv OUT_DIR
writes OUT_DIR/render_accuracy.png (relative RMSE and p99 of the map radiance per DEM and sun),
OUT_DIR/render_shadow_iou.png (sun-shadow mask IoU against the 0.98 goal) and
OUT_DIR/render_table.md (the table in docs/accuracy.md).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

GOAL_IOU = 0.98
SUNS = ["morning", "noon", "evening"]
COLOURS = {"morning": "#e69f00", "noon": "#0072b2", "evening": "#cc79a7"}


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            if k in ("dem", "label", "time_utc"):
                continue
            r[k] = float(v) if v not in ("", None) else math.nan
    return rows


def short(dem):
    for suffix in (".hgt.zip", ".hgt", ".tif"):
        if dem.endswith(suffix):
            dem = dem[: -len(suffix)]
    return dem.replace("copernicus_", "").replace("_500px", "").replace("_1000px", "")


def grouped(rows):
    dems = []
    for r in rows:
        if r["dem"] not in dems:
            dems.append(r["dem"])
    labels = [s for s in SUNS if any(r["label"] == s for r in rows)]
    labels += sorted({r["label"] for r in rows} - set(labels))
    return dems, labels


def bar_chart(rows, out, keys, ylabel, title, goal=None, log=False):
    dems, labels = grouped(rows)
    fig, axes = plt.subplots(1, len(keys), figsize=(4.6 * len(keys), 3.4), squeeze=False)
    width = 0.8 / max(1, len(labels))
    for ax, (key, name) in zip(axes[0], keys):
        for j, lab in enumerate(labels):
            xs, ys = [], []
            for i, d in enumerate(dems):
                for r in rows:
                    if r["dem"] == d and r["label"] == lab:
                        xs.append(i + (j - (len(labels) - 1) / 2) * width)
                        ys.append(r[key])
            ax.bar(xs, ys, width, label=lab, color=COLOURS.get(lab))
        if goal is not None:
            ax.axhline(goal, color="k", lw=0.8, ls="--", label=f"goal {goal}")
        ax.set_xticks(range(len(dems)))
        ax.set_xticklabels([short(d) for d in dems], rotation=20, ha="right", fontsize=8)
        ax.set_title(name, fontsize=9)
        ax.set_ylabel(ylabel, fontsize=8)
        if log:
            ax.set_yscale("log")
        ax.grid(axis="y", alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def iou_chart(rows, out):
    dems, labels = grouped(rows)
    fig, ax = plt.subplots(figsize=(6.0, 3.2))
    width = 0.8 / max(1, len(labels))
    lo = 1.0
    for j, lab in enumerate(labels):
        xs, ys = [], []
        for i, d in enumerate(dems):
            for r in rows:
                if r["dem"] == d and r["label"] == lab:
                    xs.append(i + (j - (len(labels) - 1) / 2) * width)
                    ys.append(r["mask_iou"])
                    lo = min(lo, r["mask_iou"])
        ax.bar(xs, ys, width, label=lab, color=COLOURS.get(lab))
    ax.axhline(GOAL_IOU, color="k", lw=0.8, ls="--", label=f"goal {GOAL_IOU}")
    ax.set_ylim(min(0.95, lo - 0.005), 1.0005)
    ax.set_xticks(range(len(dems)))
    ax.set_xticklabels([short(d) for d in dems], rotation=20, ha="right", fontsize=8)
    ax.set_ylabel("IoU of shadow masks", fontsize=8)
    ax.set_title("Sun-shadow mask (visible fraction < 0.5): renderer vs raymarched reference", fontsize=9)
    ax.legend(fontsize=7, loc="lower right")
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def pct(v, digits=2, sign=""):
    return "-" if math.isnan(v) else f"{100 * v:{sign}.{digits}f}%"


def table(rows, out):
    lines = [
        "| DEM | sun | azimuth | elevation | texels | rel. RMSE | p99 rel. error | bias | RMSE sunlit | RMSE shadow "
        "| shadowed | mask IoU | masks differ | frame ms | sun vis. ms |",
        "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |",
    ]
    for r in rows:
        lines.append(
            f"| {short(r['dem'])} | {r['label']} | {r['sun_azimuth_deg']:.1f} | {r['sun_elevation_deg']:.1f} "
            f"| {int(r['samples'])} | {pct(r['rel_rmse'])} | {pct(r['rel_p99'])} "
            f"| {pct(r['rel_bias'], sign='+')} | {pct(r['sunlit_rel_rmse'])} | {pct(r['shadow_rel_rmse'])} "
            f"| {pct(r.get('shadow_share', math.nan), 1)} | {r['mask_iou']:.4f} | {pct(r['mask_disagree'], 3)} "
            f"| {r['frame_ms']:.0f} | {r['sun_visibility_ms']:.0f} |"
        )
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rows = load(sys.argv[1])
    out = sys.argv[2]
    os.makedirs(out, exist_ok=True)
    bar_chart(
        rows,
        os.path.join(out, "render_accuracy.png"),
        [("rel_rmse", "relative RMSE of luminance"), ("rel_p99", "99th percentile of relative error")],
        "relative to the reference",
        "Map radiance: renderer (order-4 log-SH + exact sun) vs ray-traced reference",
        log=True,
    )
    iou_chart(rows, os.path.join(out, "render_shadow_iou.png"))
    table(rows, os.path.join(out, "render_table.md"))


if __name__ == "__main__":
    main()
