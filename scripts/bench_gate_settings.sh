# The CPU benchmark gate's settings, sourced by scripts/bench_gate.sh, scripts/bench_baseline.sh
# and scripts/bench_gate_proof.sh, so that a baseline and the runs compared with it are always
# made the same way.
#
# The gate judges instructions per step, counted by Callgrind (`mssph bench --count-instructions`):
# the same for the same build whatever else a shared runner is doing, so a rise beyond the
# threshold is a real change of the code's work. Wall time is measured too and shown beside the
# counts for information (a few repetitions: no test decides on it).
GATE_FILTER='^step/cpu/(fluid|rigid|deformable|mixed)/2000/|^haptic_tick/cpu$'
GATE_MEASURE=instructions
GATE_REPETITIONS=3
# One batch of 50 steps per repetition (each batch takes longer than this).
GATE_MIN_TIME=0.01
# One OpenMP thread: Callgrind runs threads one at a time, and a count is deterministic only for a
# single-threaded run.
GATE_THREADS=1
# The baseline (results/baselines/ci-2core/README.md says how it was made) and the threshold.
GATE_BASELINE_DIR=results/baselines/ci-2core
GATE_BASELINE="$GATE_BASELINE_DIR/cpu_gate.json"

# gate_bench OUT.json [extra mssph bench arguments]: one run of the gate's benchmarks, replacing OUT.
gate_bench() {
  local out=$1
  shift
  OMP_NUM_THREADS=$GATE_THREADS "$MSSPH" bench --backend cpu --filter "$GATE_FILTER" \
    --repetitions "$GATE_REPETITIONS" --min-time "$GATE_MIN_TIME" --count-instructions --force --out "$out" "$@" >&2
}

# gate_compare BASELINE CURRENT [extra arguments]: the gate's comparison; exit 1 when it fails.
gate_compare() {
  local baseline=$1 current=$2
  shift 2
  "$MSSPH" bench compare "$baseline" "$current" --gate "$GATE_MEASURE" --threshold "$(gate_threshold)" "$@"
}

# The threshold of the baseline's folder, else 3 %.
gate_threshold() { cat "$GATE_BASELINE_DIR/threshold" 2>/dev/null || echo 3%; }
