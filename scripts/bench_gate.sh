#!/usr/bin/env bash
# The CPU benchmark gate of CI: runs the gate's benchmarks (scripts/bench_gate_settings.sh) with
# their instruction counts and compares them with the baseline, printing the markdown table (also
# appended to $GITHUB_STEP_SUMMARY when that is set). Run after scripts/build.sh.
#
#   scripts/bench_gate.sh [--baseline FILE] [--out FILE]
#
# Exit codes are those of `mssph bench compare --gate instructions`: 0 pass; 1 a benchmark's
# instructions per step rose beyond the threshold; 2 bad input, e.g. a baseline made by another
# build type or compiler (make one with scripts/bench_baseline.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench_gate_settings.sh
MSSPH=${MSSPH:-build/mssph}
baseline=$GATE_BASELINE
out=build/bench_gate/current.json
while [[ $# -gt 0 ]]; do
  case $1 in
    --baseline) baseline=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "usage: $0 [--baseline FILE] [--out FILE]" >&2; exit 2 ;;
  esac
done
[[ -x $MSSPH ]] || { echo "error: $MSSPH not built (run scripts/build.sh)" >&2; exit 2; }
[[ -f $baseline ]] || { echo "error: no baseline $baseline (make one with scripts/bench_baseline.sh)" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "error: valgrind not found (scripts/setup.sh installs it)" >&2; exit 2; }

start=$SECONDS
gate_bench "$out"
echo "bench gate: benchmarks and counts took $((SECONDS - start)) s; comparing with $baseline" >&2
status=0
report=$(gate_compare "$baseline" "$out" --format markdown) || status=$?
echo "$report"
if [[ -n ${GITHUB_STEP_SUMMARY:-} && -n $report ]]; then echo "$report" >> "$GITHUB_STEP_SUMMARY"; fi
exit "$status"
