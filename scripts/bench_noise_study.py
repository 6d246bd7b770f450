#!/usr/bin/env python3
"""Summarises a noise study of the benchmark gate (scripts/bench_baseline.sh): the same build
compared with its own baseline N times (`mssph bench compare --format json` files), plus one run
with a known slowdown. Prints a markdown report and writes the threshold that follows from the
spread: the smallest multiple of 5 % above the largest same-build median ratio, plus 5 % margin,
and never below 10 %.

usage: bench_noise_study.py THRESHOLD_FILE DELAYED_COMPARE.json SAME_BUILD_COMPARE.json...
"""
import json
import math
import sys


def load(path):
    with open(path) as f:
        return json.load(f)


def main(argv):
    if len(argv) < 4:
        sys.exit(__doc__)
    threshold_file, delayed_path, same_paths = argv[1], argv[2], argv[3:]
    same = [load(p) for p in same_paths]
    names = [b["name"] for b in same[0]["benchmarks"]]
    ratios = {n: [] for n in names}
    significant = {n: 0 for n in names}
    for report in same:
        for b in report["benchmarks"]:
            ratios.setdefault(b["name"], []).append(b["ratio"])
            if b["p_value"] < report["alpha"]:
                significant[b["name"]] = significant.get(b["name"], 0) + 1
    worst = max(max(abs(math.log(r)) for r in rs) for rs in ratios.values())
    worst_ratio = math.exp(worst)
    threshold = max(0.10, math.ceil((worst_ratio - 1.0) / 0.05 - 1e-9) * 0.05 + 0.05)

    print(f"## Noise study: the same build against its baseline, {len(same)} runs\n")
    print("| benchmark | min ratio | max ratio | runs with p < alpha |")
    print("| --- | ---: | ---: | ---: |")
    for n in names:
        rs = ratios[n]
        print(f"| `{n}` | {min(rs):.3f} | {max(rs):.3f} | {significant[n]}/{len(rs)} |")
    print(f"\nLargest same-build deviation of a median ratio: {worst_ratio:.3f}x (either way).")
    print(f"Threshold: {threshold * 100:.0f}% (next 5 % step above it, plus 5 % margin, at least 10 %).\n")

    # The delay is the fastest step benchmark's baseline step time: that benchmark's step takes
    # 2x the baseline's, the others less (the haptic tick, far below a step, many times more).
    delayed = load(delayed_path)
    steps = [b for b in delayed["benchmarks"] if b["name"].startswith("step/")]
    doubled = min(steps, key=lambda b: b["baseline_median_seconds"])
    print("## Known slowdown: MSSPH_BENCH_STEP_DELAY_US = the fastest step benchmark's baseline step time\n")
    print("| benchmark | ratio | p | fails at the threshold |")
    print("| --- | ---: | ---: | --- |")
    caught = False
    for b in steps:
        fails = b["ratio"] > 1.0 + threshold and b["p_value"] < delayed["alpha"]
        if b is doubled:
            caught = fails
        mark = " (2x)" if b is doubled else ""
        print(f"| `{b['name']}`{mark} | {b['ratio']:.3f} | {b['p_value']:.3g} | {'yes' if fails else 'no'} |")
    print(f"\nThe benchmark slowed down 2x, `{doubled['name']}`, {'fails' if caught else 'does NOT fail'} "
          f"the gate at {threshold * 100:.0f}%.")
    with open(threshold_file, "w") as f:
        f.write(f"{threshold * 100:.0f}%\n")
    return 0 if caught else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
