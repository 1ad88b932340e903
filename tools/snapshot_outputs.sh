#!/usr/bin/env bash
# Writes what `frustum` prints for every bundled set, in every format, language and precision,
# with the bundled answers graded and every export written, into one directory. Run it before
# and after a change that must not change behaviour, then `diff -r` the two directories:
#   bash tools/snapshot_outputs.sh build/frustum /tmp/before
#   ... change, rebuild ...
#   bash tools/snapshot_outputs.sh build/frustum /tmp/after && diff -r /tmp/before /tmp/after
set -uo pipefail
cd "$(dirname "$0")/.."
bin=$(realpath "${1:?usage: tools/snapshot_outputs.sh FRUSTUM OUTDIR}")
out=${2:?usage: tools/snapshot_outputs.sh FRUSTUM OUTDIR}
rm -rf "$out" && mkdir -p "$out"
out=$(realpath "$out")

# Each command's standard output, standard error and exit status in one file.
# Commands run inside OUTDIR with relative output paths, so two snapshots differ only where
# the outputs do.
run() {
  local name=$1; shift
  (cd "$out" && { "$bin" "$@" 2>"$name.err"; echo "exit $?"; } >"$name.out")
}

# The sets are copied in and named by relative paths, so messages that name them agree too.
cp -r problems "$out/problems"
run kinds kinds
for set in problems/{seeds,examples,hard}/*.yaml; do
  base=$(basename "$(dirname "$set")")_$(basename "$set" .yaml)
  run "$base.check" check "$set"
  for format in text markdown json html latex; do
    for lang in en ja ru; do
      run "$base.solve.$format.$lang" solve "$set" --format "$format" --lang "$lang"
    done
  done
  for precision in double float long-double; do
    run "$base.solve.$precision" solve "$set" --precision "$precision" --format json
  done
  answers=$(dirname "$set")/answers/$(basename "$set")
  if [[ -f $answers ]]; then
    for lang in en ja ru; do
      run "$base.grade.$lang" grade "$set" "$answers" --lang "$lang"
    done
    run "$base.grade.json" grade "$set" "$answers" --format json
  fi
  run "$base.generate" generate "$set" --seed 7 --count 3
  # PrairieLearn's questions name the grader image they run in (any name will do here).
  run "$base.export.prairielearn" export prairielearn "$set" --image frustum/grader:snapshot \
      -o "$base.export.prairielearn.d"
  run "$base.export.qti" export qti "$set" -o "$base.export.qti.d"
  run "$base.export.moodle" export moodle "$set" -o "$base.export.moodle.xml"
done
echo "snapshot: $(find "$out" -type f | wc -l) files in $out"
