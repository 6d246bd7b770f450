# The CPU benchmark gate's settings, sourced by scripts/bench_gate.sh and scripts/bench_baseline.sh
# so that a baseline and the runs compared with it are always made the same way.
#
# The smallest host size of every medium and the haptic tick, and calibration/cpu, a fixed
# workload that times the machine: the comparison divides each ratio by its ratio
# (GATE_NORMALIZE_BY), since a shared CI machine runs the same build slower in some hours than in
# others (results/baselines/ci-2core/README.md).
GATE_FILTER='^step/cpu/(fluid|rigid|deformable|mixed)/2000/|^haptic_tick/cpu$|^calibration/cpu$'
GATE_NORMALIZE_BY=calibration/cpu
# 10 repetitions a side: complete separation gives p = 2 / C(20, 10) = 1.1e-5, so a real
# slowdown is significant even when a few repetitions are disturbed.
GATE_REPETITIONS=10
# One batch of 50 steps per repetition (each batch takes longer than this).
GATE_MIN_TIME=0.01
# Runs of the gate before it fails: a run that fails is repeated, up to this many runs in all,
# and the gate passes when one run passes. Other load on a shared VM only adds time, so a run that
# passes shows that the code is not slower; a real slowdown slows every run. The normalization
# divides out a slow hour, the repeats a burst of load within a run.
GATE_ATTEMPTS=3
# One OpenMP thread: the gate watches the cost of the kernels; on a 2-core VM a second thread
# that waits at every barrier for a core a neighbour holds adds more noise than information.
GATE_THREADS=1
# The CI machine's baseline (results/baselines/ci-2core/README.md says how it was made).
GATE_BASELINE_DIR=results/baselines/ci-2core
GATE_BASELINE="$GATE_BASELINE_DIR/cpu_gate.json"

# gate_bench OUT.json [extra mssph bench arguments]: one run of the gate's benchmarks.
gate_bench() {
  local out=$1
  shift
  OMP_NUM_THREADS=$GATE_THREADS "$MSSPH" bench --backend cpu --filter "$GATE_FILTER" \
    --repetitions "$GATE_REPETITIONS" --min-time "$GATE_MIN_TIME" --out "$out" "$@" >&2
}
