#!/usr/bin/env bash
# terrashade against Blender Cycles on a held-out DEM (docs/accuracy.md, "Against Blender Cycles"):
# the Anatolia SRTM3 tile reprojected to a local transverse Mercator at 90 m (scale factor 1 at
# the centre, so metres on the grid are metres on the ground), a 160 x 160 crop with 1989 m of
# relief; sun 20 degrees up in the south-east under terrashade's clear sky, and its overcast
# sky; Cycles with 0 bounces (direct light) against terrashade's --bounces 0, and 4 (the
# reference) against terrashade's 0, 1 and 2, and 1 with the log-SH terrain transfer
# (--terrain-transfer log-sh), with the sky's light through SH (--sky-light sh) and with the bounce's sun
# part through SH (--bounce-sun sh); albedo 0.3 and 0.8. Each Cycles case is rendered twice, the second with shadow rays leaving the
# facets themselves, to find the texels where the reference is undecided (scripts/cycles_compare.py).
# Writes docs/charts/cycles_bench.csv (about 30 minutes on 2 cores). CYCLES_WORK=DIR keeps the renders there (scripts/cycles_figure.sh can reuse
# them with the same DIR).
# REUSE_CYCLES=1 with CYCLES_WORK keeps the Cycles renders already there (terrashade's rows only).
# Usage: scripts/cycles_bench.sh [BUILD_DIR] [SAMPLES]
#   BUILD_DIR default build/release; needs its terrashade and sky_equirect_dump
#   SAMPLES   default 2048: at 256, two seeds of the snow overcast case (4 bounces) differ by 0.69%
#             (correlation 0.90), more than terrashade's own error there; at 2048 a render's
#             noise is about a third of that
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build=${1:-$root/build/release}
samples=${2:-2048}
if [ -n "${CYCLES_WORK:-}" ]; then work=$CYCLES_WORK; mkdir -p "$work"; else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
csv="$root/docs/charts/cycles_bench.csv"

# Square metric texels for Cycles' mesh; terrashade reads the same file.
[ -f "$work/anatolia_tm90.tif" ] || "$root/scripts/cycles_held_out_dem.sh" "$work/anatolia_tm90.tif"
gdal_translate -q -srcwin 20 480 160 160 "$work/anatolia_tm90.tif" "$work/crop.tif"

echo "case,sky,sun_elevation,albedo,bounces,terrashade_bounces,terrashade_transfer,terrashade_sky_light,terrashade_bounce_sun,samples,cycles_s,terrashade_s,correlation,relative_rmse,bias,fitted_scale,relative_rmse_after_fit,cast_shadow_texels,cast_shadow_relative_rmse,cast_shadow_bias,undecided_texels,relative_rmse_decided,cast_shadow_relative_rmse_decided" >"$csv"
for albedo in 0.3 0.8; do
  for sky in clear overcast; do
    REUSE_CYCLES=${REUSE_CYCLES:-0} TERRASHADE_BOUNCES=0 "$root/scripts/cycles_reference.sh" "$build" "$work/crop.tif" "$work/out" "$sky" "$albedo" 0 \
      "$samples" 135 20 | tee -a "$csv"
    for ts_bounces in 0 1 2; do  # the same Cycles render for all three (REUSE_CYCLES after the first)
      REUSE_CYCLES=$([ $ts_bounces = 0 ] && echo "${REUSE_CYCLES:-0}" || echo 1) TERRASHADE_BOUNCES=$ts_bounces \
        "$root/scripts/cycles_reference.sh" "$build" "$work/crop.tif" "$work/out" "$sky" "$albedo" 4 "$samples" \
        135 20 | tee -a "$csv"
    done
    REUSE_CYCLES=1 TERRASHADE_BOUNCES=1 TERRASHADE_TRANSFER=log-sh TERRASHADE_SKY_LIGHT=sh \
      "$root/scripts/cycles_reference.sh" "$build" "$work/crop.tif" "$work/out" "$sky" "$albedo" 4 "$samples" \
      135 20 | tee -a "$csv"
    REUSE_CYCLES=1 TERRASHADE_BOUNCES=1 TERRASHADE_SKY_LIGHT=sh \
      "$root/scripts/cycles_reference.sh" "$build" "$work/crop.tif" "$work/out" "$sky" "$albedo" 4 "$samples" \
      135 20 | tee -a "$csv"
    REUSE_CYCLES=1 TERRASHADE_BOUNCES=1 TERRASHADE_BOUNCE_SUN=sh \
      "$root/scripts/cycles_reference.sh" "$build" "$work/crop.tif" "$work/out" "$sky" "$albedo" 4 "$samples" \
      135 20 | tee -a "$csv"
  done
done
# The flat check: a level 24 x 24 plane, where terrashade's visibility is trivially open and
# Cycles' units can be checked by hand (sun albedo E sin h / pi, sky albedo E_h / pi).
gdal_create -q -outsize 24 24 -bands 1 -ot Float32 -burn 1000 -a_ullr 0 0 2160 -2160 \
  -a_srs '+proj=tmerc +lat_0=39.5833333 +lon_0=40.4166667 +k=1 +datum=WGS84 +units=m' "$work/flat.tif"
for albedo in 0.3 0.8; do
  for sky in clear overcast; do
    REUSE_CYCLES=${REUSE_CYCLES:-0} TERRASHADE_BOUNCES=0 "$root/scripts/cycles_reference.sh" "$build" "$work/flat.tif" "$work/flat" "$sky" "$albedo" 0 \
      "$samples" 135 20 |
      sed 's/^/flat_/' | tee -a "$csv"
  done
done
echo "wrote $csv"
