#!/bin/bash
# Regenerates docs/performance.md from one run on this machine: builds frustum and frustum_bench
# (Release; with OSMesa frustum_race too), then runs bench/performance.py, which measures every
# figure the page shows (CPU model, date and load included). Needs python3-numpy and python3-yaml (tools/packages/test.txt).
#
#   tools/performance.sh            sizes up to generate 10 000, grade 1 000, render 1 M (~10 min)
#   tools/performance.sh --full     also generate 100 000, grade 10 000, render 10 M
#   tools/performance.sh --only grade   one section (generate, grade, render, edge_visibility,
#                                        raster; repeatable): the page says which were not rerun
#   BUILD=build-dir REPS=5 tools/performance.sh
set -euo pipefail
cd "$(dirname "$0")/.."
. tools/bench_build.sh
exec /usr/bin/python3 bench/performance.py --frustum "$BUILD/frustum" --bench "$BUILD/frustum_bench" \
  --race "$BUILD/frustum_race" --repo . --reps "${REPS:-3}" "$@"
