#!/usr/bin/env bash
# Installs every Debian package terrashade needs to build, run, test and chart.
# Idempotent: packages already present are skipped by apt-get. Uses sudo when not root.
set -euo pipefail

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# Build toolchain and the libraries the code links against (see docs/dependencies.md).
BUILD_PKGS=(
  build-essential cmake ninja-build pkg-config
  libgeographiclib-dev      # geodesy: local ENU frames, geodesics, UTM/UPS
  libopenimageio-dev        # image I/O in tests; EXR/HDR environment maps
  libisal-dev               # PNG compression: ISA-L igzip, the fastest deflate (docs/dependencies.md)
  libdeflate-dev            # PNG compression at higher levels, and CRC-32 (docs/dependencies.md)
  libpng-dev                # tests: a PNG decoder besides OpenImageIO, and the earlier encoder as a reference
  openimageio-tools
  libtiff-dev libgeotiff-dev  # GeoTIFF tags and GeoKeys (OIIO 2.4 does not expose them)
  libproj-dev proj-data     # CRS transforms for projections GeographicLib lacks
  libzip-dev zlib1g-dev     # .hgt.zip as distributed
  libglfw3-dev libglm-dev   # viewer window, vector math
  libvulkan-dev mesa-vulkan-drivers vulkan-tools vulkan-validationlayers
  glslang-tools glslang-dev spirv-tools  # GLSL -> SPIR-V at build time
  libassimp-dev             # mesh import (AC3D, glTF, OBJ, ...)
  libsqlite3-dev            # MBTiles
  libcli11-dev              # command-line parsing
  nlohmann-json3-dev        # JSON output (info --json) and parsing gdalinfo -json in tests
  libgtest-dev libgmock-dev googletest libbenchmark-dev
)
# Test oracles, headless display and charting: never linked into terrashade.
TEST_PKGS=(
  gdal-bin                  # gdalinfo / gdalwarp / gdaldem as test oracles
  python3-gdal              # gdal2tiles.py: the classic tile pipeline `bench tiles` compares with
  saga                      # SAGA sky-view factor as a benchmark baseline
  xvfb xauth                # window tests
  python3-matplotlib python3-numpy  # charts in docs/
  unzip
  chromium                  # headless browser: the tile viewer page's test (docs/tiles/check_page.mjs)
  nodejs                    # runs that test and installs the page's npm packages
  slurm-wlm munge           # a real single-node Slurm for the job-array test (tests/scale/slurm_fixture.sh)
  clang-14 libclang-rt-14-dev  # libFuzzer + ASan/UBSan for the DEM reader fuzz targets (scripts/fuzz.sh)
)

need=()
for p in "${BUILD_PKGS[@]}" "${TEST_PKGS[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    need+=("$p")
  fi
done
if [ "${#need[@]}" -gt 0 ]; then
  echo "setup: installing ${#need[@]} packages: ${need[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
# npm (Debian's own package when the installed nodejs does not bring it), then the tile viewer's
# packages from the npm registry into docs/tiles/node_modules (not committed): MapLibre GL JS for
# the page, playwright-core to drive Debian's chromium in its test. Redone when the lock changes.
if ! command -v npm >/dev/null 2>&1; then
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends npm >/dev/null
fi
viewer="$(cd "$(dirname "$0")/.." && pwd)/docs/tiles"
if ! cmp -s "$viewer/package-lock.json" "$viewer/node_modules/.package-lock.json.installed" 2>/dev/null; then
  echo "setup: npm ci in docs/tiles"
  (cd "$viewer" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
  cp "$viewer/package-lock.json" "$viewer/node_modules/.package-lock.json.installed"
fi
echo "setup: all dependencies present"
