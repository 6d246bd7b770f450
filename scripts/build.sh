#!/usr/bin/env bash
# Configures and builds mssph (Release, Ninja) into build/.
#   scripts/build.sh [--target NAME] [CMake configure arguments...]
# --target builds one target (e.g. mssph) instead of the whole tree; the rest go to the configure
# step, e.g. scripts/build.sh -DMSSPH_CUDA=OFF.
set -euo pipefail
cd "$(dirname "$0")/.."
target=()
if [[ ${1:-} == --target ]]; then
  target=(--target "$2")
  shift 2
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build -j "$(nproc)" "${target[@]}"
