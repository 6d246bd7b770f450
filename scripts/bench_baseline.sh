#!/usr/bin/env bash
# Makes the CPU baseline of the benchmark gate on this machine and the noise study that sets the
# gate's threshold. Run it on a QUIET machine (nothing else running), after scripts/build.sh:
#
#   scripts/bench_baseline.sh [--runs N] [--dir DIR]
#
# 1. the baseline: the gate's benchmarks (scripts/bench_gate_settings.sh) -> DIR/cpu_gate.json;
# 2. the noise study: N more runs of the same build, each compared with the baseline;
# 3. a known slowdown: one run with MSSPH_BENCH_STEP_DELAY_US set to the fastest step benchmark's
#    baseline step time (that benchmark then takes 2x), which must fail the gate;
# then DIR/noise_study.md (the ratios' spread and the threshold that follows), DIR/threshold
# (read by scripts/bench_gate.sh) and DIR/noise/ (each comparison, as JSON). A run took 32 s on
# the 2-core CI machine kind at load average 10: N = 10, the default, then takes about 7 minutes
# (less on a quiet machine). Exits 1 when the known slowdown does not fail the gate.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench_gate_settings.sh
MSSPH=${MSSPH:-build/mssph}
runs=10
dir=$GATE_BASELINE_DIR
while [[ $# -gt 0 ]]; do
  case $1 in
    --runs) runs=$2; shift 2 ;;
    --dir) dir=$2; shift 2 ;;
    *) echo "usage: $0 [--runs N] [--dir DIR]" >&2; exit 2 ;;
  esac
done
[[ -x $MSSPH ]] || { echo "error: $MSSPH not built (run scripts/build.sh)" >&2; exit 2; }
mkdir -p "$dir"
# The runs' JSON is large and stays in a temporary folder; their comparisons (small) are kept in
# DIR/noise/, from which scripts/bench_noise_study.py remakes the summary.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rm -rf "$dir/noise"
mkdir -p "$dir/noise"
start=$SECONDS
load_before=$(cut -d" " -f1-3 /proc/loadavg)

echo "bench baseline: baseline run -> $dir/cpu_gate.json" >&2
gate_bench "$dir/cpu_gate.json"
same=()
for i in $(seq 1 "$runs"); do
  echo "bench baseline: noise run $i of $runs ($((SECONDS - start)) s so far)" >&2
  gate_bench "$work/run_$i.json"
  # The threshold is irrelevant here: the study reads the ratios and p-values.
  "$MSSPH" bench compare "$dir/cpu_gate.json" "$work/run_$i.json" --normalize-by "$GATE_NORMALIZE_BY" --format json > "$dir/noise/same_build_$i.json" || [[ $? == 1 ]]
  same+=("$dir/noise/same_build_$i.json")
done

# The fastest step benchmark's median step time, from the baseline [us].
delay_us=$("$MSSPH" bench compare "$dir/cpu_gate.json" "$dir/cpu_gate.json" --format json |
  /usr/bin/python3 -c 'import json, sys; print(round(1e6 * min(b["baseline_median_seconds"] for b in json.load(sys.stdin)["benchmarks"] if b["name"].startswith("step/"))))')
echo "bench baseline: known slowdown run, MSSPH_BENCH_STEP_DELAY_US=$delay_us" >&2
MSSPH_BENCH_STEP_DELAY_US=$delay_us gate_bench "$work/delayed.json"
"$MSSPH" bench compare "$dir/cpu_gate.json" "$work/delayed.json" --normalize-by "$GATE_NORMALIZE_BY" --format json > "$dir/noise/delayed.json" || [[ $? == 1 ]]

status=0
{
  echo "# Noise study of $dir/cpu_gate.json"
  echo
  echo "Made by \`scripts/bench_baseline.sh --runs $runs\` in $((SECONDS - start)) s; $("$MSSPH" --version);"
  echo "Load average (1, 5, 15 min) before the runs: $load_before; after: $(cut -d" " -f1-3 /proc/loadavg)."
  echo
  /usr/bin/python3 scripts/bench_noise_study.py "$dir/threshold" "$dir/noise/delayed.json" "${same[@]}" || status=$?
} > "$dir/noise_study.md"
cat "$dir/noise_study.md"
echo "bench baseline: done in $((SECONDS - start)) s; threshold $(cat "$dir/threshold")" >&2
exit "$status"
