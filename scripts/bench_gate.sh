#!/usr/bin/env bash
# The CPU benchmark gate of CI: runs the gate's short CPU benchmark (scripts/bench_gate_settings.sh)
# and compares it with the CI machine's baseline, normalized by the calibration benchmark
# (GATE_NORMALIZE_BY), printing the markdown table (also appended to $GITHUB_STEP_SUMMARY when
# that is set). Run after scripts/build.sh.
#
#   scripts/bench_gate.sh [--baseline FILE] [--threshold T] [--out FILE]
#
# A failing run is repeated, up to GATE_ATTEMPTS runs (scripts/bench_gate_settings.sh says why);
# every run's table is printed. Exit codes are those of the last `mssph bench compare`: 0 pass; 1 a
# benchmark significantly slower than the threshold in every run; 2 bad input, including a
# baseline made on another machine or build (make one with scripts/bench_baseline.sh on this
# machine).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench_gate_settings.sh
MSSPH=${MSSPH:-build/mssph}
baseline=$GATE_BASELINE
# The threshold from the noise study of the baseline's machine (its README), else 10 %.
threshold=$(cat "$GATE_BASELINE_DIR/threshold" 2>/dev/null || echo 10%)
out=build/bench_gate/current.json
while [[ $# -gt 0 ]]; do
  case $1 in
    --baseline) baseline=$2; shift 2 ;;
    --threshold) threshold=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "usage: $0 [--baseline FILE] [--threshold T] [--out FILE]" >&2; exit 2 ;;
  esac
done
[[ -x $MSSPH ]] || { echo "error: $MSSPH not built (run scripts/build.sh)" >&2; exit 2; }
[[ -f $baseline ]] || { echo "error: no baseline $baseline (make one with scripts/bench_baseline.sh)" >&2; exit 2; }

status=1
for attempt in $(seq 1 "$GATE_ATTEMPTS"); do
  echo "bench gate: run $attempt of at most $GATE_ATTEMPTS: the gate's CPU benchmarks ($GATE_REPETITIONS repetitions) into $out" >&2
  start=$SECONDS
  gate_bench "$out"
  echo "bench gate: benchmarks took $((SECONDS - start)) s; comparing with $baseline, threshold $threshold" >&2
  status=0
  report=$("$MSSPH" bench compare "$baseline" "$out" --threshold "$threshold" --normalize-by "$GATE_NORMALIZE_BY" \
    --format markdown) || status=$?
  echo "$report"
  if [[ -n ${GITHUB_STEP_SUMMARY:-} && -n $report ]]; then echo "$report" >> "$GITHUB_STEP_SUMMARY"; fi
  # Only "slower" (1) is worth another run; a pass or bad input (2) is final.
  if ((status != 1)); then break; fi
done
exit "$status"
