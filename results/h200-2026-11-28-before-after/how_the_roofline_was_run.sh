#!/usr/bin/env bash
# H200: the card's measured DRAM bandwidth and FP32 rate, for the roofline beside the H200 step times.
# .device-build/pack.tgz held bin/mssph_device_roofline, built here from 6e15a4e (Release, sm_90), and libbenchmark.
set -u
mkdir -p /tmp/p && tar xzf .device-build/pack.tgz -C /tmp/p
export LD_LIBRARY_PATH=/tmp/p/lib
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.max.mem --format=csv > $OUT/device.txt 2>&1
/tmp/p/bin/mssph_device_roofline --benchmark_repetitions=5 --benchmark_out=$OUT/roofline.json \
  --benchmark_out_format=json > $OUT/roofline.txt 2>&1
echo rc=$? >> $OUT/roofline.txt
