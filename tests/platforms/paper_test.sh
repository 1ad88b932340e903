#!/usr/bin/env bash
# The paper route, compiled with Debian's TeX: `frustum generate --format pdf` for a class of
# three and for drawn variants of every problem in the bundled sets (texts dropped there: they
# are compiled with pdflatex), checking that each PDF has a sheet per student and that figures
# are drawn; and a Japanese set's exam sheets and key, set for LuaLaTeX with luatexja
# (texlive-lang-japanese, in tools/packages/test.txt) and compiled.
# Usage: paper_test.sh SOURCE_DIR FRUSTUM_BINARY
set -euo pipefail
src=$(cd "$1" && pwd)
frustum=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() {
  if "${@:2}"; then echo "ok: $1"; else echo "FAILED: $1"; failures=$((failures + 1)); fi
}
pages() { sed -n 's/^Output written on .* (\([0-9]*\) pages\?,.*/\1/p' "$1"; }

cat > "$work/hw.yaml" <<'YAML'
title: "Homework 3: clipping, pixels & depth"
variants: per_student
problems:
  - id: clip
    kind: clip_line
    text: "Clip the segment PQ against the window [{window.xmin}, {window.xmax}] × [{window.ymin}, {window.ymax}] (Cohen–Sutherland); 100% of the steps."
    given: {p: [-2, 5], q: [3, 1], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 4}}
  - {id: poly, kind: clip_polygon, given: {points: [[-1, 1], [3, 1], [3, 5]], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 4}}}
  - {id: raster, kind: scan_convert, given: {triangle: [[0.5, 0.5], [5.5, 1.5], [2.5, 4.5]]}}
  - {id: depth, kind: depth_at_pixel, text: "Find z at pixel {pixel}.", given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}}
  - {id: zb, kind: zbuffer, given: {size: [4, 3], polygons: [{label: A, points: [[0, 0, 1], [4, 0, 1], [0, 3, 1]]}, {label: B, points: [[4, 3, 0.5], [0, 3, 2], [4, 0, 2]]}]}}
YAML
printf 'student\ns1\ns2\ns3\n' > "$work/roster.csv"
check "the homework set has no errors" "$frustum" check "$work/hw.yaml"
"$frustum" generate "$work/hw.yaml" --roster "$work/roster.csv" -o "$work/class" --format pdf > "$work/out.txt"
check "exams and key compiled" test -s "$work/class/hw-exams.pdf" -a -s "$work/class/hw-key.pdf"
check "a PDF file" grep -q '^%PDF' "$work/class/hw-exams.pdf"
check "one sheet per student (at least 3 pages each way)" \
  test "$(pages "$work/class/hw-exams.log")" -ge 3 -a "$(pages "$work/class/hw-key.log")" -ge 3
check "each student's sheet is there" test "$(grep -c 'section\*{Homework 3' "$work/class/hw-exams.tex")" = 3
check "figures for the five kinds that have one, per student" test "$(grep -c 'begin{tikzpicture}' "$work/class/hw-exams.tex")" = 15
check "the variant's values fill the text" grep -Eq 'Find z at pixel [[(][0-9]' "$work/class/hw-exams.tex"
check "the key gives every student's answers" test "$(grep -c 'texttt{z} (' "$work/class/hw-key.tex")" = 3
check "the generated sets are still written for grading" test -f "$work/class/hw-s1.yaml" -a -f "$work/class/answers/hw-s1.yaml"
# Grids on the picture's coordinates, givens as mathematics, problems kept whole.
check "every grid steps one unit of the picture (step=1), not TikZ's 1 cm" \
  test "$(grep -c ' grid (' "$work/class/hw-exams.tex")" = "$(grep -c 'step=1\]' "$work/class/hw-exams.tex")"
check "no raw YAML or bare xmin in the sheets (givens are typeset)" \
  test "$(grep -c 'xmin\|texttt{window\|{xmin' "$work/class/hw-exams.tex")" = 0
check "the window's bounds are typeset as x_min" grep -q 'x_{\\min} = 0' "$work/class/hw-exams.tex"
check "each problem is one unbreakable block with its figure and answer lines" \
  test "$(grep -c 'begin{minipage}' "$work/class/hw-exams.tex")" = 15
if command -v pdftotext >/dev/null && command -v pdftoppm >/dev/null; then
  # The pages as images (pdftoppm): a sheet's first page is drawn, not blank.
  pdftoppm -r 40 -f 1 -l 1 -png "$work/class/hw-exams.pdf" "$work/page" >/dev/null 2>&1 || true
  check "pdftoppm draws the first page" test -s "$(ls "$work"/page*.png 2>/dev/null | head -1)"
fi

# Every problem of the bundled sets, texts dropped, two drawn variants each: the key's steps
# cover every kind's derivation text.
python3 - "$src" "$work/all.yaml" <<'PY'
import glob, sys, yaml
src, out = sys.argv[1:]
problems = []
for f in sorted(glob.glob(src + "/problems/seeds/*.yaml") + glob.glob(src + "/problems/examples/*.yaml")):
    doc = yaml.load(open(f, encoding="utf-8"), Loader=yaml.BaseLoader)  # every scalar as text
    for p in doc.get("problems", []):
        p.pop("text", None)
        if "conventions" in doc:  # the set's course conventions (a left-handed set's points)
            p.setdefault("conventions", doc["conventions"])
        # A statements problem's givens are text in the set's language: Latin placeholders here
        # (pdflatex), as the texts are dropped; Japanese sets are checked to choose LuaLaTeX below.
        for i, st in enumerate(p.get("given", {}).get("statements", []) if p.get("kind") == "statements" else []):
            st["text"] = f"Statement {i + 1} of problem {len(problems)}."
            if "reason" in st:
                st["reason"] = f"Reason {i + 1}."
        p["id"] = f"{len(problems)}-{p['id']}"
        problems.append(p)
