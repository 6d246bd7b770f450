#!/usr/bin/env bash
# Shows that the CPU gate judges the code, not the machine (run by scripts/test.sh after the gate):
#
#   scripts/bench_gate_proof.sh [--loaded-runs N]
#
# 1. with two CPU hogs per core (bounded by `timeout`), N runs of the unchanged build
#    (default 1) must each pass the gate;
# 2. one run with a planted slowdown of the same work, an extra step every 20 (5 % more steps,
#    MSSPH_BENCH_EXTRA_STEP_EVERY), must fail it (exit 1).
# Prints one line per run; exits 0 when every run went as expected, else 1.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench_gate_settings.sh
MSSPH=${MSSPH:-build/mssph}
loaded_runs=1
while [[ $# -gt 0 ]]; do
  case $1 in
    --loaded-runs) loaded_runs=$2; shift 2 ;;
    *) echo "usage: $0 [--loaded-runs N]" >&2; exit 2 ;;
  esac
done
work=$(mktemp -d)
hogs=()
stop_hogs() { for pid in "${hogs[@]}"; do kill "$pid" 2>/dev/null || true; done; hogs=(); }
trap 'stop_hogs; rm -rf "$work"' EXIT
wrong=0

# run_gate LABEL EXPECTED_EXIT [environment...]: one gate run and its verdict against the baseline.
run_gate() {
  local label=$1 expected=$2 code=0 start=$SECONDS
  shift 2
  env "$@" bash -c 'source scripts/bench_gate_settings.sh; gate_bench "$0"' "$work/$label.json" 2>/dev/null
  gate_compare "$GATE_BASELINE" "$work/$label.json" > "$work/$label.txt" || code=$?
  local verdict="as expected"
  if ((code != expected)); then verdict="NOT AS EXPECTED"; wrong=$((wrong + 1)); cat "$work/$label.txt"; fi
  echo "bench gate proof: $label: exit $code (expected $expected) in $((SECONDS - start)) s, load $(cut -d' ' -f1 /proc/loadavg): $verdict"
}

for _ in $(seq 1 $((2 * $(nproc)))); do
  timeout $((900 * loaded_runs)) sh -c 'while :; do :; done' &
  hogs+=($!)
done
for i in $(seq 1 "$loaded_runs"); do run_gate "loaded_$i" 0 MSSPH="$MSSPH"; done
stop_hogs
run_gate planted_5_percent 1 MSSPH="$MSSPH" MSSPH_BENCH_EXTRA_STEP_EVERY=20
exit $((wrong > 0))
