#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and run the main job: the paper's
# Figure 3 sphere drop into fluid on the best available backend. Prints where the HDF5 log is and
# a one-line summary.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
./build/mssph run configs/sphere_drop_fluid.json --backend auto "$@"
