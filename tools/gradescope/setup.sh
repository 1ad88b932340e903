#!/usr/bin/env bash
# Gradescope autograder set-up: runs once, as root, when the autograder image is built, from
# the unpacked bundle (/autograder/source). Installs the packages of frustum/tools/packages/
# build.txt (the list tools/setup.sh installs too) and builds only the `frustum` binary, into
# build/ beside this script (or takes FRUSTUM_SETUP_BINARY, one built from these sources).
# Warnings do not stop this build (-Werror is for developers: GCC 12 at -O3 reports a false
# -Wrestrict inside libstdc++).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bash "$here/frustum/tools/packages/install.sh" "$here/frustum/tools/packages/build.txt"
cmake -S "$here/frustum" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
      -DFRUSTUM_TESTS=OFF -DFRUSTUM_BENCH=OFF -DFRUSTUM_WERROR=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
if [ -n "${FRUSTUM_SETUP_BINARY:-}" ]; then
  # A frustum built already from these very sources on this system (an image builder that
  # builds once for several bundles; Frustum's own CI test of this script): used as it is.
  install -m 0755 "$FRUSTUM_SETUP_BINARY" "$here/build/frustum"
else
  cmake --build "$here/build" --target frustum --parallel "$(nproc)"
fi
"$here/build/frustum" check "$here/$(. "$here/autograder.conf" && echo "$SET")"
