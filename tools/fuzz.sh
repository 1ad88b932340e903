#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, build-fuzz/) and runs each for SECONDS (default 60).
# Seeds: fuzz/corpus/<target>/ (hostile inputs) plus the bundled problem sets and answers.
# The corpus found during the run grows in build-fuzz/corpus/<target>/; a crash, leak or hang
# (-timeout=10 s of wall time per input; FUZZ_TIMEOUT=N changes it) is saved in
# build-fuzz/artifacts/ and makes the script fail; the script prints the input's first bytes
# and how long it takes alone, so a red CI log is enough to reproduce it.
# Why 10 s: exact work on one value has a budget of a fraction of a second in the normal build
# (WorkBudget, docs/reliability.md), the sanitizers and coverage make that code many times
# slower, and a CI machine may run the fuzz targets at half a development machine's speed: 10 s
# leaves the slowest inputs of fuzz/corpus/ room on such a machine (docs/performance-notes.md
# has the figures).
# FUZZ_SEED=N fixes libFuzzer's random seed: CI uses one, so a CI run replays (a prefix of) the
# same inputs as a local run with that seed, and a red CI is a regression, not a lucky draw.
# Without it every run explores afresh (what longer local runs are for).
# Every run appends one row per target to build-fuzz/figures.md (date, machine, seconds,
# executions, exec/s, corpus size, peak memory, findings): the figures docs/reliability.md
# quotes. `nice -n 10 tools/fuzz.sh 3600` is the hour-per-target run.
# Usage: [FUZZ_SEED=N] tools/fuzz.sh [SECONDS] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
shift || true
targets=("$@")
all_targets=(fuzz_loader fuzz_expression fuzz_grade fuzz_batch fuzz_csv_roster fuzz_scene fuzz_neighbours
             fuzz_work fuzz_output_text fuzz_export_questions)
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")

. tools/sanitized_build.sh  # build-fuzz/, shared with tools/sanitize.sh
cmake --build build-fuzz --parallel "$(nproc)" --target "${targets[@]}"

# fuzz_grade reads one digit (which seed set) then the answer file.
# One seed directory per run, so runs of different targets may go side by side.
seeds=build-fuzz/seeds-$$
trap 'rm -rf "$seeds"' EXIT
rm -rf "$seeds" && mkdir -p "$seeds/fuzz_grade"
for f in problems/seeds/answers/00[0-4]_*.yaml; do
  n=$(basename "$f"); { printf '%s' "${n:2:1}"; cat "$f"; } > "$seeds/fuzz_grade/$n"
done

# fuzz_scene starts from the bundled scenes too (the `scene:` of every render problem is
# also a valid scene file when written under `scene:` at the top).
mkdir -p "$seeds/fuzz_scene"
for f in problems/*/*.yaml; do grep -q "^ *scene:" "$f" && cp "$f" "$seeds/fuzz_scene/$(basename "$f")"; done

mkdir -p build-fuzz/artifacts
figures=build-fuzz/figures.md
# Rows written up to 2026-11-30 counted libFuzzer's slow-unit reports among the findings; later rows keep
# them apart and say how a timeout did when re-run alone.
[ -f "$figures" ] || printf '| date | machine | target | seconds | executions | exec/s | corpus | peak RSS MB | findings |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n' > "$figures"
machine="$(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)"
seed_arg=()
[ -n "${FUZZ_SEED:-}" ] && seed_arg=(-seed="$FUZZ_SEED")
status=0
for t in "${targets[@]}"; do
  extra=()
  # fuzz_batch and fuzz_neighbours fork grading children for two batches per input (about twenty
  # processes under ASan): its inputs get six times the time of a single-process target.
  timeout=${FUZZ_TIMEOUT:-10}
  [ "$t" = fuzz_batch ] || [ "$t" = fuzz_neighbours ] && timeout=$((timeout * 6))
  [ "$t" = fuzz_output_text ] && timeout=$((timeout * 3))
  case "$t" in
    fuzz_loader) extra=(problems/seeds problems/examples) ;;
    fuzz_grade) extra=("$seeds/fuzz_grade") ;;
    fuzz_scene) extra=("$seeds/fuzz_scene") ;;
  esac
  mkdir -p "build-fuzz/corpus/$t"
  echo "fuzz: $t for ${seconds}s"
  log="build-fuzz/$t.log"
  touch "$log.start"
  if ! "build-fuzz/fuzz/$t" "build-fuzz/corpus/$t" "fuzz/corpus/$t" "${extra[@]}" \
        -max_total_time="$seconds" -timeout="$timeout" -report_slow_units=$((timeout / 2)) \
        -rss_limit_mb=2048 -max_len=262144 \
        -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$t-" "${seed_arg[@]}" >"$log" 2>&1; then
    echo "fuzz: $t FAILED (see $log and build-fuzz/artifacts/)"
    grep -E "^==[0-9]+==ERROR|^SUMMARY|ALARM|Test unit written" "$log" | head -5 || true
    status=1
  fi
  grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$log" | sed "s/^/fuzz: $t /" || true
  figure() { grep -E "stat::$1:" "$log" | tail -1 | awk '{print $2}'; }
  # Findings are crashes, leaks, out-of-memory and timeouts; a slow unit (over half the limit)
  # is only counted. A timeout is re-run alone: on a starved machine an input can pass
  # the limit without hanging, and the row says how long it took by itself.
  found=$(find build-fuzz/artifacts -newer "$log.start" \( -name "$t-crash-*" -o -name "$t-leak-*" \
          -o -name "$t-oom-*" -o -name "$t-timeout-*" \) 2>/dev/null)
  findings=$(printf '%s' "$found" | grep -c . || true)
  slow=$(find build-fuzz/artifacts -newer "$log.start" -name "$t-slow-unit-*" 2>/dev/null | wc -l)
  alone=""
  while IFS= read -r unit; do
    start=$(date +%s%N)
    if timeout $((timeout * 10)) "build-fuzz/fuzz/$t" "$unit" -runs=1 >/dev/null 2>&1; then
      ms=$((($(date +%s%N) - start) / 1000000))
      alone+="$((ms / 1000)).$((ms % 1000 / 100)) s; "
    else
      alone+="failed again; "
    fi
  done < <(find build-fuzz/artifacts -newer "$log.start" -name "$t-timeout-*" 2>/dev/null)
  # Each finding on the console as base64 (its first 3000 bytes): CI keeps only its log.
  while IFS= read -r unit; do
    [ -n "$unit" ] || continue
    echo "fuzz: $t finding $(basename "$unit") ($(wc -c < "$unit") bytes, base64): $(head -c 3000 "$unit" | base64 -w0)"
  done <<< "$found"
  [ -n "$alone" ] && echo "fuzz: $t timeouts re-run alone: ${alone%; }"
  [ "$slow" -gt 0 ] && findings+=" (and $slow slow units)"
  [ -n "$alone" ] && findings+=" (timeouts re-run alone: ${alone%; })"
  printf '| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$(date -u +%F)" "$machine → $(cut -d' ' -f1 /proc/loadavg)" "$t" "$seconds" \
    "$(figure number_of_executed_units)" "$(figure average_exec_per_sec)" "$(find "build-fuzz/corpus/$t" -type f | wc -l)" \
    "$(figure peak_rss_mb)" "$findings" >> "$figures"
done
echo "fuzz: figures appended to $figures"
exit $status
