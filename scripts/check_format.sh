#!/usr/bin/env bash
# Checks that C++ and CUDA sources are in the style of .clang-format without changing them: a dry
# run that prints each difference and exits 1 if there is any. With no arguments it checks every
# tracked source file (fixtures under tests/style/data/ excepted); otherwise the files named.
set -euo pipefail
cd "$(dirname "$0")/.."
if (($# == 0)); then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.cu' '*.cuh' ':!tests/style/data/*')
else
  files=("$@")
fi
clang-format --dry-run --Werror "${files[@]}"
echo "check_format: ${#files[@]} files in the style of .clang-format"
