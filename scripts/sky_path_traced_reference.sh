#!/usr/bin/env bash
# Stores the path-traced reference of the physical sky's multiple scattering
# (tests/light/reference/sky_path_traced.csv, read by tests/light/physical_sky_test.cpp):
# tests/light/sky_path_tracer at 450 and 550 nm, turbidity 3, ground albedo 0.2 and 0.8.
# Usage: scripts/sky_path_traced_reference.sh [BUILD_DIR] [PATHS]   (~2 minutes at 100000 paths)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
paths=${2:-100000}
tracer=$build/tests/light/sky_path_tracer
[ -x "$tracer" ] || { echo "sky_path_traced_reference.sh: $tracer not built (cmake --build --preset release)" >&2; exit 1; }
out=tests/light/reference/sky_path_traced.csv
tmp=$(mktemp "$out.XXXXXX")
trap 'rm -f "$tmp" "$tmp".*' EXIT
# One run per wavelength and albedo, two at a time; rows prefixed by wavelength index and albedo.
run() { "$tracer" "$1" 3 "$2" "$paths" | awk -v k="$1" -v a="$2" '/^#/ {print; next} /^sun/ {next} {print k "," a "," $0}' > "$tmp.$1.$2"; }
run 3 0.2 & run 3 0.8 & wait
run 8 0.2 & run 8 0.8 & wait
{
  echo "# Path-traced physical sky (scripts/sky_path_traced_reference.sh, $paths paths per row)."
  echo "# Radiance per unit extraterrestrial irradiance; view_elevation -90 is the sky's horizontal irradiance."
  cat "$tmp".3.0.2 "$tmp".3.0.8 "$tmp".8.0.2 "$tmp".8.0.8 | grep '^#' | sed 's/^# /# run: /'
  echo "wavelength_index,albedo,sun_elevation,view_elevation,azimuth_from_sun,single,total,total_stderr"
  cat "$tmp".3.0.2 "$tmp".3.0.8 "$tmp".8.0.2 "$tmp".8.0.8 | grep -v '^#'
} > "$tmp"
chmod 644 "$tmp"
mv "$tmp" "$out"
echo "wrote $out"
