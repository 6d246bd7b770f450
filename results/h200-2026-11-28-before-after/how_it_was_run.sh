#!/usr/bin/env bash
# H200: a6d0c36 (the commit) against 6e15a4e, same benchmark command, alternated; then the drops.
# .device-build/pack.tgz held bin/{bench,mssph}_{old,new}: both commits built alike here (Release, sm_90),
# with their shared libraries and each commit's configs/sphere_drop_*.json (old_configs/, new_configs/).
set -u
mkdir -p /tmp/p && tar xzf .device-build/pack.tgz -C /tmp/p
export LD_LIBRARY_PATH=/tmp/p/lib
nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv > $OUT/device.txt 2>&1
mkdir -p /tmp/json
F='^step/cuda/(fluid|deformable|rigid)/(30000|1000000)/'
i=0
for v in old new new old; do
  i=$((i+1))
  echo "=== round $i: $v ($(date +%T))" >> $OUT/bench.txt
  timeout 150 /tmp/p/bin/bench_$v --benchmark_filter="$F" --benchmark_min_time=0.2 \
    --benchmark_out=/tmp/json/step_${v}_$i.json --benchmark_out_format=json >> $OUT/bench.txt 2>&1
  echo "rc=$?" >> $OUT/bench.txt
done
tar czf $OUT/step_json.tgz -C /tmp/json .
cd /tmp
for v in old new; do
  for m in fluid deformable rigid; do
    for s in 0.02 0.01; do
      echo "=== $v $m $s" >> $OUT/drops.txt
      timeout 60 /tmp/p/bin/mssph_$v run /tmp/p/${v}_configs/sphere_drop_$m.json --backend cuda -q \
        --set simulation/particle_spacing=$s --out /tmp/d_${v}_${m}_$s.h5 >> $OUT/drops.txt 2>&1
      echo "rc=$?" >> $OUT/drops.txt
    done
  done
done
for s in 0.02 0.01; do
  echo "=== new deformable-with-a6d0c36-config $s" >> $OUT/drops.txt
  timeout 60 /tmp/p/bin/mssph_new run /tmp/p/old_configs/sphere_drop_deformable.json --backend cuda -q \
    --set simulation/particle_spacing=$s --out /tmp/d_newold_$s.h5 >> $OUT/drops.txt 2>&1
  echo "rc=$?" >> $OUT/drops.txt
done
/tmp/p/bin/mssph_new info > $OUT/mssph_info.txt 2>&1
/tmp/p/bin/mssph_old info >> $OUT/mssph_info.txt 2>&1
