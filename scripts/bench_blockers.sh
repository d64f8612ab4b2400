#!/usr/bin/env bash
# The mesh blockers against the ray-traced triangles (the Cessna x200, 600 m over the Anatolia
# crop) at 8 ... 512 spheres, then the moving 400-sphere aircraft: docs/charts/blockers_bench.csv
# and docs/charts/blockers_accuracy.png (docs/blockers.md).
# Usage: scripts/bench_blockers.sh [path/to/terrashade]   (default: the release build; ~10 min on 2 shared cores, most of it the flat loop)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
ts=${1:-$root/build/release/app/terrashade}
out="$root/docs/charts"
cd "$root"
"$ts" bench blockers --threads 2 --csv "$out/blockers_bench.csv"
/usr/bin/python3 "$root/scripts/chart_blockers.py" "$out/blockers_bench.csv" "$out"
