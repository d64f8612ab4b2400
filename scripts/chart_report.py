#!/usr/bin/env python3
"""Charts of `terrashade bench report` (docs/accuracy.md): error against time per knob.

Input: the report CSV (command,knob,value,is_default,seconds,error,error_metric,dem).
Output: OUT_DIR/report_<command>_<metric>.png, one panel per (command, error metric, DEM) with
seconds: error against time (log-log), one curve per knob through its values, the Pareto front
(no other setting is both faster and more accurate) as a dashed step line, the defaults
circled; and OUT_DIR/report_error_only.png for the knobs that do not change the time (the log
epsilons): error against the knob's value. Prints each panel's Pareto front.
Usage: chart_report.py CSV OUT_DIR
"""
import csv
import math
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def number(text):
    try:
        v = float(text)
    except ValueError:
        return math.nan
    return v


def sort_key(value):
    v = number(value)
    return (0, v, "") if not math.isnan(v) else (1, 0.0, value)


def pareto(points):
    """Points (t, e, label) that no other point beats on both time and error."""
    front = []
    best = math.inf
    for t, e, label in sorted(points, key=lambda p: (p[0], p[1])):
        if e < best:
            front.append((t, e, label))
            best = e
    return front


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: chart_report.py CSV OUT_DIR")
    rows = list(csv.DictReader(open(sys.argv[1])))
    if not rows:
        sys.exit("chart_report.py: no rows in " + sys.argv[1])
    out_dir = sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    timed = defaultdict(lambda: defaultdict(list))  # (command, metric) -> dem -> rows
    untimed = defaultdict(list)  # (command, knob, metric) -> rows
    for r in rows:
        r["t"], r["e"] = number(r["seconds"]), number(r["error"])
        if math.isnan(r["e"]):
            continue
        if math.isnan(r["t"]):
            untimed[(r["command"], r["knob"], r["error_metric"])].append(r)
        else:
            timed[(r["command"], r["error_metric"])][r["dem"]].append(r)

    for (command, metric), by_dem in sorted(timed.items()):
        dems = sorted(by_dem)
        fig, axes = plt.subplots(1, len(dems), figsize=(6.5 * len(dems), 4.8), squeeze=False)
        for ax, dem in zip(axes[0], dems):
            by_knob = defaultdict(list)
            for r in by_dem[dem]:
                by_knob[r["knob"]].append(r)
            points = []
            palette = plt.get_cmap("tab10").colors
            # An error of 0 (the reference setting itself, or settings equal to it) cannot sit on a
            # log axis: it is drawn a factor 3 below the smallest non-zero error, marked "=0".
            positive = [r["e"] for r in by_dem[dem] if r["e"] > 0]
            # Without any non-zero error (settings all equal to the reference) the axis is linear.
            zero_at = min(positive) / 3 if positive else 0.0
            for k, (knob, rs) in enumerate(sorted(by_knob.items())):
                rs.sort(key=lambda r: sort_key(r["value"]))
                ts = [max(r["t"], 1e-9) for r in rs]
                es = [r["e"] if r["e"] > 0 else zero_at for r in rs]
                colour = palette[k % len(palette)]
                ax.plot(ts, es, "o-", ms=4, lw=1.2, label=knob, color=colour)
                for r, t, e in zip(rs, ts, es):
                    text = r["value"] + (" (=0)" if r["e"] <= 0 else "")
                    ax.annotate(text, (t, e), fontsize=7, xytext=(3, 3), textcoords="offset points")
                    points.append((t, e, knob + "=" + r["value"]))
                    if r["is_default"] == "1":
                        ax.plot([t], [e], "o", ms=13, mfc="none", mec=colour, mew=1.8)
            front = pareto(points)
            ax.step([p[0] for p in front], [p[1] for p in front], "k--", where="post", lw=1, alpha=0.6,
                    label="Pareto front")
            times = [max(r["t"], 1e-9) for r in by_dem[dem]]
            # Times within a factor 10 read better on a linear axis (log ticks would crowd it).
            ax.set_xscale("log" if max(times) > 10 * min(times) else "linear")
            ax.set_yscale("log" if positive else "linear")
            if not positive:
                ax.set_ylim(-0.5, 1.0)
            ax.set_xlabel("seconds")
            ax.set_ylabel(metric)
            ax.set_title(f"{command}: {dem}", fontsize=10)
            ax.grid(True, which="both", alpha=0.25)
            ax.legend(fontsize=7)
            print(f"{command} / {metric} / {dem}: Pareto front " +
                  ", ".join(f"{label} ({t:.3g} s, {e:.3g})" for t, e, label in front))
        fig.suptitle("error against time per knob (defaults circled)", fontsize=11)
        fig.tight_layout()
        name = f"report_{command}_{metric}".replace("-", "_").replace("/", "_")
        fig.savefig(os.path.join(out_dir, name + ".png"), dpi=110)
        plt.close(fig)

    if untimed:
        keys = sorted(untimed)
        fig, axes = plt.subplots(1, len(keys), figsize=(5.5 * len(keys), 4.2), squeeze=False)
        for ax, key in zip(axes[0], keys):
            rs = sorted(untimed[key], key=lambda r: number(r["value"]))
            xs = [number(r["value"]) for r in rs]
            es = [r["e"] for r in rs]
            ax.plot(xs, es, "o-", ms=4)
            for r, x, e in zip(rs, xs, es):
                if r["is_default"] == "1":
                    ax.plot([x], [e], "o", ms=13, mfc="none", mec="C3", mew=1.8)
            ax.set_xscale("log")
            ax.set_xlabel(key[1])
            ax.set_ylabel(key[2])
            ax.set_title(f"{key[0]}: {key[1]} (no time cost)", fontsize=10)
            ax.grid(True, which="both", alpha=0.25)
        fig.tight_layout()
        fig.savefig(os.path.join(out_dir, "report_error_only.png"), dpi=110)
        plt.close(fig)


if __name__ == "__main__":
    main()
