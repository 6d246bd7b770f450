#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run the whole test suite. GPU tests
# skip themselves when no device is present.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" --timeout 1500
