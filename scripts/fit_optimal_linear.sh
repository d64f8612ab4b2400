#!/usr/bin/env bash
# Refits the optimal-linear SH exponentiation coefficients a(m), b(m) (Ren et al. 2006) and
# writes core/sh/optimal_linear_table.inc. Deterministic (fixed seed): rerunning gives the same
# table, and tests/sh/optimal_linear_test.cpp checks the committed table against a refit.
# Usage: scripts/fit_optimal_linear.sh [path/to/terrashade]   (then rebuild)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${1:-$root/build/app/terrashade}"
"$bin" bench sh --fit-optimal-linear "$root/core/sh/optimal_linear_table.inc"
