#!/usr/bin/env bash
# Configures and builds mssph (Release) into build/. Extra arguments go to the CMake configure
# step, e.g. scripts/build.sh -DMSSPH_CUDA=OFF.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j "$(nproc)"
