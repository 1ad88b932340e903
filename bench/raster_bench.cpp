// Raster throughput at 1920 × 1080, single thread: (a) 100k small triangles, (b) 100 large
// ones, setup + coverage + depth test and write included; the same triangles through Mesa's
// llvmpipe (OSMesa, LP_NUM_THREADS as set by the caller) side by side, and after the timings a
// comparison of the two images: pixels whose winning triangle or depth differ. Not part of ctest.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>

#include "bench/bandwidth_ceiling.hpp"
#include "solver/raster/fill.hpp"

#ifdef FRUSTUM_HAVE_OSMESA
#include <GL/gl.h>
#include <GL/osmesa.h>
#endif

namespace frustum {
namespace {

constexpr int kWidth = kCeilingWidth, kHeight = kCeilingHeight;
constexpr int kSmallCount = 100000, kLargeCount = 100;

// Triangle k carries colour k + 1 (24 bits), so an image says which triangle won each pixel.
Rgb id_color(std::size_t k) {
  const auto v = static_cast<std::uint32_t>(k + 1);
  return {static_cast<std::uint8_t>(v & 0xff), static_cast<std::uint8_t>((v >> 8) & 0xff),
          static_cast<std::uint8_t>((v >> 16) & 0xff)};
}

// Rates are per second of process CPU time (MeasureProcessCPUTime): llvmpipe rasterizes on
// its own thread, and on a loaded machine wall time says little.
//
// Small: vertices within ±4 pixels of a random centre (mean area ≈ 9 pixels). Large:
// vertices anywhere on a 1.5× enlarged screen (mean ≈ 0.2 of the screen inside it).
std::vector<WindowTriangle> make_triangles(bool small, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(0, kWidth), y(0, kHeight), d(-4, 4), z(0.01, 0.99);
  std::uniform_real_distribution<double> bx(-0.25 * kWidth, 1.25 * kWidth),
      by(-0.25 * kHeight, 1.25 * kHeight);
  std::vector<WindowTriangle> out;
  const int n = small ? kSmallCount : kLargeCount;
  for (int k = 0; k < n; ++k) {
    WindowTriangle t;
    const double cx = x(rng), cy = y(rng);
    for (Vec3d& v : t.v) {
      v = small ? Vec3d(cx + d(rng), cy + d(rng), z(rng)) : Vec3d(bx(rng), by(rng), z(rng));
      // On the 1/256 grid, so both renderers snap to the same points.
      for (int a = 0; a < 2; ++a) v(a) = std::round(v(a) * 256) / 256;
    }
    t.color = id_color(static_cast<std::size_t>(k));
    out.push_back(t);
  }
  return out;
}

const std::vector<WindowTriangle>& triangles(bool small) {
  static const std::vector<WindowTriangle> s = make_triangles(true, 1),
                                           l = make_triangles(false, 2);
  return small ? s : l;
}

long covered_fragments(bool small) {
  static long counts[2] = {-1, -1};
  long& c = counts[small];
  if (c < 0) {
    FillStats st;
    render_zbuffer(triangles(small), kWidth, kHeight, {}, &st);
    c = st.fragments;
  }
  return c;
}

void report(benchmark::State& state, bool small) {
  const double frames = static_cast<double>(state.iterations());
  state.counters["tris/s"] = benchmark::Counter(
      frames * static_cast<double>(triangles(small).size()), benchmark::Counter::kIsRate);
  state.counters["pixels/s"] = benchmark::Counter(
      frames * static_cast<double>(covered_fragments(small)), benchmark::Counter::kIsRate);
}

// Setup alone: snapping, edge functions, bounding box and depth plane.
void BM_Setup(benchmark::State& state) {
  const std::vector<WindowTriangle>& tris = triangles(true);
  for (auto _ : state)
    for (std::size_t k = 0; k < tris.size(); ++k)
      benchmark::DoNotOptimize(setup_raster(tris[k], static_cast<int>(k)));
  state.counters["tris/s"] = benchmark::Counter(
      static_cast<double>(state.iterations() * tris.size()), benchmark::Counter::kIsRate);
}

// One frame: clear, then setup + fill every triangle (the clear is a small share).
void BM_Frustum(benchmark::State& state) {
  const bool small = state.range(0) != 0;
  const std::vector<WindowTriangle>& tris = triangles(small);
  Frame frame(kWidth, kHeight, {});
  for (auto _ : state) {
    std::fill(frame.depth.data.begin(), frame.depth.data.end(), kDepthClear);
    std::fill(frame.color.data.begin(), frame.color.data.end(), 0u);
    for (std::size_t k = 0; k < tris.size(); ++k)
      draw_triangle(setup_raster(tris[k], static_cast<int>(k)), frame);
    benchmark::DoNotOptimize(frame.color.data.data());
  }
  report(state, small);
}
// The bandwidth ceiling (bandwidth_ceiling.hpp) on the same buffers; tools/performance.sh prints
// fill's fraction of it.
void BM_BandwidthCeiling(benchmark::State& state) {
  Frame frame(kWidth, kHeight, {});
  std::uint32_t pass = 0;
  for (auto _ : state) {
    // Alternating slopes so that about half the fragments pass, as in a real frame.
    ++pass;
    depth_pass(frame.depth.data.data(), frame.color.data.data(), 0.5f,
               (pass % 2 ? -1.0f : 1.0f) * 1e-5f, pass);
    benchmark::ClobberMemory();
  }
  state.counters["pixels/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * kWidth * kHeight, benchmark::Counter::kIsRate);
  state.counters["bytes/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * kWidth * kHeight * 12.0,
                         benchmark::Counter::kIsRate, benchmark::Counter::kIs1024);
}
BENCHMARK(BM_BandwidthCeiling)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_Setup)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_Frustum)
    ->Arg(1)
    ->ArgName("small")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();
BENCHMARK(BM_Frustum)
    ->Arg(0)
    ->ArgName("small")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

#ifdef FRUSTUM_HAVE_OSMESA
// llvmpipe through OSMesa: identity matrices, vertices given in NDC so that its window
// coordinates and depth equal ours; flat colours, GL_LESS, depth cleared to 1.
struct Mesa {
  OSMesaContext ctx = nullptr;
  std::vector<std::uint32_t> color;
  std::vector<float> xyz;
  std::vector<std::uint8_t> rgb;
  Mesa() : color(static_cast<std::size_t>(kWidth) * kHeight) {
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 32, 0, 0, nullptr);
    if (!ctx || !OSMesaMakeCurrent(ctx, color.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) {
      std::fprintf(stderr, "OSMesa: no context\n");
      std::abort();
    }
    glViewport(0, 0, kWidth, kHeight);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glShadeModel(GL_FLAT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
  }
  ~Mesa() { OSMesaDestroyContext(ctx); }
  void load(const std::vector<WindowTriangle>& tris) {
    xyz.clear();
    rgb.clear();
    for (const WindowTriangle& t : tris)
      for (const Vec3d& v : t.v) {
        xyz.insert(xyz.end(),
                   {static_cast<float>(2 * v(0) / kWidth - 1),
                    static_cast<float>(2 * v(1) / kHeight - 1), static_cast<float>(2 * v(2) - 1)});
        rgb.insert(rgb.end(), {t.color.r, t.color.g, t.color.b});
      }
  }
  void draw() {
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glVertexPointer(3, GL_FLOAT, 0, xyz.data());
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, rgb.data());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(xyz.size() / 3));
    glFinish();
  }
  // Depth of pixel (i, j) in [0, 1] (rows bottom first, as ours).
  double depth(int i, int j) const {
    GLint w = 0, h = 0, bytes = 0;
    void* buffer = nullptr;
    OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &buffer);
    const std::size_t at =
        static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i);
    // llvmpipe keeps 24 bits (Z24 in the low bits of each 32-bit word).
    if (bytes == 4) return (static_cast<const std::uint32_t*>(buffer)[at] & 0xffffff) / 16777215.0;
    return static_cast<const std::uint16_t*>(buffer)[at] / 65535.0;
  }
};

