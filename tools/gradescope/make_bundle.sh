#!/usr/bin/env bash
# Builds autograder.zip for Gradescope ("Zip file upload" autograder):
#   tools/gradescope/make_bundle.sh problems/seeds/001_zbuffer_plane_method.yaml [ja] [out.zip]
# The zip holds setup.sh and run_autograder at its root and Frustum's sources in source/
# (the set and the feedback language recorded in source/autograder.conf).
set -euo pipefail
set_file=${1:?usage: make_bundle.sh SET.yaml [en|ja] [autograder.zip]}
lang=${2:-en}
out=$(realpath -m "${3:-autograder.zip}")
root=$(cd "$(dirname "$0")/../.." && pwd)
[ -f "$root/$set_file" ] || { echo "make_bundle: $set_file is not a file under $root" >&2; exit 1; }
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/source"
(cd "$root" && git ls-files -z | xargs -0 cp --parents -t "$stage/source")
printf 'SET=%q\nLANG_FEEDBACK=%q\n' "$set_file" "$lang" > "$stage/source/autograder.conf"
cp "$root/tools/gradescope/setup.sh" "$root/tools/gradescope/run_autograder" "$stage/"
chmod +x "$stage/setup.sh" "$stage/run_autograder"
rm -f "$out"
(cd "$stage" && python3 -m zipfile -c "$out" setup.sh run_autograder source >/dev/null)
echo "wrote $out"
