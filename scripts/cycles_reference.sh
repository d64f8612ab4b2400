#!/usr/bin/env bash
# One case of terrashade against Blender Cycles on the same crop, same sun, same sky, grey
# Lambert terrain (docs/accuracy.md, "Against Blender Cycles"). Prints one CSV row:
#   case,sky,sun_elevation,albedo,bounces,terrashade_bounces,terrashade_transfer,terrashade_sky_light,terrashade_bounce_sun,samples,cycles_s,terrashade_s,correlation,relative_rmse,bias,fitted_scale,relative_rmse_after_fit,cast_shadow_texels,cast_shadow_relative_rmse,cast_shadow_bias,undecided_texels,relative_rmse_decided,cast_shadow_relative_rmse_decided
# (cast_shadow_*: the texels in the terrain's cast shadow from the sun, facing it, on their own;
# *_decided: without the texels where Cycles itself is undecided, which a second Cycles render
# with shadow rays leaving the facets themselves finds, --terminator-offset 0; scripts/cycles_compare.py)
# Usage: scripts/cycles_reference.sh BUILD_DIR CROP.tif OUT_DIR SKY ALBEDO BOUNCES SAMPLES [AZIMUTH ELEVATION]
#   AZIMUTH    the sun's, clockwise from the crop's grid north (Cycles' scene is the grid; terrashade
#              takes true azimuths, so it gets AZIMUTH less where true north lies on the grid, from
#              terrashade info)
#   BUILD_DIR  a build with terrashade and tests/light/sky_equirect_dump (ninja terrashade sky_equirect_dump)
#   CROP.tif   a DEM crop in a projected CRS with square texels (scripts/cycles_bench.sh makes one)
#   SKY        clear | overcast (terrashade's models; their ground below the horizon gets ALBEDO)
# Needs blender (scripts/setup_reference.sh), oiiotool (openimageio-tools) and python3-gdal.
# Units match exactly: Cycles' world is terrashade's own sky radiance (kcd/m^2, dumped per
# direction), its sun lamp terrashade's sun irradiance; terrashade renders grey:ALBEDO. No fitted
# factor. Environment: TERRASHADE_BOUNCES, terrashade's --bounces (default 1); TERRASHADE_TRANSFER,
# its --terrain-transfer (default exact); TERRASHADE_SKY_LIGHT, its --sky-light (default horizons);
# TERRASHADE_BOUNCE_SUN, its --bounce-sun (default gather); TERRASHADE_ARGS,
# more options for terrashade; REUSE_CYCLES=1 keeps the Cycles renders already in OUT_DIR (the same
# case: same tag); UNDECIDED=0 skips the second Cycles render (the *_decided columns stay empty).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
[ $# -ge 7 ] || { sed -n 2,13p "$0"; exit 2; }
build=$1 crop=$2 out=$3 sky=$4 albedo=$5 bounces=$6 samples=$7 azimuth=${8:-135} elevation=${9:-20}
threads=${THREADS:-2}
mkdir -p "$out"
# SKY may carry its own parameters (physical:aureole=0): the albedo joins them.
tag="$(echo "$sky" | tr ':,=' '___')_e${elevation}_a${albedo}_b${bounces}"
case "$sky" in *:*) spec="$sky,albedo=$albedo" ;; *) spec="$sky:albedo=$albedo" ;; esac

"$build/tests/light/sky_equirect_dump" "$spec" "$azimuth" "$elevation" 1024 "$out/sky_$tag" >/dev/null

cycles_s=0
if [ "${REUSE_CYCLES:-0}" = 1 ] && [ -f "$out/cycles_$tag.tif" ]; then
  cycles_s=$(cat "$out/cycles_$tag.seconds" 2>/dev/null || echo 0)  # the time of the render reused
else
log=$(blender -b --factory-startup -t "$threads" -P "$root/scripts/cycles_reference.py" -- "$crop" "$out/cycles_$tag.tif" \
  --sky map --sky-map "$out/sky_$tag" --albedo "$albedo" --bounces "$bounces" --samples "$samples" \
  --threads "$threads" 2>&1) || { echo "$log" >&2; exit 1; }
cycles_s=$(echo "$log" | grep -o '"cycles_seconds": [0-9.]*' | awk '{print $2}')
echo "$cycles_s" >"$out/cycles_$tag.seconds"
fi
alternative=()
if [ "${UNDECIDED:-1}" = 1 ]; then
  alt="$out/cycles_${tag}_facets.tif"
  if [ "${REUSE_CYCLES:-0}" = 1 ] && [ -f "$alt" ]; then :; else
    log=$(blender -b --factory-startup -t "$threads" -P "$root/scripts/cycles_reference.py" -- "$crop" "$alt" \
      --sky map --sky-map "$out/sky_$tag" --albedo "$albedo" --bounces "$bounces" --samples "$samples" \
      --threads "$threads" --terminator-offset 0 2>&1) || { echo "$log" >&2; exit 1; }
  fi
  alternative=(--alternative "$alt")
fi

# terrashade's --sun-azimuth is from true north: the grid's AZIMUTH less the meridian convergence.
north=$("$build/app/terrashade" info "$crop" | awk '$1 == "true" && $2 == "north" {print $3}')
true_azimuth=$(echo "$azimuth - (${north:-0})" | bc -l)
t0=$(date +%s.%N)
"$build/app/terrashade" render "$crop" --colors "grey:$albedo" --bounces "${TERRASHADE_BOUNCES:-1}" \
  --terrain-transfer "${TERRASHADE_TRANSFER:-exact}" --sky-light "${TERRASHADE_SKY_LIGHT:-horizons}" \
  --bounce-sun "${TERRASHADE_BOUNCE_SUN:-gather}" ${TERRASHADE_ARGS:-} --sky "$spec" --sun-azimuth "$true_azimuth" \
  --sun-elevation "$elevation" --no-curvature --cpu --threads "$threads" -o "$out/terrashade_$tag.exr" >/dev/null
t1=$(date +%s.%N)
terrashade_s=$(echo "$t1 - $t0" | bc)
oiiotool "$out/terrashade_$tag.exr" -d float -o "$out/terrashade_$tag.tif"

json=$(/usr/bin/python3 "$root/scripts/cycles_compare.py" "$out/cycles_$tag.tif" "$out/terrashade_$tag.tif" \
  --dem "$crop" --sun-azimuth "$azimuth" --sun-elevation "$elevation" "${alternative[@]}")
field() { echo "$json" | /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin).get('$1', ''))"; }
echo "$tag,$sky,$elevation,$albedo,$bounces,${TERRASHADE_BOUNCES:-1},${TERRASHADE_TRANSFER:-exact},${TERRASHADE_SKY_LIGHT:-horizons},${TERRASHADE_BOUNCE_SUN:-gather},$samples,$cycles_s,$(printf %.2f "$terrashade_s"),$(field correlation),$(field relative_rmse),$(field bias),$(field fitted_scale),$(field relative_rmse_after_fit),$(field cast_shadow_texels),$(field cast_shadow_relative_rmse),$(field cast_shadow_bias),$(field undecided_texels),$(field relative_rmse_decided),$(field cast_shadow_relative_rmse_decided)"