Mesa& mesa() {
  static Mesa m;
  return m;
}

void BM_Llvmpipe(benchmark::State& state) {
  const bool small = state.range(0) != 0;
  Mesa& m = mesa();
  m.load(triangles(small));
  for (auto _ : state) m.draw();
  report(state, small);
}
BENCHMARK(BM_Llvmpipe)
    ->Arg(1)
    ->ArgName("small")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();
BENCHMARK(BM_Llvmpipe)
    ->Arg(0)
    ->ArgName("small")
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

void compare(bool small) {
  const std::vector<WindowTriangle>& tris = triangles(small);
  const Frame ours = render_zbuffer(tris, kWidth, kHeight, {});
  Mesa& m = mesa();
  m.load(tris);
  m.draw();
  long covered = 0, coverage = 0, depth5 = 0, depth3 = 0;
  double worst = 0;
  for (int j = 0; j < kHeight; ++j)
    for (int i = 0; i < kWidth; ++i) {
      const std::uint32_t a = ours.color.at(i, j) & 0xffffff;
      const std::uint32_t b = m.color[static_cast<std::size_t>(j) * kWidth + i] & 0xffffff;
      covered += a != 0;
      if (a != b) {
        ++coverage;
        continue;
      }
      if (a == 0) continue;
      const double dz = std::abs(static_cast<double>(ours.depth.at(i, j)) - m.depth(i, j));
      worst = std::max(worst, dz);
      depth5 += dz > 1e-5;
      depth3 += dz > 1e-3;
    }
  std::printf(
      "%s: %ld pixels covered; %ld differ in the winning triangle (%.4f%%); of the rest, depth "
      "differs by "
      "more than 1e-5 at %ld and by more than 1e-3 at %ld (largest %.2g)\n",
      small ? "100k small" : "100 large", covered, coverage,
      100.0 * coverage / std::max(covered, 1L), depth5, depth3, worst);
}
#endif

}  // namespace
}  // namespace frustum

int main(int argc, char** argv) {
  // llvmpipe's threads are the documented LP_NUM_THREADS, as the caller set it (unset: one per
  // core); tools/performance.sh runs it with 1 and with every core.
  const char* lp_threads = std::getenv("LP_NUM_THREADS");
  benchmark::AddCustomContext("LP_NUM_THREADS", lp_threads ? lp_threads : "unset (one per core)");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
#ifdef FRUSTUM_HAVE_OSMESA
  frustum::compare(true);
  frustum::compare(false);
#endif
  return 0;
}
