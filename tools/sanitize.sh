#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer + UBSan (build-asan/) and runs it. Any
# memory error, leak or undefined behaviour aborts the test that caused it.
set -euo pipefail
cd "$(dirname "$0")/.."

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFRUSTUM_SANITIZE=ON \
      "${launcher[@]}" >/dev/null
cmake --build build-asan --parallel "$(nproc)" --target frustum_tests frustum
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The benchmarks (label bench: the llvmpipe race) are not built here.
ctest --test-dir build-asan --output-on-failure --parallel "$(nproc)" -LE bench
