#!/usr/bin/env bash
# End to end, as Gradescope does it: make_bundle.sh from an untracked set and its per-student
# variants, the zip unpacked into a fresh root-like /autograder, the bundle's own setup.sh
# (packages already present are skipped; it builds only `frustum` from the bundled sources),
# then run_autograder on real submissions; every results.json is validated against
# Gradescope's documented fields and its scores checked.
# Usage: gradescope_bundle_test.sh SOURCE_DIR FRUSTUM_BINARY [--full]
# Without --full (CI, ctest): setup.sh configures the bundled sources as it always does, every
# source file of the `frustum` target is preprocessed from the bundle alone (each #include found
# in it or in the installed packages), and setup.sh is given FRUSTUM_BINARY, built from these
# same sources, in place of a second compile (tens of minutes on a loaded machine). With
# --full, setup.sh compiles frustum itself from the bundle, as Gradescope does (run it after a
# change to the bundle's layout).
set -euo pipefail
src=$(cd "$1" && pwd)
frustum=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
full=false
[ "${3:-}" = --full ] && full=true
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() {  # check DESCRIPTION COMMAND...: one assertion
  if "${@:2}"; then echo "ok: $1"; else echo "FAILED: $1"; failures=$((failures + 1)); fi
}
json() { python3 -c "import json, sys; print(eval(sys.argv[2], {}, {'r': json.load(open(sys.argv[1]))}))" "$@"; }

# An instructor's own set, never committed, with a per-student variant for two students.
mkdir -p "$work/course"
cat > "$work/course/homework 3.yaml" <<'YAML'
title: "Homework 3: planes and outcodes"
variants: per_student
problems:
  - id: depth
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
    ask: [plane, z]
  - id: clip
    kind: clip_line
    given: {p: [-2, 5], q: [3, 1], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 4}}
    ask: [outcode_p, outcode_q, clipped]
YAML
"$frustum" generate "$work/course/homework 3.yaml" --student s100 --student s200 -o "$work/course/variants" >/dev/null
bash "$src/tools/gradescope/make_bundle.sh" "$work/course/homework 3.yaml" --variants "$work/course/variants" \
  --identity sid -o "$work/autograder.zip"
# The older call, a committed seed set, Japanese feedback shown after the due date.
cp "$src/problems/seeds/001_zbuffer_plane_method.yaml" "$work/course/seed.yaml"
bash "$src/tools/gradescope/make_bundle.sh" "$work/course/seed.yaml" ja "$work/seed.zip" --visibility after_due_date

# Gradescope unpacks the zip into /autograder/source and runs setup.sh there.
ag=$work/root/autograder
mkdir -p "$ag/source"
(cd "$ag/source" && python3 -m zipfile -e "$work/autograder.zip" .)
chmod +x "$ag/source/setup.sh" "$ag/source/run_autograder"
cp "$ag/source/run_autograder" "$ag/run_autograder"
check "the zip holds setup.sh, run_autograder and the conf at its root" \
  test -f "$ag/source/setup.sh" -a -f "$ag/source/run_autograder" -a -f "$ag/source/autograder.conf"
check "the untracked set and both variants are in the bundle" \
  test -f "$ag/source/assignment/homework 3.yaml" -a -f "$ag/source/assignment/variants/homework 3-s100.yaml" \
       -a -f "$ag/source/assignment/variants/homework 3-s200.yaml"
# Reuse compiled objects between runs of this test (the sources are the same each time).
if command -v ccache >/dev/null; then export CMAKE_CXX_COMPILER_LAUNCHER=ccache CCACHE_BASEDIR=$work; fi
if $full; then
  check "setup.sh builds frustum from the bundled sources" bash "$ag/source/setup.sh"
else
  check "setup.sh configures the bundled sources and installs the given frustum" \
    env FRUSTUM_SETUP_BINARY="$frustum" bash "$ag/source/setup.sh"
  # What a compile would need from the bundle: every file the target's sources include.
  check "every source of frustum preprocesses from the bundle alone" python3 - "$ag/source" <<'PY'
import concurrent.futures, json, os, shlex, subprocess, sys
root = sys.argv[1]
commands = json.load(open(os.path.join(root, 'build', 'compile_commands.json')))
def preprocess(c):
    args = shlex.split(c['command'])
    # The compile command with -E in place of -c and no object written; directives only (every
    # #include and #if is followed, no macro expanded: a third of the time of a full -E).
    out = []
    skip = False
    for a in args:
        if skip:
            skip = False
            continue
        if a == '-o':
            skip = True
            continue
        out.append('-E' if a == '-c' else a)
    r = subprocess.run(out + ['-fdirectives-only', '-o', os.devnull], cwd=c['directory'], capture_output=True, text=True)
    return c['file'], r.returncode, r.stderr
