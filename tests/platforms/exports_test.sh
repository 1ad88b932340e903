#!/usr/bin/env bash
# The routes to PrairieLearn, Canvas and Moodle, end to end on real sets:
# - `frustum export prairielearn`: every info.json against PrairieLearn's documented fields,
#   server.py's generate() run as PrairieLearn runs it, question.html's inputs matching the
#   params; then tools/prairielearn/frustum-pl-grade in a stand-in /grade tree with the
#   answers as PrairieLearn's elements submit them (right, wrong, unreadable), every
#   results.json against PrairieLearn's documented format (the bulk of the submissions run the
#   grader's script in one Python process, since an interpreter's start-up was four fifths of
#   this test's time; the language, feedback and hostile-input checks run it as its own
#   process, as PrairieLearn does);
# - `frustum export qti` and `export moodle`: the XML against the schemas in schemas/, and the
#   numbers and windows in them against `frustum solve`;
# - `frustum export canvas-grades` / `moodle-grades` from a class graded by `frustum grade`.
# Usage: exports_test.sh SOURCE_DIR FRUSTUM_BINARY
set -euo pipefail
src=$(cd "$1" && pwd)
frustum=$(realpath "$2")
here=$src/tests/platforms
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() {
  if "${@:2}"; then echo "ok: $1"; else echo "FAILED: $1"; failures=$((failures + 1)); fi
}
validate() { python3 "$here/validate_json.py" "$@"; }

# --- PrairieLearn -------------------------------------------------------------------------
# Besides the seeds: statements none of which is true, and a polygon clipped away (key `none`).
# Another set (its own title: a question's UUID is its set's title and its id), every statement
# false.
sed -e 's/truth: ○/truth: ×/' -e 's/ja: "ポリゴンの法線ベクトルとバックフェースカリング"/ja: "正しい記述のない問題"/' \
  "$src/problems/seeds/003_polygons_backface.yaml" > "$work/none_true.yaml"
cat > "$work/clipped_away.yaml" <<'YAML'
title: Clipped away
problems:
  - id: gone
    kind: clip_polygon
    text: "Clip the triangle against the window 0 ≤ x ≤ 1, 0 ≤ y ≤ 1."
    given:
      points: [[5, 5], [8, 5], [5, 8]]
      window: {xmin: 0, xmax: 1, ymin: 0, ymax: 1}
  - id: kept
    kind: clip_polygon
    given:
      points: [[0, 0], [4, 0], [0, 4]]
      window: {xmin: 1, xmax: 3, ymin: 1, ymax: 3}
YAML
image=frustum-course/frustum-grader:test
for set in "$src"/problems/seeds/001_zbuffer_plane_method.yaml "$src"/problems/seeds/003_polygons_backface.yaml \
           "$src"/problems/seeds/000_projection_and_hidden_surfaces.yaml "$work/none_true.yaml" "$work/clipped_away.yaml"; do
  "$frustum" export prairielearn "$set" --count 4 --seed 3 --image "$image" -o "$work/pl" >/dev/null 2>&1
