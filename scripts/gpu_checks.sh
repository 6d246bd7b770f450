#!/usr/bin/env bash
# The checks that need a GPU, on an already built tree: the cuda backend's tests (one step and
# many steps against the reference, repeatability), compute-sanitizer memcheck, racecheck, initcheck
# and synccheck on a short run of every shipped scene, memcheck and racecheck on two drops at one
# lane per particle, and the Figure 2 step-time benchmarks as JSON.
#
# Usage: scripts/gpu_checks.sh [BUILD_DIR] [OUT_DIR] [BENCHMARK_FILTER]
#   BUILD_DIR         default build
#   OUT_DIR           default results/gpu-checks; logs, test XML and benchmark JSON land here
#   BENCHMARK_FILTER  Google Benchmark regex, default step/cuda (all media and sizes)
# Exit code: the number of failed stages (0: all passed).
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-results/gpu-checks}
filter=${3:-step/cuda}
mkdir -p "$out"
failures=0

stage() {  # stage NAME COMMAND...: runs COMMAND, logs to $out/NAME.log, counts a failure
  local name=$1
  shift
  echo "== $name: $*"
  local start=$SECONDS
  if "$@" >"$out/$name.log" 2>&1; then
    echo "   passed ($((SECONDS - start)) s)"
  else
    echo "   FAILED with exit code $? ($((SECONDS - start)) s); last lines of $out/$name.log:"
    tail -n 15 "$out/$name.log"
    failures=$((failures + 1))
  fi
}

nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv >"$out/device.csv" 2>&1
cat "$out/device.csv"
"$build/mssph" info | tee "$out/mssph_info.txt"

# Both spellings: the small scenes' tests end in /cuda, the 1M scenes' at one lane per particle
# are named Cuda/<scene>.
stage one_step_tests "$build/tests/backends/one_step_agreement_test" --gtest_filter='*cuda*:*Cuda*' \
  --gtest_output="xml:$out/one_step_tests.xml"
stage many_step_tests "$build/tests/backends/backend_agreement_test" --gtest_filter='*cuda*' \
  --gtest_output="xml:$out/many_step_tests.xml"

# compute-sanitizer's four tools on a short coarse run of every shipped scene: the three drops
# (fluid with a container, an elastic block with fixed particles, a rigid block), the tap, squeeze
# and stir scenes with their simulated device, and the three together. The drops start with the
# sphere 3 cm into the block's surface layer, so the interaction forces work from the first step.
short_run=(--backend cuda -q --set simulation/particle_spacing=0.04 --set simulation/duration=0.005)
for scene in sphere_drop_fluid sphere_drop_deformable sphere_drop_rigid tap squeeze stir tap_squeeze_stir; do
  placement=()
  [[ $scene == sphere_drop_* ]] && placement=(--set "bodies/sphere/position=[0,0,0.37]")
  for tool in memcheck racecheck initcheck synccheck; do
    stage "${tool}_${scene}" compute-sanitizer --tool "$tool" --error-exitcode 9 \
      "$build/mssph" run "configs/$scene.json" "${short_run[@]}" "${placement[@]}" --out "$out/${tool}_${scene}.h5"
    rm -f "$out/${tool}_${scene}.h5" "$out/${tool}_${scene}.h5.xdmf"
  done
done

# The same scenes at 4 cm give every particle a team of lanes. Large scenes take one lane per
# particle, whose walks hold segments in shared memory and, for fluid particles, pass near notes
# from the density pass to the force pass (kernels/common/near_notes.hpp): memcheck and racecheck
# on the fluid and rigid drops at 5 mm, which a data-centre GPU gives one lane per particle
# (choose_team_lanes).
one_lane_run=(--backend cuda -q --set simulation/particle_spacing=0.005 --set simulation/duration=0.0005)
for scene in sphere_drop_fluid sphere_drop_rigid; do
  for tool in memcheck racecheck; do
    stage "${tool}_${scene}_one_lane" compute-sanitizer --tool "$tool" --error-exitcode 9 \
      "$build/mssph" run "configs/$scene.json" "${one_lane_run[@]}" --out "$out/${tool}_${scene}_one_lane.h5"
    rm -f "$out/${tool}_${scene}_one_lane.h5" "$out/${tool}_${scene}_one_lane.h5.xdmf"
  done
done

stage benchmarks "$build/benchmarks/mssph_backend_benchmarks" --benchmark_filter="$filter" \
  --benchmark_min_time=0.2 --benchmark_out="$out/backend_benchmarks.json" --benchmark_out_format=json

echo "gpu checks: $failures stage(s) failed; logs in $out"
exit "$failures"
