#!/usr/bin/env bash
# Quick start, command 2 (and CI): install what is missing, build, run the whole test suite, then
# the CPU benchmark gate against the CI machine's baseline and the quick validation report. GPU
# tests and cases skip themselves when no device is present.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
# ctest runs as many tests at once as there are cores: one OpenMP thread each, so that two tests'
# thread teams do not fight over the same cores (tests that need threads set them themselves).
OMP_NUM_THREADS=1 ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 1500
scripts/bench_gate.sh
# The convergence suite is left out: at the quick spacings it measures real non-convergence (see
# validation/convergence/*/README.md), which the full report on a GPU shows.
./build/mssph validate --quick --suite kernels --suite physics --out build/validate-quick
