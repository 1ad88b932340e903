# Sourced by tools/performance.sh and tools/accuracy.sh: from the repository root, configures
# $BUILD (default build/, Release with the benchmarks) when it does not exist yet and builds
# frustum and frustum_bench in it.
BUILD=${BUILD:-build}
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DFRUSTUM_BENCH=ON
fi
cmake --build "$BUILD" -j"$(nproc)" --target frustum frustum_bench
