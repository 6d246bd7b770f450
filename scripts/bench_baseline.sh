#!/usr/bin/env bash
# Makes the CPU baseline of the benchmark gate and checks that the gate can judge against it:
#
#   scripts/bench_baseline.sh [--runs N] [--dir DIR]
#
# 1. the baseline: the gate's benchmarks with their instruction counts
#    (scripts/bench_gate_settings.sh) -> DIR/cpu_gate.json;
# 2. N more runs of the same build (default 3), each compared with it: every count must agree;
# 3. planted slowdowns of the same work (MSSPH_BENCH_EXTRA_STEP_EVERY=N, 1/N more steps): every
#    20th step (5 %) must fail the gate, every 50th (2 %, below the 3 % threshold) must pass;
# then DIR/gate_study.md with the ratios. The counts do not depend on other load, so any machine
# with the CI build's compiler and build type makes the same baseline. Exits 1 when a check fails.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/bench_gate_settings.sh
MSSPH=${MSSPH:-build/mssph}
runs=3
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
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
start=$SECONDS

echo "bench baseline: baseline run -> $dir/cpu_gate.json" >&2
gate_bench "$dir/cpu_gate.json"
comparisons=()
# compare_run LABEL EXPECTED_EXIT: compares $work/LABEL.json with the baseline, records the JSON.
compare_run() {
  local code=0
  gate_compare "$dir/cpu_gate.json" "$work/$1.json" --format json > "$work/$1.compare.json" || code=$?
  comparisons+=("$1" "$2" "$code" "$work/$1.compare.json")
}
for i in $(seq 1 "$runs"); do
  echo "bench baseline: same-build run $i of $runs ($((SECONDS - start)) s so far)" >&2
  gate_bench "$work/same_$i.json"
  compare_run "same_$i" 0
done
for every in 20 50; do
  echo "bench baseline: planted run, one extra step every $every" >&2
  MSSPH_BENCH_EXTRA_STEP_EVERY=$every gate_bench "$work/extra_every_$every.json"
  compare_run "extra_every_$every" "$([[ $every == 20 ]] && echo 1 || echo 0)"
done

{
  echo "# Gate study of $dir/cpu_gate.json"
  echo
  echo "Made by \`scripts/bench_baseline.sh --runs $runs\` in $((SECONDS - start)) s; $("$MSSPH" --version);"
  echo "threshold $(gate_threshold) on instructions per step."
  echo
  /usr/bin/python3 - "${comparisons[@]}" <<'PY'
import json, sys
args = sys.argv[1:]
print("| run | expected exit | exit | largest instruction ratio | wall-time ratios |")
print("|---|---|---|---|---|")
failed = 0
for label, expected, code, path in zip(args[0::4], args[1::4], args[2::4], args[3::4]):
    report = json.load(open(path))
    ratios = [b["instruction_ratio"] for b in report["benchmarks"]]
    walls = ", ".join(f'{b["ratio"]:.2f}' for b in report["benchmarks"])
    ok = expected == code
    failed += not ok
    print(f"| {label} | {expected} | {code}{'' if ok else ' (WRONG)'} | {max(ratios):.5f} | {walls} |")
print()
print("All as expected." if not failed else f"{failed} run(s) not as expected.")
sys.exit(1 if failed else 0)
PY
} > "$dir/gate_study.md" || status=$?
cat "$dir/gate_study.md"
echo "bench baseline: done in $((SECONDS - start)) s" >&2
exit "${status:-0}"
