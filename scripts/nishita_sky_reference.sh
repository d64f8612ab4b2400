#!/usr/bin/env bash
# Tabulate Blender's Nishita sky (Cycles render) as CSV + EXR panoramas.
# Usage: scripts/nishita_sky_reference.sh OUT.csv [--sun-elevations 3,10,20,45] [--width 720]
#        [--dust-density D] [--air-density A] [--ozone-density O] [--altitude M]
# See scripts/nishita_sky_reference.py for the model facts and the pixel<->direction mapping.
set -uo pipefail
if [ $# -lt 1 ] || [[ $1 == -* ]]; then
  echo "usage: $0 OUT.csv [extra args for nishita_sky_reference.py]" >&2
  exit 2
fi
if ! command -v blender >/dev/null 2>&1; then
  echo "nishita_sky_reference.sh: 'blender' not found on PATH (needs Blender with Cycles, tested with 3.4)" >&2
  exit 1
fi
out=$1
shift
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# --python-exit-code makes a Python error fail the run (Blender exits 0 otherwise);
# Cycles' per-tile progress lines ("Fra:...") are dropped as noise.
blender -b --factory-startup --python-exit-code 1 -P "$here/nishita_sky_reference.py" \
  -- --out "$out" "$@" 2>&1 | grep --line-buffered -v '^Fra:'
exit "${PIPESTATUS[0]}"
