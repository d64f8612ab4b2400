#!/usr/bin/env bash
# Opt-in: installs Blender (Cycles) for the independent reference pictures of
# scripts/cycles_reference.sh, cycles_bench.sh and make_cycles_reference.sh (docs/accuracy.md,
# "Against Blender Cycles"). Not part of scripts/setup.sh: nothing builds or tests with Blender
# (the test reads stored references); it is ~400 MB with its dependencies (docs/dependencies.md).
# Also needs what scripts/setup.sh test installs: gdal-bin, python3-gdal, openimageio-tools.
# Usage: scripts/setup_reference.sh   (uses sudo when not root)
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PKGS=(blender gdal-bin python3-gdal python3-numpy openimageio-tools bc)
missing=()
for p in "${PKGS[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  $SUDO apt-get update
  $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
# Debian's Blender runs on the system python, so its scripts import osgeo (GDAL) directly.
blender -b --factory-startup --python-expr "import osgeo, numpy" >/dev/null
echo "setup_reference: blender $(blender --version | head -1 | awk '{print $2}') ready"
