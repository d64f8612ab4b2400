#!/usr/bin/env bash
# Installs the Debian packages terrashade needs (docs/dependencies.md says why each).
# Usage: scripts/setup.sh [demo|test|bench]
#   demo: what building and running terrashade needs (scripts/demo.sh): the toolchain and the
#         libraries it links, Mesa's Vulkan drivers to run on.
#   test: that, plus the test oracles, headless display and browser, Slurm, clang for the fuzzers,
#         charting, and the tile viewer's npm packages (scripts/test.sh; the default).
#   bench: test, plus what only the benchmarks compare with and no test runs: GRASS GIS (r.sun,
#         r.horizon for scripts/bench_insolation.sh). Kept out of test so CI does not install it.
# Idempotent: packages already present are skipped (no apt-get at all when all are present).
# Uses sudo when not root.
set -euo pipefail

what="${1:-test}"
case "$what" in demo|test|bench) ;; *) echo "setup: usage: scripts/setup.sh [demo|test|bench]" >&2; exit 2 ;; esac

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

# Build toolchain and the libraries terrashade links against.
DEMO_PKGS=(
  build-essential cmake ninja-build pkg-config
  mold                      # the linker, ~4x faster than GNU ld here (docs/dependencies.md)
  libgeographiclib-dev      # geodesy: local ENU frames, geodesics, UTM/UPS
  libopenimageio-dev        # EXR/HDR environment maps (the lazily loaded image module); image I/O in tests
  openimageio-tools         # Debian's OpenImageIO CMake config fails without its tools (/usr/bin/iconvert)
  libisal-dev               # PNG compression: ISA-L igzip, the fastest deflate (docs/dependencies.md)
  libdeflate-dev            # PNG compression at higher levels, and CRC-32 (docs/dependencies.md)
  libtiff-dev libgeotiff-dev  # GeoTIFF tags and GeoKeys (OIIO 2.4 does not expose them)
  libproj-dev proj-data     # CRS transforms for projections GeographicLib lacks
  libzip-dev zlib1g-dev     # .hgt.zip as distributed
  libglfw3-dev libglm-dev   # viewer window, vector math
  libvulkan-dev mesa-vulkan-drivers  # Vulkan, and lavapipe to run it without a GPU
  glslang-tools glslang-dev spirv-tools  # GLSL -> SPIR-V at build time
  libassimp-dev             # mesh import (AC3D, glTF, OBJ, ...)
  libsqlite3-dev            # MBTiles
  sqlite3                   # reads MBTiles for the lightable tiles' Node reader (app/web/tileset.mjs)
  libcli11-dev              # command-line parsing
  nlohmann-json3-dev        # JSON output (info --json)
)
# The tests, benchmarks and charts: never linked into terrashade.
TEST_PKGS=(
  libgtest-dev libgmock-dev googletest libbenchmark-dev  # GoogleTest
  libpng-dev                # tests: a PNG decoder besides OpenImageIO, and the earlier encoder as a reference
  vulkan-tools vulkan-validationlayers  # every GPU test runs with the validation layer on
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
# The benchmarks' other tools that no test needs (grass-core alone is 31 MB installed, with its
# own dependencies besides; CI, which runs scripts/test.sh, never installs them).
BENCH_PKGS=(
  grass-core                # GRASS GIS r.sun and r.horizon: `bench insolation` (docs/insolation.md)
)

wanted=("${DEMO_PKGS[@]}")
if [ "$what" != demo ]; then wanted+=("${TEST_PKGS[@]}"); fi
if [ "$what" = bench ]; then wanted+=("${BENCH_PKGS[@]}"); fi
need=()
for p in "${wanted[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    need+=("$p")
  fi
done
if [ "${#need[@]}" -gt 0 ]; then
  echo "setup: installing ${#need[@]} packages ($what): ${need[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
fi
if [ "$what" != demo ]; then
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
fi
echo "setup: the $what dependencies are present"
