#!/usr/bin/env bash
# Installs what mssph needs from Debian 12's packages, only what is missing; safe to re-run.
# Must run as root (or with sudo available). CUDA is optional: with nvcc on PATH the CUDA backend
# is built too.
set -euo pipefail

packages=(
  build-essential cmake git pkg-config   # compilers and build
  ninja-build                            # the asan-ubsan preset's generator (scripts/asan_tests.sh)
  libeigen3-dev                          # double-precision reference maths
  libhdf5-dev hdf5-tools                 # run logs (C API) and h5dump
  libcli11-dev                           # command line
  nlohmann-json3-dev                     # scene files
  libgtest-dev libgmock-dev              # tests
  libbenchmark-dev                       # benchmarks
  clang libclang-rt-14-dev               # fuzz targets (libFuzzer runtime: scripts/fuzz_tests.sh)
  python3 python3-h5py python3-matplotlib python3-numpy python3-jsonschema  # plots, schema check
  slurmctld slurmd slurm-client          # Slurm: the sweep test starts its own single-node cluster
)

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
