#!/usr/bin/env bash
# Installs what mssph needs from Debian 12's packages, only what is missing; safe to re-run.
# Must run as root (or with sudo available). CUDA is optional: with nvcc on PATH the CUDA backend
# is built too.
#   scripts/setup.sh          everything: building, running, and the whole test suite
#   scripts/setup.sh --run    what building mssph and drawing its figures need (the quick start)
set -euo pipefail

run_packages=(
  build-essential cmake git pkg-config ninja-build  # compilers and build
  libeigen3-dev                          # double-precision reference maths
  libhdf5-dev hdf5-tools                 # run logs (C API) and h5dump
  libcli11-dev                           # command line
  nlohmann-json3-dev                     # scene files
  libbenchmark-dev                       # benchmarks (mssph bench)
  python3 python3-h5py python3-matplotlib python3-numpy  # plots and the figures' checks
)
test_packages=(
  libgtest-dev libgmock-dev              # tests
  clang libclang-rt-14-dev               # the fuzz and sanitizer builds (their runtimes)
  libomp-dev                             # OpenMP for Clang (scripts/asan_tests.sh, fuzz_tests.sh)
  clang-format                           # the style check (scripts/check_format.sh)
  valgrind                               # the CPU gate's instruction counts (scripts/bench_gate.sh)
  python3-jsonschema                     # the scene-schema check
  slurmctld slurmd slurm-client          # Slurm: the sweep test starts its own single-node cluster
)

packages=("${run_packages[@]}")
if [[ ${1:-} != --run ]]; then packages+=("${test_packages[@]}"); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
