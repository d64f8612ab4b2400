"""The sky's light, error against per-frame time (scripts/sky_light_chart.sh makes the CSV)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

rows = list(csv.DictReader(open(sys.argv[1])))
fig, ax = plt.subplots(figsize=(6.4, 4.0), dpi=100)
for sky, colour in (("clear", "tab:orange"), ("preetham", "tab:olive"), ("overcast", "tab:blue")):
    xs = [float(r["frame_ms"]) for r in rows]
    ys = [100 * float(r[sky + "_rel_rmse"]) for r in rows]
    ax.plot(xs[1:], ys[1:], "o-", color=colour, label=f"{sky}: horizons, 4/8/16/32 sectors")
    ax.plot(xs[:1], ys[:1], "s", color=colour, markerfacecolor="white", label=f"{sky}: sh")
    for r, x, y in zip(rows[1:], xs[1:], ys[1:]):
        if sky == "clear":
            ax.annotate(r["sectors"], (x, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
ax.set_xlabel("relight, per frame (ms, 500 x 500 texels, CPU, 2 threads)")
ax.set_ylabel("relative RMSE against Cycles (%)")
ax.set_title("The sky's light: SH against the horizons' sectors")
ax.set_ylim(bottom=0)
ax.grid(alpha=0.3)
ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(sys.argv[2])
