#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, build-fuzz/) and runs each for SECONDS (default 60).
# Seeds: fuzz/corpus/<target>/ (hostile inputs) plus the bundled problem sets and answers.
# The corpus found during the run grows in build-fuzz/corpus/<target>/; a crash, leak or hang
# (-timeout=5 s of wall time per input; FUZZ_TIMEOUT=N raises it on a loaded machine) is saved
# in build-fuzz/artifacts/ and makes the script fail.
# FUZZ_SEED=N fixes libFuzzer's random seed: CI uses one, so a CI run replays (a prefix of) the
# same inputs as a local run with that seed, and a red CI is a regression, not a lucky draw.
# Without it every run explores afresh (what longer local runs are for).
# Usage: [FUZZ_SEED=N] tools/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(fuzz_loader fuzz_expression fuzz_grade)

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_COMPILER=clang++ -DFRUSTUM_FUZZ=ON -DFRUSTUM_TESTS=OFF "${launcher[@]}" >/dev/null
cmake --build build-fuzz --parallel "$(nproc)" --target "${targets[@]}"

# fuzz_grade reads one digit (which seed set) then the answer file.
seeds=build-fuzz/seeds
rm -rf "$seeds" && mkdir -p "$seeds/fuzz_grade"
for f in problems/seeds/answers/00[0-4]_*.yaml; do
  n=$(basename "$f"); { printf '%s' "${n:2:1}"; cat "$f"; } > "$seeds/fuzz_grade/$n"
done

mkdir -p build-fuzz/artifacts
seed_arg=()
[ -n "${FUZZ_SEED:-}" ] && seed_arg=(-seed="$FUZZ_SEED")
status=0
for t in "${targets[@]}"; do
  extra=()
  case "$t" in
    fuzz_loader) extra=(problems/seeds problems/examples) ;;
    fuzz_grade) extra=("$seeds/fuzz_grade") ;;
  esac
  mkdir -p "build-fuzz/corpus/$t"
  echo "fuzz: $t for ${seconds}s"
  log="build-fuzz/$t.log"
  if ! "build-fuzz/fuzz/$t" "build-fuzz/corpus/$t" "fuzz/corpus/$t" "${extra[@]}" \
        -max_total_time="$seconds" -timeout="${FUZZ_TIMEOUT:-5}" -rss_limit_mb=2048 -max_len=262144 \
        -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t-" "${seed_arg[@]}" >"$log" 2>&1; then
    echo "fuzz: $t FAILED (see $log and build-fuzz/artifacts/)"
    grep -E "^==[0-9]+==ERROR|^SUMMARY|ALARM|Test unit written" "$log" | head -5 || true
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$log" | sed "s/^/fuzz: $t /" || true
done
exit $status