done
"$frustum" export prairielearn "$src/problems/seeds/003_polygons_backface.yaml" --lang ja --image "$image" -o "$work/pl-ja" >/dev/null 2>&1
check "every question's info.json has PrairieLearn's fields" \
  validate "$here/prairielearn_info.schema.json" "$work"/pl/*/info.json
check "the grader image is the one given, a name PrairieLearn can pull" \
  test "$(cat "$work"/pl/*/info.json | grep -c "\"image\": \"$image\"")" = "$(ls -d "$work"/pl/*/ | wc -l)"
check "without --image, export prairielearn refuses and says why" \
  grep -q "give --image ACCOUNT/NAME:TAG" <("$frustum" export prairielearn "$src/problems/seeds/001_zbuffer_plane_method.yaml" -o "$work/noimage" 2>&1 || true)
check "UUIDs are distinct" test "$(cat "$work"/pl/*/info.json | grep -c '"uuid"')" = \
                               "$(cat "$work"/pl/*/info.json | grep '"uuid"' | sort -u | wc -l)"
"$frustum" export prairielearn "$src/problems/seeds/001_zbuffer_plane_method.yaml" --count 4 --seed 3 --image "$image" -o "$work/pl2" >/dev/null 2>&1
check "a second export is byte-identical (UUIDs and variants stay)" \
  diff <(cd "$work/pl2" && cat */*) <(cd "$work/pl" && cat 001_*/*)
# PrairieLearn's own element rules (prairielearn_elements.py, from the elements' code): every
# question renders, every input takes the key as a student types it.
check "PrairieLearn: every question.html passes the elements' rules (pl-checkbox has a right option, ...)" \
  python3 "$here/prairielearn_elements.py" "$work"/pl/*/ "$work"/pl-ja/*/
# ... and the rules catch what PrairieLearn refuses: a question as the exports once were (no
# right checkbox, min-correct="0", a pl-number-input), planted in a copy of a real one.
planted=$work/planted && mkdir -p "$planted" && cp "$(ls -d "$work"/pl/none_true-*culling*/)"* "$planted/"
sed -i 's/correct="true">\([^0-9]\)/correct="false">\1/; s/hide-letter-keys="true">/hide-letter-keys="true" min-correct="0">/' "$planted/question.html"
echo '<pl-number-input answers-name="w"></pl-number-input>' >> "$planted/question.html"
check "PrairieLearn: the element rules refuse a checkbox with no right option and a pl-number-input" \
  test "$(python3 "$here/prairielearn_elements.py" "$planted/" | grep -c 'At least one option must be true\|min-correct must be\|refuses exact forms')" = 3

# PrairieLearn's side, played by Python: generate() with a seeded `random`, then the answers
# as the elements submit them, then the external grader's run.
cat > "$work/play.py" <<'PY'
import importlib.util, json, os, random, re, runpy, subprocess, sys


def play(work, frustum, grader, question, mode, seed, in_process):
    """One submission: generate() seeded with SEED, the answers (right, wrong or unreadable) as
    the elements submit them, the grader's run; returns the grader's results.json as a dict."""
    spec = importlib.util.spec_from_file_location("server", os.path.join(question, "server.py"))
    server = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(server)
    random.seed(seed)
    data = {"params": {}, "correct_answers": {}}
    server.generate(data)
    params = data["params"]
    html = open(os.path.join(question, "question.html"), encoding="utf-8").read()
    element = {"choice": "pl-multiple-choice", "string": "pl-string-input", "checkbox": "pl-checkbox"}
    for name, kind in params["inputs"].items():
        if not re.search(r'<%s answers-name="%s"' % (element[kind], re.escape(name)), html):
            raise SystemExit(f"question.html has no {element[kind]} for {name}")
        if kind == "string" and name not in data["correct_answers"]:
            raise SystemExit(f"server.py sets no correct_answers for {name} (the answer panel would be empty)")
    # The expected answers, from Frustum itself.
    set_path = os.path.join(work, "set.yaml")
    open(set_path, "w", encoding="utf-8").write(params["set"])
    solved = json.loads(subprocess.run([frustum, "solve", set_path, "--format", "json"], check=True,
                                       stdout=subprocess.PIPE).stdout)
    answers = solved["problems"][0]["answers"]
    submitted, raw, changed = {}, {}, False
    for name, kind in params["inputs"].items():
        a = answers[name]
        value = a["value"]
        if kind == "choice":  # the options as question.html shows them (in the export's language)
            block = re.search(r'<pl-multiple-choice answers-name="%s"[^>]*>(.*?)</pl-multiple-choice>'
                              % re.escape(name), html, re.S).group(1)
            options = re.findall(r'<pl-answer correct="\{\{params\.correct\.%s\.(\w+)\}\}">(.*?)</pl-answer>'
                                 % re.escape(name), block)
            words = [w for w, _ in options]
            params[name] = [{"key": chr(97 + i), "html": shown} for i, (_, shown) in enumerate(options)]
            right = str(value).lower() if isinstance(value, bool) else str(value)
            submitted[name] = raw[name] = chr(97 + words.index(right))
        elif kind == "checkbox":  # which statements are true: the options as question.html lists them
            options = re.findall(r'<pl-answer correct="(true|false)">(.*?)</pl-answer>', html)
            params[name] = [{"key": chr(97 + i), "html": text} for i, (_, text) in enumerate(options)]
            submitted[name] = [chr(97 + i) for i, (right, _) in enumerate(options) if right == "true"]
            numbered = [r for r, text in options if re.match(r"\d+\.", text)]
            if [k for k, v in value.items() if v == "true"] != [str(i + 1) for i, r in enumerate(numbered) if r == "true"]:
                raise SystemExit("question.html's checkboxes are not the key")
        else:  # pl-string-input: the key as the answer panel shows it (exact forms, `none`)
            text = data["correct_answers"][name]
            if mode == "wrong" and isinstance(value, (int, float)) and not isinstance(value, bool):
                text, changed = str(value + 1000), True
            submitted[name] = raw[name] = text
    if mode == "unreadable":  # a list that does not close, or a nested mapping where words belong
        kinds = params["inputs"]
        name = next(iter(kinds))
        raw[name] = submitted[name] = ["z"] if kinds[name] == "checkbox" else "{0-1: {x: y}}" if kinds[name] == "string" else "[1, 2"
    root = os.path.join(work, "grade")
    os.makedirs(os.path.join(root, "data"), exist_ok=True)
    json.dump({"params": params, "correct_answers": data["correct_answers"], "submitted_answers": submitted,
               "raw_submitted_answers": raw}, open(os.path.join(root, "data", "data.json"), "w"))
    results = os.path.join(root, "results", "results.json")
    if os.path.exists(results):
        os.remove(results)
    if in_process:  # the grader's own script, run as its own __main__ without a second interpreter
        os.environ.update(GRADE_ROOT=root, FRUSTUM=frustum)
        try:
            runpy.run_path(grader, run_name="__main__")
        except SystemExit as e:
            if e.code not in (0, None):
                raise
    else:
        subprocess.run([sys.executable, grader], check=True, env=dict(os.environ, GRADE_ROOT=root, FRUSTUM=frustum))
    r = json.load(open(results))
    return r, changed


