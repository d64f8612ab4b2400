#!/usr/bin/python3
"""Charts for docs/visibility.md from `terrashade bench visibility` CSVs.

usage: chart_visibility.py vis_bench.csv [vis_saga.csv] OUT_DIR
writes OUT_DIR/vis_error_vs_time.png, vis_svf_vs_directions.png, vis_horizon_error.png,
vis_table.md (the table in docs/visibility.md) and, with the SAGA CSV, vis_saga.png.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import NullFormatter  # noqa: E402

GOAL_SVF_RMSE = 0.0015


def load(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            if k in ("dem", "method", "variant"):
                continue
            r[k] = float(v) if v not in ("", None) else math.nan
    return rows


def label(r):
    if r["method"] == "exact":
        near, lines = r["variant"].split(":")
        return f"exact near={near} lines={lines}"
    if r["method"] == "pyramid":
        return f"pyramid {r['variant']}"
    return r["method"]


def series(rows, dem):
    out = {}
    for r in rows:
        if r["dem"] != dem or r["method"] == "reference" or r["variant"] in ("full-dem", "saga", "saga-formula"):
            continue
        out.setdefault(label(r), []).append(r)
    for v in out.values():
        v.sort(key=lambda r: r["directions"])
    return out


COLOURS = {"exact near=0 lines=1": "tab:orange", "exact near=1 lines=1": "tab:olive",
           "exact near=2 lines=1": "tab:blue", "exact near=2 lines=2": "tab:cyan", "exact near=4 lines=1": "tab:purple",
           "pyramid fast": "tab:pink", "pyramid balanced": "tab:red", "pyramid fine": "tab:brown"}


def style(name):
    if name in COLOURS:
        return dict(marker="o" if name.startswith("exact") else "s",
                    linestyle="-" if name.startswith("exact") else "--", color=COLOURS[name])
    if name.startswith("exact"):
        return dict(marker="o", linestyle="-")
    if name.startswith("pyramid"):
        return dict(marker="s", linestyle="--")
    return dict(marker="^", linestyle=":", color="black")


def grid_of(n):
    """Panels for n DEMs plus one for the legend."""
    cols = min(3, n + 1)
    return (n + 1 + cols - 1) // cols, cols


def legend_in_spare(fig, axes, n_used):
    handles, labels = axes.flat[0].get_legend_handles_labels()
    spare = list(axes.flat)[n_used:]
    for ax in spare:
        ax.axis("off")
    if spare:
        spare[0].legend(handles, labels, loc="center", fontsize=7)
    else:
        fig.legend(handles, labels, loc="lower right", fontsize=6)


def error_vs_time(rows, dems, out):
    nr, nc = grid_of(len(dems))
    fig, axes = plt.subplots(nr, nc, figsize=(4.2 * nc, 3.4 * nr), squeeze=False)
    for ax, dem in zip(axes.flat, dems):
        for name, rs in sorted(series(rows, dem).items()):
            ax.loglog([r["time_ms"] for r in rs], [r["svf_rmse"] for r in rs], label=name, markersize=3,
                      linewidth=1, **style(name))
        ax.axhline(GOAL_SVF_RMSE, color="red", linewidth=0.8, linestyle="-.")
        ax.set_title(dem, fontsize=8)
        ax.set_xlabel("time per window (ms)", fontsize=7)
        ax.set_ylabel("svf RMSE vs reference", fontsize=7)
        ax.tick_params(labelsize=6)
    legend_in_spare(fig, axes, len(dems))
    fig.suptitle("svf error vs time (points: D = 8, 16, 32, 64; red: goal 0.0015)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "vis_error_vs_time.png"), dpi=90)
    plt.close(fig)


def svf_vs_directions(rows, dems, out):
    keep = ("exact near=2 lines=1", "exact near=0 lines=1", "pyramid balanced", "raymarch")
    nr, nc = grid_of(len(dems))
    fig, axes = plt.subplots(nr, nc, figsize=(4.2 * nc, 3.4 * nr), squeeze=False)
    for ax, dem in zip(axes.flat, dems):
        s = series(rows, dem)
        for name in keep:
            if name not in s:
                continue
            rs = s[name]
            d = [r["directions"] for r in rs]
            ax.loglog(d, [r["svf_rmse"] for r in rs], label=name + " (RMSE)", markersize=3, linewidth=1, **style(name))
            ax.loglog(d, [r["svf_p99"] for r in rs], label=name + " (p99)", markersize=2, linewidth=0.6, alpha=0.5,
                      **style(name))
        ax.axhline(GOAL_SVF_RMSE, color="red", linewidth=0.8, linestyle="-.")
        ax.set_xticks([8, 16, 32, 64])
        ax.set_xticklabels(["8", "16", "32", "64"])
        ax.xaxis.set_minor_formatter(NullFormatter())
        ax.set_title(dem, fontsize=8)
        ax.set_xlabel("azimuths D", fontsize=7)
        ax.set_ylabel("svf |error|", fontsize=7)
        ax.tick_params(labelsize=6)
    legend_in_spare(fig, axes, len(dems))
    fig.suptitle("svf RMSE and 99th percentile vs azimuth count", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "vis_svf_vs_directions.png"), dpi=90)
    plt.close(fig)


def horizon_error(rows, dems, out):
    names = sorted({label(r) for r in rows if r["method"] in ("exact", "pyramid") and r["directions"] == 32
                    and r["variant"] not in ("full-dem", "saga-formula")})
    fig, ax = plt.subplots(figsize=(8, 3.6))
    width = 0.8 / max(1, len(names))
    for i, name in enumerate(names):
        vals = []
        for dem in dems:
            rs = [r for r in series(rows, dem).get(name, []) if r["directions"] == 32]
            vals.append(rs[0]["horizon_rmse_deg"] if rs else math.nan)
        ax.bar([k + i * width for k in range(len(dems))], vals, width, label=name)
    ax.set_xticks([k + 0.4 - width / 2 for k in range(len(dems))])
    ax.set_xticklabels([d.split(".")[0][:18] for d in dems], fontsize=7)
    ax.set_ylabel("horizon RMSE (degrees), D = 32", fontsize=8)
    ax.legend(fontsize=6, ncol=2)
    ax.set_title("horizon-angle error against the raymarch reference", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "vis_horizon_error.png"), dpi=90)
    plt.close(fig)


def saga_chart(rows, out):
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    groups = {}
    for r in rows:
        if r["variant"] in ("saga", "saga-formula"):
            groups.setdefault(r["method"] + (" (terrashade)" if r["variant"] == "saga-formula" else ""), []).append(r)
    for name, rs in sorted(groups.items()):
        rs.sort(key=lambda r: r["directions"])
        st = dict(marker="o", linestyle="-") if "terrashade" in name else dict(marker="x", linestyle="--")
        for ax, key in zip(axes, ("saga_svf_rmse", "saga_visible_rmse")):
            ax.loglog([r["time_ms"] for r in rs], [r[key] for r in rs], label=name, **st)
            for r in rs:
                ax.annotate(str(int(r["directions"])), (r["time_ms"], r[key]), fontsize=6)
    for ax, title in zip(axes, ("SAGA 'Sky View Factor' (tilted receiver)", "SAGA 'Visible Sky' (angle-linear)")):
        ax.set_title(title, fontsize=8)
        ax.set_xlabel("wall time (ms), same run", fontsize=7)
        ax.set_ylabel("RMSE vs 128-azimuth raymarch, same formula", fontsize=7)
        ax.tick_params(labelsize=6)
        ax.legend(fontsize=6)
    fig.suptitle("terrashade exact vs saga_cmd ta_lighting 3 on a projected DEM (labels: sectors D)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "vis_saga.png"), dpi=90)
    plt.close(fig)


def markdown_table(rows, dems):
    """Per DEM and method: svf RMSE at D = 8..64, and at D = 32 the p99, horizon rms, time."""
    lines = ["| DEM | method | svf RMSE D=8 | 16 | 32 | 64 | svf p99 (32) | horizon rms deg (32) | ms (32) |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for dem in dems:
        for name, rs in sorted(series(rows, dem).items()):
            by_d = {int(r["directions"]): r for r in rs}
            r32 = by_d.get(32)
            cells = [f"{by_d[d]['svf_rmse']:.5f}" if d in by_d else "" for d in (8, 16, 32, 64)]
            lines.append(f"| {dem} | {name} | " + " | ".join(cells) + " | " +
                         (f"{r32['svf_p99']:.4f} | {r32['horizon_rmse_deg']:.2f} | {r32['time_ms']:.0f} |" if r32 else "| | |"))
        full = [r for r in rows if r["dem"] == dem and r["variant"] == "full-dem"]
        for r in full:
            lines.append(f"| {dem} ({int(r['width'])}x{int(r['height'])}, whole) | {r['method']} D={int(r['directions'])} "
                         f"| | | | | | | {r['time_ms']:.0f} |")
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    out = argv[-1]
    rows = load(argv[1])
    dems = []
    for r in rows:
        if r["dem"] not in dems and r["method"] == "reference":
            dems.append(r["dem"])
    error_vs_time(rows, dems, out)
    svf_vs_directions(rows, dems, out)
    horizon_error(rows, dems, out)
    with open(os.path.join(out, "vis_table.md"), "w") as f:
        f.write(markdown_table(rows, dems))
    if len(argv) > 3 and os.path.exists(argv[2]):
        saga_chart(load(argv[2]), out)


if __name__ == "__main__":
    main(sys.argv)
