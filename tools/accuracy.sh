#!/bin/bash
# Regenerates the measured part of docs/accuracy.md (and docs/accuracy_results.md and the two
# plots) from one run on this machine: builds frustum and frustum_bench, then runs
# bench/accuracy_page.py, which records the CPU model, date, commit, build type and load with
# the figures. The page's prose outside its `measured` markers is left as written.
#
#   tools/accuracy.sh                 (~2 min)
#   BUILD=build-dir REPS=9 tools/accuracy.sh
set -euo pipefail
cd "$(dirname "$0")/.."
. tools/bench_build.sh
exec /usr/bin/python3 bench/accuracy_page.py --frustum "$BUILD/frustum" --bench "$BUILD/frustum_bench" \
  --repo . --reps "${REPS:-7}"
