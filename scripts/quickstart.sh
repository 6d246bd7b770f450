#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and run the main job: the paper's
# Figure 3 (a sphere dropped on rigid, deformable and fluid blocks) at coarse resolution on the
# best available backend, drawn and checked against physics. Prints the check table and where the
# figure is; extra arguments go to `mssph figure 3` (e.g. --resolution paper). --force: a second
# quick start replaces the first one's logs.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
./build/mssph figure 3 --resolution coarse --backend auto --out results/runs/figure3 --force "$@"
