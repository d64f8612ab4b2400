#!/usr/bin/python3
"""Charts of the sky models for docs/lighting.md.

Runs the sky_chart_csv program (built in BUILD_DIR/tests/light) to print the data, then draws
  docs/charts/sky_profile.png : luminance along the sun's vertical, clear sky at several
                                turbidities and the CIE overcast sky (sun 30 degrees up)
  docs/charts/sky_sh.png      : the same profile (on the whole circle, ground included) beside
                                its order-4 SH reconstruction
  docs/charts/sky_low_sun.png : CIE x and luminance along the sun's vertical with the sun 3 and
                                20 degrees up: the physical sky, Preetham's, and Blender's Nishita
                                sky (tests/light/reference/nishita_sky_default.csv)
Usage: /usr/bin/python3 scripts/chart_sky.py [BUILD_DIR]   (default: build/release)
"""
import csv
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "release")
    exe = os.path.join(build, "tests", "light", "sky_chart_csv")
    out_dir = os.path.join(ROOT, "docs", "charts")
    os.makedirs(out_dir, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([exe, tmp], check=True)
        profile = read(os.path.join(tmp, "sky_profile.csv"))
        sh = read(os.path.join(tmp, "sky_sh.csv"))
        low = read(os.path.join(tmp, "sky_low_sun.csv"))
    with open(os.path.join(ROOT, "tests", "light", "reference", "nishita_sky_default.csv")) as f:
        nishita = list(csv.DictReader(line for line in f if not line.startswith("#")))

    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)
    for t in sorted({r["turbidity"] for r in profile if r["sky"] == "clear"}, key=float):
        rows = [r for r in profile if r["sky"] == "clear" and r["turbidity"] == t]
        ax.plot([float(r["signed_zenith_deg"]) for r in rows], [float(r["luminance"]) for r in rows],
                label=f"clear, T = {float(t):g}")
    rows = [r for r in profile if r["sky"] == "physical"]
    ax.plot([float(r["signed_zenith_deg"]) for r in rows], [float(r["luminance"]) for r in rows], "C1:",
            label="physical, T = 3")
    rows = [r for r in profile if r["sky"] == "overcast"]
    ax.plot([float(r["signed_zenith_deg"]) for r in rows], [float(r["luminance"]) for r in rows], "k--",
            label="CIE overcast")
    ax.axvline(60.0, color="orange", lw=0.8, ls=":")
    ax.text(61, ax.get_ylim()[1] * 0.9, "sun", color="orange", fontsize=8)
    ax.set_yscale("log")
    ax.set_xlabel("zenith angle in the sun's vertical plane (deg, + towards the sun)")
    ax.set_ylabel("luminance (kcd/m$^2$)")
    ax.set_title("Sky luminance, sun 30 deg up (clear: Preetham 1999; physical; CIE overcast)", fontsize=10)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "sky_profile.png"))

    fig, ax = plt.subplots(figsize=(6.4, 3.6), dpi=100)
    for name, style in (("clear T=3", "C0"), ("physical T=3", "C2"), ("overcast", "C3")):
        rows = [r for r in sh if r["sky"] == name]
        x = [float(r["signed_zenith_deg"]) for r in rows]
        ax.plot(x, [float(r["true_luminance"]) for r in rows], style, label=f"{name}: model")
        ax.plot(x, [float(r["sh_luminance"]) for r in rows], style, ls="--", label=f"{name}: order-4 SH")
    for h in (-90, 90):
        ax.axvline(h, color="grey", lw=0.8, ls=":")
    ax.set_xlabel("angle from the zenith in the sun's vertical plane (deg; |angle| > 90 = ground)")
    ax.set_ylabel("luminance (kcd/m$^2$)")
    ax.set_title("Sky radiance and its order-4 SH (sun 30 deg up at +60)", fontsize=10)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "sky_sh.png"))
    # Low sun: colour and luminance along the sun's vertical, models and Blender's Nishita sky.
    fig, axes = plt.subplots(2, 2, figsize=(9.6, 6.4), dpi=100, sharex=True)
    styles = {"physical T=3": "C0-", "physical T=3 single scattering": "C0:",
              "single scattering with Blender's dust": "C2-", "Preetham T=3": "C1--"}
    for col, e in enumerate((3.0, 20.0)):
        for name, style in styles.items():
            rows = [r for r in low if r["sky"] == name and float(r["sun_elevation_deg"]) == e]
            z = [float(r["signed_zenith_deg"]) for r in rows]
            axes[0][col].plot(z, [float(r["x"]) for r in rows], style, lw=1.2, label=name)
            axes[1][col].plot(z, [float(r["luminance"]) for r in rows], style, lw=1.2, label=name)
        pts = [r for r in nishita if float(r["sun_elevation_deg"]) == e and float(r["rel_azimuth_deg"]) in (0.0, 180.0)]
        z = [(90.0 - float(r["view_elevation_deg"])) * (1 if float(r["rel_azimuth_deg"]) == 0.0 else -1) for r in pts]
        axes[0][col].plot(z, [float(r["x"]) for r in pts], "k.", label="Blender Nishita (default dust, single scattering)")
        axes[1][col].plot(z, [0.683 * float(r["Y"]) for r in pts], "k.", label="Blender Nishita (default dust)")
        axes[0][col].set_title(f"sun {e:g} deg up (at +{90 - e:g})", fontsize=10)
        axes[1][col].set_yscale("log")
        axes[1][col].set_xlabel("zenith angle in the sun's vertical (deg, + towards the sun)")
        for ax in (axes[0][col], axes[1][col]):
            ax.axvline(90 - e, color="orange", lw=0.8, ls=":")
            ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("CIE x (redder up)")
    axes[1][0].set_ylabel("luminance (kcd/m$^2$)")
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "sky_low_sun.png"))
    print("wrote docs/charts/sky_profile.png, docs/charts/sky_sh.png and docs/charts/sky_low_sun.png")


if __name__ == "__main__":
    main()
