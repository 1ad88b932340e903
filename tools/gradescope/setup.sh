#!/usr/bin/env bash
# Gradescope autograder set-up: runs once, as root, when the autograder image is built.
# The bundle (make_bundle.sh) puts Frustum's sources in /autograder/source.
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends build-essential cmake ninja-build pkg-config \
  libeigen3-dev libyaml-cpp-dev libfmt-dev libginac-dev libcln-dev libcli11-dev nlohmann-json3-dev
cd /autograder/source
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DFRUSTUM_TESTS=OFF -DFRUSTUM_BENCH=OFF
cmake --build build --target frustum --parallel "$(nproc)"
