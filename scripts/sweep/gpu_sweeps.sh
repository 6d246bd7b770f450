#!/usr/bin/env bash
# The sweeps that need GPUs, on a machine with one or more:
#   1. the full stiffness sweep (configs/sweep_stiffness.json) on every listed GPU, merged and
#      plotted: OUT/stiffness/summary.csv and OUT/stiffness/plots/;
#   2. with two or more GPUs, the viscosity sweep (configs/sweep_viscosity.json) on the first GPU
#      alone and then on the first two, timed: the speed-up of --gpus 0,1 over --gpus 0, written to
#      OUT/multi_gpu_speedup.txt with the machine, the commit and a check that both runs give the
#      same metrics (timing metrics aside).
# Usage: scripts/sweep/gpu_sweeps.sh [BUILD_DIR] [OUT_DIR] [GPUS] [SWEEP_ARGUMENTS...]
#   defaults: build, results/sweeps, every GPU nvidia-smi lists; SWEEP_ARGUMENTS go to every sweep
#   (e.g. --set simulation/particle_spacing=0.04 --set simulation/duration=0.05 for a quick trial).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
out=${2:-results/sweeps}
gpus=${3:-$(nvidia-smi --query-gpu=index --format=csv,noheader | paste -sd, -)}
extra=("${@:4}")
mssph="$build/mssph"
mkdir -p "$out"

# A point that fails (exit code 3) is listed in the summary; the plot shows the others.
code=0
"$mssph" sweep configs/sweep_stiffness.json --out "$out/stiffness" --backend cuda --gpus "$gpus" "${extra[@]}" || code=$?
echo "gpu_sweeps: stiffness sweep exit code $code"
"$mssph" sweep plot "$out/stiffness"

IFS=, read -r -a gpu_list <<< "$gpus"
if ((${#gpu_list[@]} < 2)); then
  echo "gpu_sweeps: one GPU ($gpus): no multi-GPU speed-up measured"
  exit 0
fi
pair="${gpu_list[0]},${gpu_list[1]}"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# Wall-clock seconds of a command (its stdout dropped; progress stays on stderr).
seconds() {
  local start end
  start=$(date +%s%N)
  "$@" > /dev/null
  end=$(date +%s%N)
  awk -v ns=$((end - start)) 'BEGIN { printf "%.1f", ns / 1e9 }'
}
one=$(seconds "$mssph" sweep configs/sweep_viscosity.json --out "$scratch/one_gpu" --backend cuda --gpus "${gpu_list[0]}" "${extra[@]}")
two=$(seconds "$mssph" sweep configs/sweep_viscosity.json --out "$scratch/two_gpus" --backend cuda --gpus "$pair" "${extra[@]}")
same=$(/usr/bin/python3 - "$scratch/one_gpu/summary.csv" "$scratch/two_gpus/summary.csv" <<'EOF'
import csv, sys
timing = {"mean_step_time", "real_time_factor"}  # wall-clock measurements differ run to run
a, b = (list(csv.DictReader(open(p))) for p in sys.argv[1:])
print("yes" if [{k: v for k, v in r.items() if k not in timing} for r in a] ==
      [{k: v for k, v in r.items() if k not in timing} for r in b] else "NO")
EOF
)
{
  echo "mssph sweep --gpus speed-up: configs/sweep_viscosity.json (15 points, cuda backend) ${extra[*]}"
  echo "commit: $(git rev-parse --short HEAD)$(git diff --quiet || echo -dirty)"
  echo "GPUs: $(nvidia-smi --query-gpu=index,name --format=csv,noheader | paste -sd';' -)"
  echo "--gpus ${gpu_list[0]}: $one s"
  echo "--gpus $pair: $two s"
  echo "speed-up: $(awk -v a="$one" -v b="$two" 'BEGIN { printf "%.2f", a / b }')"
  echo "same metrics on one and two GPUs (timing metrics aside): $same"
} | tee "$out/multi_gpu_speedup.txt"
