#!/usr/bin/env bash
# Installs what is missing (Debian 12, as root), then configures and builds Frustum in build/.
# Used by the README's two quick-start commands and by CI (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
          libeigen3-dev libyaml-cpp-dev libfmt-dev libginac-dev libcln-dev
          libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev
          libstb-dev libbenchmark-dev libosmesa6-dev
          clang libclang-rt-14-dev
          chromium libjs-katex nodejs texlive-luatex texlive-latex-recommended fonts-dejavu-core)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build --parallel "$(nproc)"
