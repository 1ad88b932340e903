# Sourced by tools/performance.sh and tools/accuracy.sh: from the repository root, configures
# $BUILD (default build/, Release with the benchmarks) when it does not exist yet and builds
# frustum, frustum_bench and (with OSMesa) frustum_race in it.
BUILD=${BUILD:-build}
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFRUSTUM_BENCH=ON
fi
targets=(frustum frustum_bench)
if cmake --build "$BUILD" --target help | grep -q '^frustum_race:'; then targets+=(frustum_race); fi
cmake --build "$BUILD" -j"$(nproc)" --target "${targets[@]}"
