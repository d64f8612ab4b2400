#!/usr/bin/env bash
# Configures and builds terrashade (release preset) after installing its dependencies.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
