#!/usr/bin/env bash
# Installs the dependencies, configures and builds terrashade (release preset).
# Usage: scripts/build.sh demo|test [TARGET...]
#   demo: the packages the demo needs (scripts/setup.sh demo); test: those of the tests too.
#   TARGET...: what to build (default: everything, tests and terrashade-bench included; the demo
#   builds only the terrashade target and its image module).
set -euo pipefail
cd "$(dirname "$0")/.."
what="${1:?usage: scripts/build.sh demo|test [TARGET...]}"
shift
bash scripts/setup.sh "$what"
cmake --preset release >/dev/null
if [ $# -gt 0 ]; then
  cmake --build --preset release -j"$(nproc)" --target "$@"
else
  cmake --build --preset release -j"$(nproc)"
fi
