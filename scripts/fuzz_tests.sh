#!/usr/bin/env bash
# Fuzzes the scene loader and the device recording readers (tests/fuzz) for a bounded time: a
# Clang build of the fuzz targets and the foundation layer they link, alone, in build-fuzz/
# (ASan + UBSan + libFuzzer, the "fuzz" preset), then both targets at once for
# MSSPH_FUZZ_SECONDS each (default 60), from copies of their seeds (tests/corpus, configs/).
# Fails on any crash, leak, undefined behaviour, hang (10 s for one input) or use of more than
# 2 GB, and names the file the offending input was written to.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${MSSPH_FUZZ_SECONDS:-60}"
build=build-fuzz  # the preset's binaryDir

cmake --preset fuzz -DMSSPH_FUZZ_SECONDS="$seconds"
cmake --build --preset fuzz -j "$(nproc)"
if ctest --preset fuzz -j 2; then
  # How much fuzzing that was: libFuzzer's last line per target, from ctest's full log.
  awk '/ Testing: / { test = $NF } /^Done [0-9]+ runs/ { print "fuzz: " test ": " $0 }' \
    "$build"/Testing/Temporary/LastTest.log
  exit 0
fi
echo "fuzz: failed; the inputs that did it (reproduce with the target and the file as its argument):" >&2
found=0
for input in "$build"/tests/fuzz/*/artifacts/*; do
  [[ -f "$input" ]] || continue
  echo "  $(realpath "$input")" >&2
  found=1
done
if ((found == 0)); then echo "  none written (see the log above)" >&2; fi
exit 1
