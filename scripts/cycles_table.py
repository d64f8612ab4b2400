#!/usr/bin/env python3
"""The table of docs/accuracy.md, "Against Blender Cycles", from docs/charts/cycles_bench.csv
(scripts/cycles_bench.sh): one Markdown row per case of the held-out crop (the flat rows are
quoted in the text), the defaults in bold.

    /usr/bin/python3 scripts/cycles_table.py [docs/charts/cycles_bench.csv]
"""
import csv
import sys


def is_default(r):
    return (r["bounces"] == "4" and r["terrashade_bounces"] == "1" and r["terrashade_transfer"] == "exact"
            and r["terrashade_sky_light"] == "horizons" and r["terrashade_bounce_sun"] == "gather")


def percent(r, key, digits=2, sign=False):
    return f"{100 * float(r[key]):{'+' if sign else ''}.{digits}f}%"


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "docs/charts/cycles_bench.csv"
    print("| case | albedo | Cycles bounces | terrashade `--bounces` | `--terrain-transfer` | `--sky-light` "
          "| `--bounce-sun` | correlation | relative RMSE | bias | in cast shadows: relative RMSE (bias) "
          "| without the undecided texels: all / cast shadows |")
    print("| --- | ---: | ---: | ---: | --- | --- | --- | ---: | ---: | ---: | ---: | ---: |")
    for r in csv.DictReader(open(path)):
        if r["case"].startswith("flat"):
            continue
        bold = (lambda s: f"**{s}**") if is_default(r) else (lambda s: s)
        sky = "sun 20 deg + clear sky" if r["sky"] == "clear" else r["sky"]
        bounce_sun = r["terrashade_bounce_sun"] if r["terrashade_bounces"] != "0" else "-"
        cast = f"{percent(r, 'cast_shadow_relative_rmse', 1)} ({percent(r, 'cast_shadow_bias', 1, True)})"
        decided = (f"{percent(r, 'relative_rmse_decided')} / {percent(r, 'cast_shadow_relative_rmse_decided', 1)}"
                   if r["undecided_texels"] not in ("", "0") else "(none undecided)")
        print(f"| {sky} | {r['albedo']} | {r['bounces']} | {bold(r['terrashade_bounces'])} | "
              f"{r['terrashade_transfer']} | {r['terrashade_sky_light']} | {bounce_sun} | "
              f"{float(r['correlation']):.4f} | {bold(percent(r, 'relative_rmse'))} | {percent(r, 'bias', 1, True)} | "
              f"{cast} | {decided} |")


if __name__ == "__main__":
    main()
