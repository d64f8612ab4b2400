#!/usr/bin/env bash
# The reference positions for tests/web/sun_position_test.mjs: runs terrashade's SPA
# (`terrashade sun --json`, standard atmosphere at the height, Espenak-Meeus delta T) over a fixed
# set of instants and sites and writes tests/web/sun_reference.json, one compact line per case.
#   - 176 cases on a fixed pseudo-random grid: latitudes -70..70, longitudes -170..175, heights
#     0..3000 m, years 1990..2060, any day, any hour (so the sun is often below the horizon);
#   - 32 grazing cases: for a site and a day, the morning instant (to 1 s) where the unrefracted
#     elevation crosses -2, -1.2, -0.5, -0.2, 0, 0.3, 1 or 3 deg, found by bisection with the
#     binary itself (the refraction threshold at -0.83337 deg is avoided on purpose: there the
#     refracted elevation jumps by 0.6 deg and any model's tiny error would flip it).
# Usage: scripts/make_sun_reference.sh path/to/terrashade   (about 1.5 min; deterministic output)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ts=${1:?usage: $0 path/to/terrashade}
out="$root/tests/web/sun_reference.json"

# sun TIME LAT LON H -> "azimuth elevation elevation_unrefracted" from the binary's JSON.
sun() {
  "$ts" sun --time "$1" --lat "$2" --lon "$3" --height-m "$4" --json |
    awk -F'[:,]' '/"azimuth_deg"/ {a=$2} /"elevation_deg"/ {e=$2} /"elevation_unrefracted_deg"/ {u=$2}
                  END {gsub(/ /, "", a); gsub(/ /, "", e); gsub(/ /, "", u); print a, e, u}'
}
iso() { date -u -d "@$1" +%Y-%m-%dT%H:%M:%SZ; }

lines=()
add() {  # TIME LAT LON H AZ EL EL0
  lines+=("{\"time\":\"$1\",\"lat\":$2,\"lon\":$3,\"height_m\":$4,\"azimuth_deg\":$5,\"elevation_deg\":$6,\"elevation_unrefracted_deg\":$7}")
}

# The grid: the Park-Miller generator (fixed seed, exact in awk's doubles) picks each case's coordinates.
while read -r t lat lon h; do
  read -r az el el0 < <(sun "$t" "$lat" "$lon" "$h")
  add "$t" "$lat" "$lon" "$h" "$az" "$el" "$el0"
done < <(awk 'BEGIN {
  s = 12345; m = 2147483647
  split("-70 -63.5 -55 -47.2 -40 -33.9 -25 -18.4 -10 -3.2 0 4.5 12 19.8 27.3 35 41.7 48.9 56 62.4 70", la, " ")
  split("-170 -122.4 -74 -43.2 -8.5 0 2.35 13.4 37.6 77.2 116.4 139.7 151.2 175", lo, " ")
  split("0 120 450 1000 1800 2400 3000", hs, " ")
  for (i = 0; i < 176; i++) {
    s = (16807 * s) % m; y = 1990 + int(s / m * 71)
    s = (16807 * s) % m; mo = 1 + int(s / m * 12)
    s = (16807 * s) % m; d = 1 + int(s / m * 28)
    s = (16807 * s) % m; hr = int(s / m * 24)
    s = (16807 * s) % m; mi = int(s / m * 60)
    s = (16807 * s) % m; sec = int(s / m * 60)
    printf "%04d-%02d-%02dT%02d:%02d:%02dZ %s %s %s\n", y, mo, d, hr, mi, sec, la[1 + i % 21], lo[1 + (i * 5) % 14], hs[1 + (i * 3) % 7]
  }
}')

# Grazing sun: bisection between local solar midnight and noon (the elevation rises between them).
grazing=(
  "1991-03-20 47.37 8.54 500 0" "1995-06-21 -33.9 18.4 0 -0.2" "1999-12-21 60.2 24.9 30 0.3"
  "2003-09-23 0.0 -78.5 2850 -0.5" "2007-01-15 -45.0 170.5 1200 1" "2011-07-04 35.7 139.7 40 -1.2"
  "2015-11-11 -60.0 -65.0 0 3" "2019-05-05 19.4 -99.1 2240 -2" "2023-08-30 52.5 13.4 35 0"
  "2027-02-28 -23.5 -46.6 760 0.3" "2031-10-31 64.1 -21.9 0 -0.2" "2035-04-01 -12.0 -77.0 150 -0.5"
  "2039-06-21 40.0 -105.3 1655 1" "2043-12-21 -40.0 -73.0 2000 0" "2047-03-15 27.9 86.9 3000 -1.2"
  "2051-09-01 -55.0 -68.0 0 3" "2055-05-20 10.5 -66.9 900 -2" "2059-01-01 57.0 -3.0 300 0.3"
  "1993-08-08 -7.0 110.0 0 0" "1997-10-10 45.8 6.9 2400 -0.2" "2001-04-20 -18.0 -70.0 3000 -0.5"
  "2005-02-02 38.7 -9.1 100 1" "2009-06-30 -1.3 36.8 1700 0" "2013-12-01 55.8 37.6 150 -1.2"
  "2017-03-01 -34.6 -58.4 25 3" "2021-11-21 30.0 31.2 20 -2" "2025-09-09 -26.2 28.0 1750 0.3"
  "2029-07-07 58.0 20.0 400 -0.5" "2033-03-20 -62.0 2.5 0 -0.2" "2045-05-31 50.1 -122.9 2200 0"
  "2053-10-15 -15.8 -47.9 1170 1" "2060-12-31 33.5 -112.1 340 -1.2"
)
for g in "${grazing[@]}"; do
  read -r day lat lon h target <<<"$g"
  midnight=$(date -u -d "${day}T00:00:00Z" +%s)
  lo=$(awk -v m="$midnight" -v l="$lon" 'BEGIN {printf "%.0f", m - l / 15 * 3600}')
  hi=$((lo + 43200))
  read -r _ _ e_lo < <(sun "$(iso "$lo")" "$lat" "$lon" "$h")
  read -r _ _ e_hi < <(sun "$(iso "$hi")" "$lat" "$lon" "$h")
  if ! awk -v a="$e_lo" -v b="$e_hi" -v t="$target" 'BEGIN {exit !(a < t && b > t)}'; then
    echo "grazing case '$g' does not bracket $target deg ($e_lo .. $e_hi)" >&2
    exit 1
  fi
  while ((hi - lo > 1)); do
    mid=$(((lo + hi) / 2))
    read -r _ _ e < <(sun "$(iso "$mid")" "$lat" "$lon" "$h")
    if awk -v e="$e" -v t="$target" 'BEGIN {exit !(e < t)}'; then lo=$mid; else hi=$mid; fi
  done
  read -r az el el0 < <(sun "$(iso "$hi")" "$lat" "$lon" "$h")
  add "$(iso "$hi")" "$lat" "$lon" "$h" "$az" "$el" "$el0"
done

{
  echo "{\"source\":\"terrashade sun --json (NREL SPA, standard atmosphere at height_m, Espenak-Meeus delta T), by scripts/make_sun_reference.sh\","
  echo "\"cases\":["
  n=${#lines[@]}
  for ((i = 0; i < n; i++)); do
    if ((i + 1 < n)); then echo "${lines[i]},"; else echo "${lines[i]}"; fi
  done
  echo "]}"
} >"$out"
echo "wrote $out (${#lines[@]} cases)"
