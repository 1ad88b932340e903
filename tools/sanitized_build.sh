# Sourced by tools/sanitize.sh and tools/fuzz.sh: configures build-fuzz/, the one sanitized build
# (clang, AddressSanitizer + UBSan, libFuzzer's coverage in the libraries, the tests and the fuzz
# targets). Both scripts configure it the same way, so neither makes the other recompile, and CI
# compiles the sanitized libraries once for the sanitized suite and the fuzzers (it compiled
# them twice, with GCC and clang, until 2026-12-02). Outside a fuzz target the coverage hooks
# are the sanitizer runtime's empty defaults. The normal build (tools/setup.sh) is GCC's, so the
# suite runs under both compilers.
SANITIZED_BUILD=build-fuzz
sanitized_launcher=()
command -v ccache >/dev/null && sanitized_launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# Line tables only (-gline-tables-only): a sanitizer's report names every frame's file and line
# as with -g, and the build skips the full debug information (types, variables) that only a
# debugger reads, the larger part of its compile and link time.
cmake -S . -B "$SANITIZED_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
      -DCMAKE_CXX_COMPILER=clang++ -DFRUSTUM_SANITIZE=ON -DFRUSTUM_FUZZ=ON -DFRUSTUM_TESTS=ON \
      "${sanitized_launcher[@]}" >/dev/null