# play.py WORK FRUSTUM GRADER QUESTION MODE SEED: one submission through the grader as
# PrairieLearn runs it (its own process), printing {gradable, score[, changed]}.
# play.py WORK FRUSTUM GRADER --many SCHEMA JOB...: each JOB is MODE:SEED:QUESTION, the grader
# run in this process (one interpreter for all: Python's start-up is most of a run), and each
# results.json checked against SCHEMA; prints a JSON line per job with the schema's errors.
work, frustum, grader = sys.argv[1:4]
if sys.argv[4] != "--many":
    question, mode, seed = sys.argv[4], sys.argv[5], int(sys.argv[6])
    r, changed = play(work, frustum, grader, question, mode, seed, False)
    out = {"gradable": r.get("gradable"), "score": r.get("score")}
    if mode == "wrong":
        out["changed"] = changed
    print(json.dumps(out))
    sys.exit(0)
import jsonschema
validator = jsonschema.Draft202012Validator(json.load(open(sys.argv[5], encoding="utf-8")))
for job in sys.argv[6:]:
    mode, seed, question = job.split(":", 2)
    try:
        r, changed = play(work, frustum, grader, question, mode, int(seed), True)
    except SystemExit as e:
        print(json.dumps({"job": job, "failed": str(e.code)}))
        continue
    errors = ["/".join(map(str, e.absolute_path)) + ": " + e.message for e in validator.iter_errors(r)]
    print(json.dumps({"job": job, "mode": mode, "gradable": r.get("gradable"), "score": r.get("score"),
                      "changed": changed, "errors": errors}))
PY
grader=$src/tools/prairielearn/frustum-pl-grade
jobs=()
for q in "$work"/pl/*/ "$work"/pl-ja/*/; do
  jobs+=("right:1:$q" "right:2:$q" "wrong:1:$q" "unreadable:1:$q")
