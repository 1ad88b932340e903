#!/usr/bin/env bash
# Fails when a C++ file differs from the repository's .clang-format (ctest: Source.Format).
#   bash tools/check_format.sh          check every file
#   bash tools/check_format.sh --fix    rewrite them in place
set -euo pipefail
cd "$(dirname "$0")/.."
mode=(--dry-run --Werror)
[[ ${1:-} == --fix ]] && mode=(-i)
dirs=()
for d in solver grader report batch export server app bench tests fuzz; do [[ -d $d ]] && dirs+=("$d"); done
files=$(find "${dirs[@]}" -name '*.cpp' -o -name '*.hpp' | sort)
# shellcheck disable=SC2086
clang-format --style=file "${mode[@]}" $files
