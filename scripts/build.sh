#!/usr/bin/env bash
# Configures and builds terrashade (release preset) after installing its dependencies.
# Usage: scripts/build.sh [TARGET...]   (default: everything, tests included; the demo builds
# only the terrashade target and its image module)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release >/dev/null
if [ $# -gt 0 ]; then
  cmake --build --preset release -j"$(nproc)" --target "$@"
else
  cmake --build --preset release -j"$(nproc)"
fi