done
python3 "$work/play.py" "$work" "$frustum" "$grader" --many "$here/prairielearn_results.schema.json" "${jobs[@]}" > "$work/played.jsonl"
read -r all_right all_wrong all_invalid graded wrongs < <(python3 - "$work/played.jsonl" <<'PY'
import json, sys
right = wrong = invalid = 1
graded = wrongs = 0
for line in open(sys.argv[1], encoding="utf-8"):
    r = json.loads(line)
    bad = r.get("failed") or r["errors"]
    if r.get("failed"):
        print("  FAILED:", r["job"], r["failed"], file=sys.stderr)
    elif r["errors"]:
        print("  results.json of", r["job"], "breaks the schema:", r["errors"], file=sys.stderr)
    mode = r["job"].split(":")[0]
    if mode == "right":
        graded += not bad
        if bad or (r["gradable"], r["score"]) != (True, 1.0):
            print("  right answers:", line.strip(), file=sys.stderr)
            right = 0
    elif mode == "wrong" and (bad or r["changed"]):  # some number was moved
        wrongs += 1
        if bad or not (r["gradable"] and r["score"] < 1):
            print("  wrong numbers:", line.strip(), file=sys.stderr)
            wrong = 0
    elif mode == "unreadable" and (bad or (r["gradable"], r["score"]) != (False, None)):
        print("  unreadable:", line.strip(), file=sys.stderr)
        invalid = 0
print(right, wrong, invalid, graded, wrongs)
PY
)
check "PrairieLearn: the key as typed (exact forms, none), as the elements submit it, earns 1.0 ($graded variants)" test $all_right = 1 -a $graded -gt 20
check "PrairieLearn: numbers off by 1000 lose points ($wrongs questions)" test $all_wrong = 1 -a $wrongs -gt 5
check "PrairieLearn: an unreadable answer is not gradable (no attempt charged)" test $all_invalid = 1
# The feedback: HTML with MathJax-delimited formulas for the submission panel, no Markdown or
# $$ in the grader-results element's <pre> fields, and in the export's language.
python3 "$work/play.py" "$work" "$frustum" "$grader" "$(ls -d "$work"/pl-ja/*culling-statements*/)" right 1 >/dev/null
check "PrairieLearn: a --lang ja export grades with Japanese feedback" \
  grep -q '得点\|正解' "$work/grade/results/results.json"
# Its words are the student's (表, 裏, 真横), its inputs captioned by their symbols, and the
# word a student picks is read back by the grader.
backface_ja=$(ls -d "$work"/pl-ja/*backface*/ | head -1)
check "PrairieLearn: a --lang ja export shows the facing choices in Japanese and captions inputs by their symbols" \
  bash -c 'grep -q ">裏</pl-answer>" "$1" && grep -q "label=\"D_f =\"" "$1"' _ "$backface_ja/question.html"
python3 "$work/play.py" "$work" "$frustum" "$grader" "$backface_ja" right 1 >/dev/null
check "PrairieLearn: the Japanese word picked (裏) earns its points" python3 - "$work/grade/results/results.json" <<'PY'
import json, sys
sys.exit(0 if json.load(open(sys.argv[1])).get("score") == 1.0 else 1)
PY
python3 "$work/play.py" "$work" "$frustum" "$grader" "$(ls -d "$work"/pl/001_*zbuf*/ | head -1)" wrong 1 >/dev/null
check "PrairieLearn: feedback is HTML in frustum_html, no Markdown or \$\$ in the <pre> fields" python3 - "$work/grade/results/results.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
pre = json.dumps([r.get("message"), r.get("output")] + [[t.get("message"), t.get("output")] for t in r.get("tests", [])])
ok = "$$" not in pre and "| ---" not in pre and "**" not in pre
ok = ok and "<table>" in r.get("frustum_html", "") and "Expected" not in r["frustum_html"]
sys.exit(0 if ok else 1)
PY

# Hostile text in a string answer: an alias bomb is refused before it is expanded (expanded, it
# would make an answers file of hundreds of megabytes), an oversized submission is not
# gradable, and the grader's temporary folder is removed whatever happens (TMPDIR is checked
# empty after each run).
cat > "$work/hostile.py" <<'PY'
import json, os, subprocess, sys
root, frustum, grader, set_file, case = sys.argv[1:6]
os.makedirs(os.path.join(root, "data"), exist_ok=True)
results = os.path.join(root, "results", "results.json")
if os.path.exists(results):
    os.remove(results)
bomb = "[&a [x, x, x, x, x, x, x, x, x], &b [*a, *a, *a, *a, *a, *a, *a, *a, *a], " + \
       ", ".join(f"&{c} [" + ", ".join([f"*{p}"] * 9) + "]" for p, c in zip("bcdefgh", "cdefghi")) + "]"
