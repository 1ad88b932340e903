#!/usr/bin/env bash
# Packaging, end to end (CI, as root): `cmake --install` into a scratch prefix installs the
# binary, the man pages and bash completion; `cpack -G DEB` builds the .deb; dpkg -i installs it
# on this machine; the installed frustum solves and grades a seed set, its man pages open and
# its completion answers. The package is removed again unless it was installed before.
# Usage: deb_install_test.sh BUILD_DIR
set -euo pipefail
build=$(cd "${1:-build}" && pwd)
src=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
work=$(mktemp -d)
was_installed=$(dpkg-query -W -f='${Status}' frustum 2>/dev/null | grep -c "install ok installed" || true)
cleanup() {
  [ "$was_installed" = 1 ] || dpkg -r frustum >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
failures=0
check() {
  if "${@:2}"; then echo "ok: $1"; else echo "FAILED: $1"; failures=$((failures + 1)); fi
}
version=$(sed -n 's/^CMAKE_PROJECT_VERSION:STATIC=//p' "$build/CMakeCache.txt")

cmake --build "$build" --target frustum man >/dev/null
cmake --install "$build" --prefix "$work/prefix" >/dev/null
check "cmake --install: the binary" test -x "$work/prefix/bin/frustum"
check "cmake --install: a man page per subcommand" \
  test "$(ls "$work/prefix/share/man/man1" | grep -c '^frustum.*\.1\.gz$')" -ge 10
check "cmake --install: bash completion" test -f "$work/prefix/share/bash-completion/completions/frustum"

(cd "$build" && cpack -G DEB -B "$work/deb" >/dev/null)
deb=$(ls "$work/deb"/frustum_"$version"_*.deb)
check "the .deb depends on the shared libraries it links" grep -q "libginac" <(dpkg-deb -f "$deb" Depends)
check "the .deb suggests TeX, KaTeX and CodeMirror" grep -q "texlive-latex-base.*libjs-katex.*libjs-codemirror" <(dpkg-deb -f "$deb" Suggests)
check "the .deb has its copyright file" grep -q "./usr/share/doc/frustum/copyright$" <(dpkg-deb -c "$deb")
dpkg -i "$deb" >/dev/null || apt-get install -f -y -qq >/dev/null
check "dpkg -i installed frustum $version" test "$(dpkg-query -W -f='${Version}' frustum)" = "$version"
check "/usr/bin/frustum --version" test "$(/usr/bin/frustum --version)" = "frustum $version"
cd "$work"  # nothing from the source tree on the path
/usr/bin/frustum solve "$src/problems/seeds/001_zbuffer_plane_method.yaml" --id seed001-pixel-z --format json > solved.json
check "the installed frustum solves seed 001 (z = 8)" \
  test "$(python3 -c 'import json; print(json.load(open("solved.json"))["problems"][0]["answers"]["z"]["value"])')" = 8
/usr/bin/frustum solve "$src/problems/seeds" > seeds.txt
check "the installed frustum solves every seed set" grep -q "D_f = −2" seeds.txt
check "the installed frustum grades the published answers fully" \
  grep -q "^Student seed003-published: \([0-9.]*\) / \1$" <(/usr/bin/frustum grade --lang en "$src/problems/seeds/003_polygons_backface.yaml" \
                                                            "$src/problems/seeds/answers/003_polygons_backface.yaml")
check "man frustum-grade is installed" grep -q "^frustum-grade " <(zcat /usr/share/man/man1/frustum-grade.1.gz | grep -A1 "^.SH NAME" | tail -1)
complete_words() {  # complete_words WORD...: what bash completion offers for the last word
  bash -c 'source /usr/share/bash-completion/bash_completion
           source /usr/share/bash-completion/completions/frustum
           COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); COMP_LINE="$*"; COMP_POINT=${#COMP_LINE}
           _frustum; echo "${COMPREPLY[*]}"' _ "$@"
}
check "completion: subcommands" test "$(complete_words frustum so)" = "solve"
check "completion: options" grep -qw -- "--precision" <(complete_words frustum solve --p)
check "completion: a choice's words" test "$(complete_words frustum solve x.yaml --format '')" = "text markdown json html latex"
check "completion: a positional's words (export's formats)" \
  test "$(complete_words frustum export '')" = "prairielearn qti moodle canvas-grades moodle-grades"
echo "$failures failed"
[ "$failures" -eq 0 ]
