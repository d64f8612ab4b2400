#!/usr/bin/python3
"""Charts of the SH exponentiation study for docs/method.md.

Usage (from the repository root, after building):
    build/app/terrashade bench sh --csv sh.csv --eps-csv eps.csv
    build/app/terrashade bench sh --sweep --csv sh_sweep.csv
    /usr/bin/python3 scripts/chart_sh.py sh.csv eps.csv sh_sweep.csv [docs/charts]

Writes sh_exp_error_vs_magnitude.png, sh_exp_error_vs_cost.png and sh_log_epsilon.png.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = ["taylor", "dc_isolation", "optimal_linear", "scaling_squaring", "hybrid"]
COLORS = dict(zip(METHODS, ["#888888", "#1f77b4", "#2ca02c", "#ff7f0e", "#d62728"]))
MARKERS = dict(zip(METHODS, ["x", "o", "s", "^", "D"]))


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                pass
    return rows


def error_vs_magnitude(rows, out):
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for m in METHODS:
        shape = sorted([r for r in rows if r["kind"] == "shape" and r["method"] == m], key=lambda r: r["magnitude"])
        if shape:
            a.loglog([r["magnitude"] for r in shape], [max(r["rms_error"], 1e-7) for r in shape],
                     marker=MARKERS[m], color=COLORS[m], label=m)
        scene = sorted([r for r in rows if r["kind"] == "scene" and r["method"] == m], key=lambda r: r["blockers"])
        if scene:
            b.semilogy([r["blockers"] for r in scene], [max(r["truth_rms_error"], 1e-7) for r in scene],
                       marker=MARKERS[m], color=COLORS[m], label=m)
    exact = sorted([r for r in rows if r["kind"] == "scene" and r["method"] == "hybrid"], key=lambda r: r["blockers"])
    if exact:
        b.semilogy([r["blockers"] for r in exact], [r["exact_truth_rms_error"] for r in exact], "k--",
                   label="exact exp of the order-4 log")
        for r in exact:
            b.annotate("%.0f" % r["magnitude"], (r["blockers"], r["exact_truth_rms_error"]), fontsize=7,
                       textcoords="offset points", xytext=(0, 6), ha="center")
    a.set_xlabel("non-DC magnitude |f_hat| of the log vector (DC = 0)")
    a.set_ylabel("RMS error vs exact exponential")
    a.set_title("Scaled random log shapes")
    a.set_ylim(1e-6, 1e6)
    a.grid(True, which="both", alpha=0.3)
    a.legend(fontsize=8)
    b.set_xscale("symlog", linthresh=1)
    b.set_xlabel("sphere blockers (+ a height field); labels: mean |f_hat|")
    b.set_ylabel("RMS error vs true visibility (order 4)")
    b.set_title("Random scenes, log eps = log 0.001")
    b.set_ylim(1e-3, 1e3)
    b.grid(True, which="both", alpha=0.3)
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def error_vs_cost(rows, out):
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for m in METHODS:
        params = []
        for r in rows:
            if r["method"] == m and r["param"] not in params:
                params.append(r["param"])
        pts_a, pts_b = [], []
        for p in params:
            sel = [r for r in rows if r["method"] == m and r["param"] == p]
            shapes = [r for r in sel if r["kind"] == "shape" and r["magnitude"] <= 4.01]
            scenes = [r for r in sel if r["kind"] == "scene"]
            if shapes:
                pts_a.append((sum(r["ns_per_exp"] for r in shapes) / len(shapes),
                              sum(r["rms_error"] for r in shapes) / len(shapes), p))
            if scenes:
                pts_b.append((sum(r["ns_per_exp"] for r in scenes) / len(scenes),
                              sum(r["truth_rms_error"] for r in scenes) / len(scenes), p))
        for ax, pts in ((a, pts_a), (b, pts_b)):
            if not pts:
                continue
            pts.sort()
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker=MARKERS[m], color=COLORS[m], label=m)
            for x, y, p in pts:
                ax.annotate(p.replace("threshold=", "t=").replace("order=", "n="), (x, y), fontsize=6,
                            textcoords="offset points", xytext=(3, 3))
    a.set_title("Shapes |f_hat| <= 4: error vs exact exponential")
    b.set_title("Scenes 0..500 blockers: error vs true visibility\n(taylor: 1e2..1e13, off the scale)", fontsize=10)
    b.set_ylim(0.1, 2.0)
    for ax in (a, b):
        ax.set_xlabel("ns per exponentiation (one core, float)")
        ax.set_ylabel("mean RMS error")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    plt.close(fig)


def log_epsilon(rows, out, default_eps=0.05):
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    lobes = []
    for r in rows:
        if r["lobe"] not in lobes:
            lobes.append(r["lobe"])
    for lobe in lobes:
        sel = sorted([r for r in rows if r["lobe"] == lobe], key=lambda r: r["eps"])
        eps = [r["eps"] for r in sel]
        if lobe.startswith("vis_"):
            axes[0].loglog(eps, [r["rms_error"] for r in sel], ls="--", lw=1, marker=".",
                           label="scenes, %s blockers vs binary" % lobe[4:])
            continue
        axes[0].loglog(eps, [r["rms_error"] for r in sel], marker="o", label=lobe)
        axes[1].semilogx(eps, [r["albedo"] / r["albedo_true"] for r in sel], marker="o", label=lobe)
        if lobe != "sphere":  # a blocker's visibility below the horizon is 1, not 0
            axes[2].loglog(eps, [max(r["lower_leak"], 1e-6) for r in sel], marker="o", label=lobe)
    axes[0].set_ylabel("RMS error: exp(log lobe) vs projected lobe")
    axes[1].set_ylabel("integral / true integral")
    axes[1].set_title("albedo (sphere: visible solid angle)", fontsize=9)
    axes[1].axhline(1.0, color="k", lw=0.8)
    axes[1].set_ylim(0, 3)
    axes[2].set_ylabel("integral of |reconstruction| below horizon")
    for ax in axes:
        ax.set_xlabel("epsilon (floor of the clamped function)")
        ax.axvline(default_eps, color="k", ls=":", lw=1)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=6 if ax is axes[0] else 8)
    fig.suptitle("log-epsilon trade-off (hybrid exponentiation; dotted: default BRDF eps = %g)" % default_eps)
    fig.tight_layout()
    fig.savefig(out, dpi=80)
    plt.close(fig)


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    out_dir = argv[4] if len(argv) > 4 else "docs/charts"
    os.makedirs(out_dir, exist_ok=True)
    error_vs_magnitude(read(argv[1]), os.path.join(out_dir, "sh_exp_error_vs_magnitude.png"))
    log_epsilon(read(argv[2]), os.path.join(out_dir, "sh_log_epsilon.png"))
    error_vs_cost(read(argv[3]), os.path.join(out_dir, "sh_exp_error_vs_cost.png"))


if __name__ == "__main__":
    main(sys.argv)