outside = [c['file'] for c in commands if not os.path.realpath(c['file']).startswith(os.path.realpath(root))]
if outside or len(commands) < 100:
    sys.exit(f'{len(commands)} sources, outside the bundle: {outside[:3]}')
with concurrent.futures.ThreadPoolExecutor(os.cpu_count()) as pool:
    failed = [(f, e) for f, rc, e in pool.map(preprocess, commands) if rc]
for f, e in failed[:5]:
    print(f, e[:400])
sys.exit(1 if failed else 0)
PY
fi
check "setup.sh built only the frustum target" test ! -e "$ag/source/build/frustum_tests" -a ! -e "$ag/source/build/frustum_bench"

run() {  # run SUBMISSION_FILE... : a fresh submission directory, then run_autograder
  rm -rf "$ag/submission" "$ag/results"
  mkdir -p "$ag/submission"
  for f in "$@"; do cp "$f" "$ag/submission/"; done
  (cd "$ag" && AUTOGRADER_ROOT=$ag ./run_autograder > "$work/stdout" 2>&1)
  python3 "$src/tests/platforms/validate_json.py" "$src/tests/platforms/gradescope_results.schema.json" \
    "$ag/results/results.json"
}
metadata() {  # metadata SID: Gradescope's submission_metadata.json for one submitter
  printf '{"id": 1, "users": [{"email": "%s@example.edu", "id": 7, "name": "A Student", "sid": "%s"}]}' "$1" "$1" \
    > "$ag/submission_metadata.json"
}
results=$ag/results/results.json

metadata s100
check "s100's key is valid results.json" run "$work/course/variants/answers/homework 3-s100.yaml"
max=$(json "$results" 'sum(t["max_score"] for t in r["tests"])')
check "the set is worth something ($max)" test "$max" != 0
check "s100's own key earns full marks ($max)" test "$(json "$results" 'r["score"]')" = "$max"
check "one passed test per problem" test "$(json "$results" '[t["status"] for t in r["tests"]]')" = "['passed', 'passed']"
# Graded against their own generated set (their key earns full marks, another's scores 0 below);
# what the student reads names none of the instructor's files.
check "s100's feedback names none of the instructor's files" \
  test "$(json "$results" 'r["output"]' | grep -c "variants/")" = 0

# s200 uploads s100's key under s100's name: refused, with a message naming both.
metadata s200
check "another student's key is valid results.json" run "$work/course/variants/answers/homework 3-s100.yaml"
check "another student's key scores 0" test "$(json "$results" 'r["score"]')" = 0
check "the message names the claimed and the real submitter" \
  grep -q "student: s100.*s200" <(json "$results" 'r["output"]')

# s200's key with one value changed: partial credit, the changed problem failed.
sed 's/^\(    z: \).*/\1 12345/' "$work/course/variants/answers/homework 3-s200.yaml" > "$work/wrong.yaml"
check "a wrong z is valid results.json" run "$work/wrong.yaml"
check "a wrong z loses marks but not all" \
  test "$(json "$results" '0 < r["score"] < sum(t["max_score"] for t in r["tests"])')" = True
check "the depth problem failed, the clip problem passed" \
  test "$(json "$results" '[t["status"] for t in r["tests"]]')" = "['failed', 'passed']"

printf 'student: s200\nanswers: [unclosed\n' > "$work/broken.yaml"
check "a broken file is valid results.json" run "$work/broken.yaml"
check "a broken file scores 0 with a located reason" grep -q "broken.yaml:[0-9]*:[0-9]*: invalid YAML" <(json "$results" 'r["output"]')
check "no answers file is valid results.json" run "$src/README.md"
check "no answers file says so" grep -q "No answers file" <(json "$results" 'r["output"]')

# The seed bundle: same sources, so its build is the one above.
ag2=$work/root2/autograder
mkdir -p "$ag2/source"
(cd "$ag2/source" && python3 -m zipfile -e "$work/seed.zip" .)
check "both bundles carry the same sources" diff -r "$ag/source/frustum" "$ag2/source/frustum"
ln -s "$ag/source/build" "$ag2/source/build"
rm -f "$ag/submission_metadata.json"
ag=$ag2
cp "$ag/source/run_autograder" "$ag/run_autograder" && chmod +x "$ag/run_autograder"
results=$ag/results/results.json
check "the published answers are valid results.json" run "$src/problems/seeds/answers/001_zbuffer_plane_method.yaml"
check "the published answers earn 8 of 8" test "$(json "$results" 'r["score"]')" = 8
check "each problem's feedback is shown after the due date" \
  test "$(json "$results" '{t["visibility"] for t in r["tests"]}')" = "{'after_due_date'}"
check "the feedback is in Japanese" grep -q "判定" <(json "$results" 'r["tests"][0]["output"]')

echo "$failures failed"
[ "$failures" -eq 0 ]
