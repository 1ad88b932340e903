#!/usr/bin/env bash
# Builds autograder.zip for Gradescope's "Zip file upload" autograder from any problem set
# (tracked by git or not) and, optionally, the per-student sets `frustum generate -o DIR` wrote:
#   tools/gradescope/make_bundle.sh SET.yaml [--variants DIR] [--lang en|ja|ru]
#                                   [--identity sid|email|id] [--visibility WHEN] [-o autograder.zip]
# The zip's root holds setup.sh, run_autograder, autograder.conf, frustum/ (the sources the
# `frustum` binary is built from) and assignment/ (the set, and the variants in variants/).
# --identity: with per-student sets, check that the answers' `student:` is the Gradescope
# submitter's student id (sid) or e-mail, so nobody is graded against another student's set.
# --visibility: when students see each problem's feedback (expected answers and derivations):
# visible (default), after_due_date, after_published or hidden. Gradescope hides a submission's
# total score while any of its tests is hidden (its autograder specification), so the score is
# held back with the feedback: shown after the due date, when grades are published, or never.
set -euo pipefail
usage() { echo "usage: make_bundle.sh SET.yaml [--variants DIR] [--lang en|ja|ru] [--identity sid|email|id] [--visibility WHEN] [-o autograder.zip]" >&2; exit 2; }
root=$(cd "$(dirname "$0")/../.." && pwd)
set_file= variants= lang=en identity= visibility=visible out=autograder.zip positional=()
while [ $# -gt 0 ]; do
  case "$1" in
    --variants) variants=${2:?--variants needs a directory}; shift 2 ;;
    --lang) lang=${2:?--lang needs en, ja or ru}; shift 2 ;;
    --identity) identity=${2:?--identity needs sid, email or id}; shift 2 ;;
    --visibility) visibility=${2:?--visibility needs visible, after_due_date, after_published or hidden}; shift 2 ;;
    -o|--output) out=${2:?-o needs a file name}; shift 2 ;;
    -h|--help) usage ;;
    -*) echo "make_bundle: unknown option $1" >&2; usage ;;
    *) positional+=("$1"); shift ;;
  esac
done
# The older form `make_bundle.sh SET [LANG] [OUT]` still works.
[ ${#positional[@]} -ge 1 ] || usage
set_file=${positional[0]}
[ ${#positional[@]} -ge 2 ] && lang=${positional[1]}
[ ${#positional[@]} -ge 3 ] && out=${positional[2]}
[ ${#positional[@]} -le 3 ] || usage
case "$lang" in en|ja|ru) ;; *) echo "make_bundle: --lang must be en, ja or ru, not '$lang'" >&2; exit 2 ;; esac
case "$identity" in ""|sid|email|id) ;; *) echo "make_bundle: --identity must be sid, email or id, not '$identity'" >&2; exit 2 ;; esac
case "$visibility" in visible|after_due_date|after_published|hidden) ;;
  *) echo "make_bundle: --visibility must be visible, after_due_date, after_published or hidden, not '$visibility'" >&2; exit 2 ;; esac
[ -f "$set_file" ] || { echo "make_bundle: $set_file: no such file" >&2; exit 1; }
[ -z "$variants" ] || [ -d "$variants" ] || { echo "make_bundle: $variants: no such directory" >&2; exit 1; }
out=$(realpath -m "$out")
# zipfile would end in a traceback: say which directory is missing instead.
[ -d "$(dirname "$out")" ] || { echo "make_bundle: $(dirname "$out"): no such directory (for -o $out); create it first" >&2; exit 1; }
[ ! -d "$out" ] || { echo "make_bundle: -o $out is a directory; give the zip's file name" >&2; exit 1; }
set_name=$(basename "$set_file")
stem=${set_name%.*}

# A set with errors would give every submission 0: check it (and each variant) first when a
# built frustum is at hand.
frustum=$root/build/frustum
[ -x "$frustum" ] || frustum=$(command -v frustum || true)
if [ -n "$frustum" ]; then
  "$frustum" check "$set_file" >/dev/null || { echo "make_bundle: $set_file has errors (frustum check $set_file)" >&2; exit 1; }
fi

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
# The sources of the `frustum` target: the top CMakeLists.txt and the directories it builds from.
mkdir -p "$stage/frustum/tools" "$stage/assignment"
for part in CMakeLists.txt app bench grader report batch export server solver; do
  [ -e "$root/$part" ] && cp -R "$root/$part" "$stage/frustum/"
done
cp -R "$root/tools/packages" "$stage/frustum/tools/"
cp "$set_file" "$stage/assignment/$set_name"
variants_conf=
if [ -n "$variants" ]; then
  shopt -s nullglob
  files=("$variants/$stem"-*.yaml)
  shopt -u nullglob
  [ ${#files[@]} -gt 0 ] || { echo "make_bundle: $variants has no $stem-*.yaml (frustum generate $set_file ... -o $variants)" >&2; exit 1; }
  mkdir -p "$stage/assignment/variants"
  for f in "${files[@]}"; do
    if [ -n "$frustum" ]; then
      "$frustum" check "$f" >/dev/null || { echo "make_bundle: $f has errors (frustum check $f)" >&2; exit 1; }
    fi
    cp "$f" "$stage/assignment/variants/"
  done
  variants_conf=assignment/variants
  echo "make_bundle: ${#files[@]} per-student sets from $variants"
fi
printf 'SET=%q\nVARIANTS=%q\nLANG_FEEDBACK=%q\nIDENTITY=%q\nVISIBILITY=%q\n' \
  "assignment/$set_name" "$variants_conf" "$lang" "$identity" "$visibility" > "$stage/autograder.conf"
cp "$root/tools/gradescope/setup.sh" "$root/tools/gradescope/run_autograder" "$stage/"
chmod +x "$stage/setup.sh" "$stage/run_autograder"
rm -f "$out"
(cd "$stage" && python3 -m zipfile -c "$out" setup.sh run_autograder autograder.conf frustum assignment >/dev/null)
echo "wrote $out"