yaml.safe_dump({"title": "Every kind", "problems": problems}, open(out, "w", encoding="utf-8"), allow_unicode=True)
PY
"$frustum" generate "$work/all.yaml" --seed 4 --count 2 -o "$work/all" --format latex >/dev/null 2>&1
compile() { pdflatex -interaction=nonstopmode -halt-on-error -output-directory "$(dirname "$1")" "$1" >/dev/null; }
check "every kind's exam sheet compiles with pdflatex" compile "$work/all/all-exams.tex"
# Some steps gloss a term in Japanese (輪郭線): such a key is set for LuaLaTeX; the others compile here.
if head -1 "$work/all/all-key.tex" | grep -q Japanese; then
  check "a key with Japanese glosses is set for LuaLaTeX" grep -q 'usepackage{luatexja}' "$work/all/all-key.tex"
fi
python3 - "$work/all.yaml" "$work/latin.yaml" <<'PY'
import sys, yaml
doc = yaml.safe_load(open(sys.argv[1], encoding="utf-8"))
doc["problems"] = [p for p in doc["problems"] if p["kind"] not in ("edge_visibility",)]
yaml.safe_dump(doc, open(sys.argv[2], "w", encoding="utf-8"), allow_unicode=True)
PY
"$frustum" generate "$work/latin.yaml" --seed 4 --count 2 -o "$work/latin" --format pdf >/dev/null 2>&1 || true
check "the key of every other kind compiles with pdflatex" test -s "$work/latin/latin-key.pdf"
check "no character of any key or sheet lacks a LaTeX form" \
  test "$(cat "$work"/all/*.tex "$work"/latin/*.tex | grep -c 'unknownchar{[0-9A-F]')" = 0

"$frustum" generate "$src/problems/seeds/001_zbuffer_plane_method.yaml" --seed 1 --lang ja -o "$work/ja" --format latex >/dev/null 2>&1
check "a Japanese exam chooses LuaLaTeX with luatexja" grep -q 'usepackage{luatexja}' "$work/ja/001_zbuffer_plane_method-exams.tex"
check "a Japanese sheet's answer lines carry no English key (cross:, plane:)" \
  test "$(grep -c 'texttt{[a-z_]*}: \\hrulefill' "$work/ja/001_zbuffer_plane_method-exams.tex")" = 0
# And the Japanese PDFs themselves (texlive-lang-japanese): a sheet per student, the text set in
# Japanese (its words are in the PDF's text), the key with its Japanese steps.
"$frustum" generate "$src/problems/seeds/001_zbuffer_plane_method.yaml" --roster "$work/roster.csv" --lang ja -o "$work/japdf" --format pdf >/dev/null 2>&1 || true
check "the Japanese exam sheets compile with LuaLaTeX" test -s "$work/japdf/001_zbuffer_plane_method-exams.pdf"
check "the Japanese key compiles with LuaLaTeX" test -s "$work/japdf/001_zbuffer_plane_method-key.pdf"
# Russian: LuaLaTeX with a Cyrillic font (DejaVu), every letter kept (none shown as [U+XXXX]).
"$frustum" generate "$src/problems/seeds/001_zbuffer_plane_method.yaml" --roster "$work/roster.csv" --lang ru -o "$work/rupdf" --format pdf >/dev/null 2>&1 || true
check "the Russian exam sheets compile with LuaLaTeX" test -s "$work/rupdf/001_zbuffer_plane_method-exams.pdf"
check "the Russian key compiles with LuaLaTeX" test -s "$work/rupdf/001_zbuffer_plane_method-key.pdf"
check "no Cyrillic letter of the Russian sheets lacks a LaTeX form" \
  test "$(cat "$work"/rupdf/*.tex | grep -c 'unknownchar{04')" = 0
# A set's file name is only a name: one that would close a shell quote and run a command, and an
# apostrophe, compile as any other (the compiler runs from an argument vector, on a fixed name).
mkdir -p "$work/names"
cp "$src/problems/seeds/001_zbuffer_plane_method.yaml" "$work/names/w';touch HACKED;'.yaml"
cp "$src/problems/seeds/001_zbuffer_plane_method.yaml" "$work/names/O'Brien.yaml"
for name in "w';touch HACKED;'" "O'Brien"; do
  (cd "$work/names" && "$frustum" generate "$name.yaml" --seed 1 --count 2 -o "out $name" --format pdf >/dev/null 2>&1) || true
  check "a set named $name compiles to PDF" test -s "$work/names/out $name/$name-exams.pdf"
done
check "no command in a file name ran" test ! -e "$work/names/HACKED"
check "no compiler directory is left behind" test -z "$(find "$work/names" -name '.frustum-latex-*')"
pdf_has() {  # pdf_has PDF WORD: the PDF's extracted text holds WORD (read whole: no SIGPIPE)
  local text
  text=$(pdftotext "$1" -) && grep -q -- "$2" <<<"$text"
}
if command -v pdftotext >/dev/null; then
  check "the Japanese exam's text is Japanese in the PDF" \
    pdf_has "$work/japdf/001_zbuffer_plane_method-exams.pdf" '平面'
  check "the Russian exam's text is Russian in the PDF" \
    pdf_has "$work/rupdf/001_zbuffer_plane_method-exams.pdf" 'треугольника'
  check "the Russian key's steps are Russian in the PDF" \
    pdf_has "$work/rupdf/001_zbuffer_plane_method-key.pdf" 'Нормаль'
fi

echo "$failures failed"
[ "$failures" -eq 0 ]