raw = {"bomb": {"silhouette": bomb}, "huge": {"silhouette": "[" + "1-4, " * 300000 + "1-4]"},
       "anchor": {"silhouette": "[&a 1-4, 1-6]"}, "plain": {"silhouette": "[1-4, 1-6]"}}[case]
params = {"set": open(set_file, encoding="utf-8").read(), "problem": "seed003-ico-silhouette",
          "inputs": {"silhouette": "string"}}
json.dump({"params": params, "submitted_answers": {}, "raw_submitted_answers": raw},
          open(os.path.join(root, "data", "data.json"), "w"))
subprocess.run([sys.executable, grader], check=True, timeout=120,
               env=dict(os.environ, GRADE_ROOT=root, FRUSTUM=frustum, TMPDIR=os.path.join(root, "tmp")))
r = json.load(open(results))
left = os.listdir(os.path.join(root, "tmp"))
print(json.dumps({"gradable": r.get("gradable"), "left": left,
                  "size": os.path.getsize(results), "message": r.get("message", "")[:200]}))
PY
hostile() { rm -rf "$work/hostile" && mkdir -p "$work/hostile/tmp" &&
  python3 "$work/hostile.py" "$work/hostile" "$frustum" "$grader" "$src/problems/seeds/003_polygons_backface.yaml" "$1"; }
# DESCRIPTION CASE CONDITION: the CONDITION (Python, on the result r) holds after the grader ran.
hostile_check() {
  local r
  r=$(hostile "$2")
  check "PrairieLearn: $1" python3 -c "import json,sys; r=json.loads(sys.argv[1]); sys.exit(0 if ($3) else 1)" "$r"
  echo "  $2: $r"
}
# Read as written, the bomb and the anchor are not edge lists: unparseable answers, which
# PrairieLearn shows as format errors that cost no attempt.
hostile_check "an alias bomb in a string answer is read as written, not expanded" bomb \
  "r['gradable'] is False and 'could not be read' in r['message'] and r['left'] == [] and r['size'] < 100000"
hostile_check "an anchor in a string answer is refused, and the folder removed" anchor \
  "r['gradable'] is False and 'could not be read' in r['message'] and r['left'] == []"
hostile_check "a 1.5 MB answer is not gradable, naming the limit, and the folder removed" huge \
  "r['gradable'] is False and '1048576 bytes' in r['message'] and r['left'] == []"
hostile_check "a plain label list still grades, and the folder is removed" plain \
  "r['gradable'] is True and r['left'] == []"

# --- Canvas QTI and Moodle XML ------------------------------------------------------------
for set in 001_zbuffer_plane_method 003_polygons_backface 004_placing_and_projecting; do
  "$frustum" export qti "$src/problems/seeds/$set.yaml" --count 2 -o "$work/qti-$set" >/dev/null 2>&1
  "$frustum" export moodle "$src/problems/seeds/$set.yaml" --count 3 -o "$work/moodle-$set.xml" >/dev/null 2>&1
done
check "QTI assessments validate against the QTI 1.2 schema" \
  xmllint --noout --schema "$here/schemas/qti_1p2_subset.xsd" "$work"/qti-*/frustum_*.xml
check "QTI manifests are well-formed and list the one assessment" \
  python3 - "$work" <<'PY'
import glob, os, sys, xml.etree.ElementTree as ET
ok = True
for manifest in glob.glob(os.path.join(sys.argv[1], "qti-*", "imsmanifest.xml")):
    hrefs = {r.get("href") for r in ET.parse(manifest).getroot().iter("{http://www.imsglobal.org/xsd/imscp_v1p1}resource")}
    files = {os.path.basename(f) for f in glob.glob(os.path.join(os.path.dirname(manifest), "frustum_*.xml"))}
    ok = ok and hrefs == files and len(files) == 1
sys.exit(0 if ok else 1)
PY
# As Canvas's QTI importer reads a question group (qti_exporter's assessment_test_converter:
# a section whose selection picks a count, its points per item, the items in it): every
# problem of a two-variant export is a group picking 1 of its 2 items, worth its points.
check "QTI: each problem is a Canvas question group drawing 1 of its variants" \
  python3 - "$work" <<'PY'
