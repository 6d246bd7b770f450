#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build the mssph program alone, and run the main
# job: the paper's Figure 3 (a sphere dropped on rigid, deformable and fluid blocks) at coarse
# resolution on the best available backend, drawn and checked against physics. Prints the check
# table and where the figure is; extra arguments go to `mssph figure 3` (e.g. --resolution paper).
# --force: a second quick start replaces the first one's logs. The whole tree with its tests is
# scripts/test.sh's job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --run
scripts/build.sh --target mssph -DCMAKE_UNITY_BUILD=ON  # a fresh tree: batches build sooner (test.sh says why)
./build/mssph figure 3 --resolution coarse --backend auto --out results/runs/figure3 --force "$@"
