#!/usr/bin/env bash
# Installs what is missing (Debian 12, as root), then configures and builds Frustum in build/.
#   bash tools/setup.sh           what building and running need (tools/packages/build.txt)
#   bash tools/setup.sh --tests   also the test, benchmark and packaging tools
#                                 (tools/packages/test.txt) and the whole suite's targets
# Used by the README's two quick-start commands and by CI (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."

lists=(tools/packages/build.txt)
options=()
case "${1:-}" in
  "") ;;
  --tests)
    lists+=(tools/packages/test.txt)
    options=(-DFRUSTUM_TESTS=ON -DFRUSTUM_BENCH=ON -DFRUSTUM_PLATFORM_TESTS=ON)
    ;;
  *) echo "usage: tools/setup.sh [--tests]" >&2; exit 2 ;;
esac
bash tools/packages/install.sh "${lists[@]}"
if [ "${1:-}" = --tests ]; then
  # playwright-core drives Debian's chromium in the served pages' browser test; it never
  # downloads a browser (and the variable says so to any package that would).
  # Debian's nodejs comes without npm (its own package); a Node.js that brings npm is kept.
  command -v npm >/dev/null || bash tools/packages/install.sh tools/packages/npm.txt
  (cd tests/browser && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund)
fi

# Optimised, with line tables and function names (-g1): a crash's backtrace names its files and
# lines, and the compile skips the full debug information (types, variables) that only a
# debugger reads (a fifth to a quarter of each file's compile time). For a debugger session,
# configure another directory with the default flags (-g).
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" "${options[@]}" >/dev/null
cmake --build build --parallel "$(nproc)"