import glob, os, sys, xml.etree.ElementTree as ET
ns = "{http://www.imsglobal.org/xsd/ims_qtiasiv1p2}"
ok, groups = True, 0
for f in glob.glob(os.path.join(sys.argv[1], "qti-*", "frustum_*.xml")):
    root = ET.parse(f).getroot().find(ns + "assessment").find(ns + "section")
    for g in root.findall(ns + "section"):
        groups += 1
        sel = g.find(f"{ns}selection_ordering/{ns}selection")
        items = g.findall(ns + "item")
        points = float(sel.find(f"{ns}selection_extension/{ns}points_per_item").text)
        ok = ok and sel.find(ns + "selection_number").text == "1" and len(items) == 2 and points > 0
        for item in items:
            meta = {m.find(ns + "fieldlabel").text: m.find(ns + "fieldentry").text
                    for m in item.iter(ns + "qtimetadatafield")}
            ok = ok and float(meta["points_possible"]) == points
    ok = ok and not root.findall(ns + "item")  # every item is in its problem's group
sys.exit(0 if ok and groups >= 6 else 1)
PY
check "Moodle XML validates against the Moodle XML schema" \
  xmllint --noout --schema "$here/schemas/moodle_xml_subset.xsd" "$work"/moodle-*.xml
# Every numeric field's range is the grader's window: value ± window graded by Frustum.
check "Moodle Cloze fields are well formed; tolerances positive (zero only where the grader wants an exact zero)" python3 - "$work" <<'PY'
import glob, os, re, sys
ok, n = True, 0
for f in glob.glob(os.path.join(sys.argv[1], "moodle-*.xml")):
    text = open(f, encoding="utf-8").read()
    for m in re.finditer(r"\{(\d+):(NUMERICAL|MULTICHOICE|SHORTANSWER):([^}]*)\}", text):
        n += 1
        if m.group(2) == "NUMERICAL":
            value, tol = m.group(3).lstrip("=").split(":")
            ok = ok and (float(tol) > 0 or float(value) == 0) and float(tol) < abs(float(value)) + 1
        elif m.group(2) == "MULTICHOICE":
            ok = ok and m.group(3).count("=") == 1
    ok = ok and text.count("{") == text.count("}")
sys.exit(0 if ok and n > 50 else 1)
PY

# --- Gradebooks ---------------------------------------------------------------------------
mkdir -p "$work/class"
cp "$src/problems/seeds/answers/003_polygons_backface.yaml" "$work/class/a.yaml"
sed 's/^student: .*/student: s2/; s/D_f: -2/D_f: 5/' "$src/problems/seeds/answers/003_polygons_backface.yaml" > "$work/class/b.yaml"
printf 'student: s3\nanswers: [broken\n' > "$work/class/c.yaml"
"$frustum" grade "$src/problems/seeds/003_polygons_backface.yaml" "$work/class" -o "$work/grades" >/dev/null 2>&1 || true
"$frustum" export canvas-grades "$work/grades/gradebook.csv" --assignment "Homework 3" -o "$work/canvas.csv"
"$frustum" export moodle-grades "$work/grades/gradebook.csv" --assignment "Homework 3" -o "$work/moodle.csv"
check "Canvas CSV: the import columns, Points Possible, one row per student" python3 - "$work" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1] + "/canvas.csv", encoding="utf-8")))
book = {r[0]: r for r in csv.reader(open(sys.argv[1] + "/grades/gradebook.csv", encoding="utf-8"))}
ok = rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Homework 3"]
ok = ok and rows[1][0] == "Points Possible" and rows[1][5] == book["seed003-published"][2]
by_id = {r[2]: r[5] for r in rows[2:]}
ok = ok and by_id.get("seed003-published") == book["seed003-published"][1]
ok = ok and by_id.get("s3", "") == ""  # not graded: left empty, never a zero
sys.exit(0 if ok else 1)
PY
check "Moodle CSV: ID number and the grade column" \
  grep -q '^seed003-published,' <(tail -n +2 "$work/moodle.csv")
printf 'student,score,max_score,percent,status\na,1,2,50,graded\na,2,2,100,graded\n' > "$work/twice.csv"
check "a student with two rows is refused, naming the line" \
  grep -q "twice.csv:3:1: student: student 'a' is also on line 2" <("$frustum" export canvas-grades "$work/twice.csv" 2>&1 || true)

echo "$failures failed"
[ "$failures" -eq 0 ]
