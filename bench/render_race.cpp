// frustum_race SCENE [--size WxH] [--id ID] [--reps N] [--out DIR] [--json] [--max-differ F]
//
// The same scene rendered end to end (scene file → transform → clip → raster → PNG) by Frustum
// and by Mesa's llvmpipe (OSMesa), runs interleaved, wall and CPU time of each:
// - Frustum: exactly `frustum render SCENE -o DIR/frustum.png [--size] [--id]` (run_render, the
//   command's own library call), into a frame kept from run to run as llvmpipe's context keeps
//   its framebuffer (a new frame would cost the kernel 16 MB of zeroed pages at 1920 × 1080 on
//   every run, which llvmpipe's side does not pay).
// - llvmpipe: the same reader (load_render_scene: parsing costs the same) and the same hierarchy
//   walk (for_each_world_triangle: the model transforms, in double, filling a float vertex
//   buffer as an application would), then the view and projection matrices to fixed-function GL,
//   which transforms, clips, lights (Processing's lights() as GL_LIGHT0, two-sided, flat), maps to
//   the viewport and rasterizes into a depth-tested frame; glReadPixels, and the same PNG writer
//   (write_color_png). The context is made once, before the runs.
// The process allocates with mimalloc, as the `frustum` binary does (CMakeLists.txt), for both
// sides: with glibc's malloc, the memory llvmpipe's run gave back was taken again page by page by
// Frustum's next render.
// LP_NUM_THREADS is left as the caller set it (unset: Mesa's default, one per core), and Frustum
// renders with as many threads (`--threads`: a modelled scene's geometry in parts and its frame in
// bands, a larger scene streamed by every thread in strips of rows). In the same run: the bandwidth
// ceiling (bandwidth_ceiling.hpp) and the fraction of it that Frustum's fill reaches on this scene,
// and how many pixels of the two images differ (by more than 2 levels in a channel); --max-differ F
// fails (exit 1) when more than the fraction F of the pixels do.
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <fmt/format.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

#include "app/commands.hpp"
#include "bench/bandwidth_ceiling.hpp"
#include "solver/raster/fill.hpp"
#include "solver/raster_fast/png_writer.hpp"
#include "solver/raster_fast/threaded_zbuffer.hpp"

namespace frustum {
namespace {

struct Times {
  std::vector<double> wall, cpu;  // seconds, one per run
};

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <typename F>
void timed(Times& times, F&& run) {
  const double cpu0 = process_cpu_seconds();
  const auto wall0 = std::chrono::steady_clock::now();
  run();
  times.wall.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
  times.cpu.push_back(process_cpu_seconds() - cpu0);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

Scene load(const app::RenderOptions& opt) {
  std::ostringstream sink;
  const app::Output quiet{sink, sink, false};
  std::variant<Scene, int> loaded = app::load_render_scene(opt, quiet);
  if (std::holds_alternative<int>(loaded)) {
    std::cerr << sink.str();
    std::exit(2);
  }
  return std::get<Scene>(std::move(loaded));
}

// A context of the scene's size: RGBA8 colour, a depth buffer (llvmpipe keeps 24 bits).
struct Llvmpipe {
  OSMesaContext ctx = nullptr;
  Image<std::uint32_t> frame;
  Llvmpipe(int width, int height) : frame(width, height, 0u) {
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx || !OSMesaMakeCurrent(ctx, frame.data.data(), GL_UNSIGNED_BYTE, width, height)) {
      std::cerr << "OSMesa: no context\n";
      std::exit(2);
    }
  }
  ~Llvmpipe() { OSMesaDestroyContext(ctx); }
  Llvmpipe(const Llvmpipe&) = delete;
  Llvmpipe& operator=(const Llvmpipe&) = delete;
};

// A run of consecutive triangles drawn with one fill and one cull state.
struct Batch {
  GLint first = 0;
  GLsizei count = 0;
  Rgb fill;
  Cull cull = Cull::None;
};

// The llvmpipe side, start to end; returns the image as read back (raster rows, y up).
const Image<std::uint32_t>& render_llvmpipe(const app::RenderOptions& opt, Llvmpipe& gl) {
  // The PNG writer's threads, started while the scene is read, as `frustum render` starts them.
  std::optional<ThreadTeam> team = app::render_team(opt.threads);
  const Scene scene = load(opt);
  // The vertex buffer: world positions, and face normals (n = (v1 − v0) × (v2 − v0), the
  // side shade() lights) when there is a light, filled by Frustum's hierarchy walk.
  const bool lit = scene.light.has_value();
  std::vector<float> xyz, normals;
  std::vector<Batch> batches;
  for_each_world_triangle(scene, [&](const WorldTriangle& t) {
    if (batches.empty() || batches.back().fill != t.fill || batches.back().cull != t.cull)
      batches.push_back({static_cast<GLint>(xyz.size() / 3), 0, t.fill, t.cull});
    batches.back().count += 3;
    for (const Vec3d& v : t.v)
      xyz.insert(xyz.end(),
                 {static_cast<float>(v(0)), static_cast<float>(v(1)), static_cast<float>(v(2))});
    if (!lit) return;
    Vec3d n = (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]);
    if (n.norm() > 0) n.normalize();
    for (int k = 0; k < 3; ++k)
      normals.insert(normals.end(), {static_cast<float>(n(0)), static_cast<float>(n(1)),
                                     static_cast<float>(n(2))});
  });

  glViewport(0, 0, scene.width, scene.height);
  glMatrixMode(GL_PROJECTION);
  Mat4d clip_from_eye = scene.clip_from_eye;
  // DirectX's clip z runs over [0, w]; GL clips z to [−w, w] and maps z/w to (z/w + 1)/2:
  // z' = 2z − w gives the same depth and the same near plane.
  if (scene.api == Api::DirectX)
    clip_from_eye.row(2) = 2 * clip_from_eye.row(2) - clip_from_eye.row(3);
  glLoadMatrixd(clip_from_eye.data());  // Eigen is column-major, as GL
  glMatrixMode(GL_MODELVIEW);
  const Mat4d view = eye_from_world(scene);
  glLoadMatrixd(view.data());
  // Raster space is GL's window space for every API (pipeline.hpp), so the front is
  // counter-clockwise there for OpenGL and clockwise for Processing and DirectX.
  glFrontFace(scene.api == Api::OpenGL ? GL_CCW : GL_CW);
  glCullFace(GL_BACK);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glShadeModel(GL_FLAT);
  if (lit) {
    // colour = fill·(ambient + diffuse·max(0, n̂·(−d̂)))/255, two-sided (scene.hpp).
    const DirectionalLight& l = *scene.light;
    const Vec3d to_light = -l.direction;
    const GLfloat position[4] = {static_cast<float>(to_light(0)), static_cast<float>(to_light(1)),
                                 static_cast<float>(to_light(2)), 0};
    const auto a = static_cast<float>(l.ambient / 255), d = static_cast<float>(l.diffuse / 255);
    const GLfloat ambient[4] = {a, a, a, 1}, diffuse[4] = {d, d, d, 1}, none[4] = {0, 0, 0, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, position);  // world, through the view matrix
    glLightfv(GL_LIGHT0, GL_AMBIENT, ambient);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, none);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, none);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnableClientState(GL_NORMAL_ARRAY);
    glNormalPointer(GL_FLOAT, 0, normals.data());
  } else {
    glDisable(GL_LIGHTING);
    glDisableClientState(GL_NORMAL_ARRAY);
  }
  glClearColor(scene.background.r / 255.0f, scene.background.g / 255.0f,
               scene.background.b / 255.0f, 1);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, xyz.data());
  for (const Batch& b : batches) {
    if (b.cull == Cull::Back)
      glEnable(GL_CULL_FACE);
    else
      glDisable(GL_CULL_FACE);
    glColor3ub(b.fill.r, b.fill.g, b.fill.b);
    glDrawArrays(GL_TRIANGLES, b.first, b.count);
  }
  glFinish();
  glReadPixels(0, 0, scene.width, scene.height, GL_RGBA, GL_UNSIGNED_BYTE, gl.frame.data.data());
  if (!write_color_png(opt.output, gl.frame, opt.threads, team ? &*team : nullptr)) {
    std::cerr << opt.output << ": cannot write the image\n";
    std::exit(2);
  }
  return gl.frame;
}

// Pixels whose colours differ by more than 2 levels in some channel.
long differing_pixels(const Image<std::uint32_t>& a, const Image<std::uint32_t>& b) {
  long n = 0;
  for (std::size_t k = 0; k < a.data.size(); ++k)
    for (int shift = 0; shift < 24; shift += 8) {
      const int x = static_cast<int>((a.data[k] >> shift) & 0xff);
      const int y = static_cast<int>((b.data[k] >> shift) & 0xff);
      if (std::abs(x - y) > 2) {
        ++n;
        break;
      }
    }
  return n;
}

// Threads of this process (the application's and llvmpipe's).
long process_threads() {
  long n = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
    ++n;
  return n;
}

// Passes of the fill alone and of the ceiling's loop, in turn (so that both see the machine in
// the same state); each figure is the best pass.
constexpr int kMeasurePasses = 20;

// Seconds of one pass of the ceiling's loop over `frame`.
double ceiling_pass(Frame& frame, int p) {
  const auto t0 = std::chrono::steady_clock::now();
  depth_pass(frame.depth.data.data(), frame.color.data.data(), 0.5f, (p % 2 ? -1.0f : 1.0f) * 1e-5f,
             static_cast<std::uint32_t>(p));
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int usage() {
  std::cerr << "usage: frustum_race SCENE [--size WxH] [--id ID] [--reps N] [--out DIR] [--json] "
               "[--max-differ FRACTION]\n";
  return 2;
}

int race(int argc, char** argv) {
  app::RenderOptions opt;
  int reps = 3;
  std::string out_dir = ".";
  bool json = false;
  double max_differ = 1;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    const bool has_value = k + 1 < argc;
    if (a == "--size" && has_value) {
      int w = 0, h = 0;
      if (std::sscanf(argv[++k], "%dx%d", &w, &h) != 2 || w <= 0 || h <= 0) return usage();
      opt.size = std::pair{w, h};
    } else if (a == "--id" && has_value) {
      opt.id = argv[++k];
    } else if (a == "--reps" && has_value) {
      reps = std::max(1, std::atoi(argv[++k]));
    } else if (a == "--out" && has_value) {
      out_dir = argv[++k];
    } else if (a == "--max-differ" && has_value) {
      max_differ = std::atof(argv[++k]);
    } else if (a == "--json") {
      json = true;
    } else if (opt.file.empty() && a[0] != '-') {
      opt.file = a;
    } else {
      return usage();
    }
  }
  if (opt.file.empty()) return usage();
  std::filesystem::create_directories(out_dir);
  const std::string frustum_png = (std::filesystem::path(out_dir) / "frustum.png").string();
  const std::string llvmpipe_png = (std::filesystem::path(out_dir) / "llvmpipe.png").string();
  const char* lp_env = std::getenv("LP_NUM_THREADS");
  const std::string lp_threads = lp_env ? lp_env : "unset";
  // Frustum gets as many threads as llvmpipe (unset: one per core, Mesa's default).
  const int asked = lp_env ? std::max(1, std::atoi(lp_env))
                           : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  opt.threads = asked;

  // Untimed: the frame size, the context, Frustum's own image for the comparison, the fill alone.
  const Scene scene = load(opt);
  const std::string frustum_threads = std::to_string(asked);
  Llvmpipe gl(scene.width, scene.height);
  GeometryStats gs;
  const std::vector<WindowTriangle> tris = geometry(scene, flatten(scene, false), &gs);
  FillStats fs;
  const Frame ours = render_zbuffer(tris, scene.width, scene.height, scene.background, &fs);
  // The fill alone (setup and draw) into a cleared frame, as the ceiling's loop: the best of as
  // many passes as the ceiling's, each beside one of the ceiling's, so that both are measured
  // alike on a shared machine.
  Frame frame(scene.width, scene.height, scene.background);
  Frame ceiling_frame(kCeilingWidth, kCeilingHeight, {});
  double fill_best = 1e30, ceiling_best = 1e30;
  for (int k = 0; k < kMeasurePasses; ++k) {
    frame.reset(scene.width, scene.height, scene.background);
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t t = 0; t < tris.size(); ++t)
      draw_triangle(setup_raster(tris[t], static_cast<int>(t)), frame);
    fill_best = std::min(
        fill_best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    ceiling_best = std::min(ceiling_best, ceiling_pass(ceiling_frame, k + 1));
  }
  const double fill_rate = static_cast<double>(fs.fragments) / fill_best;
  const double ceiling = static_cast<double>(kCeilingWidth) * kCeilingHeight / ceiling_best;

  // The race: runs interleaved, the side that goes first alternating.
  Times frustum_times, llvmpipe_times;
  const Image<std::uint32_t>* theirs = nullptr;
  std::ostringstream sink;
  const app::Output quiet{sink, sink, false};
  Frame target;  // Frustum's render target, kept as llvmpipe's context keeps its framebuffer
  auto run_frustum = [&] {
    app::RenderOptions o = opt;
    o.output = frustum_png;
    timed(frustum_times, [&] {
      if (app::run_render(o, quiet, &target) != 0) {
        std::cerr << sink.str();
        std::exit(2);
      }
    });
  };
  auto run_llvmpipe = [&] {
    app::RenderOptions o = opt;
    o.output = llvmpipe_png;
    timed(llvmpipe_times, [&] { theirs = &render_llvmpipe(o, gl); });
  };
  for (int r = 0; r < reps; ++r) {
    if (r % 2 == 0) {
      run_frustum();
      run_llvmpipe();
    } else {
      run_llvmpipe();
      run_frustum();
    }
  }
  const long threads = process_threads();
  const long pixels = static_cast<long>(ours.color.data.size());
  const long differ = differing_pixels(ours.color, *theirs);
  const double speedup = median(llvmpipe_times.wall) / median(frustum_times.wall);
  const double cpu_ratio = median(llvmpipe_times.cpu) / median(frustum_times.cpu);

  if (json) {
    auto side = [&](const char* name, const std::string& threads, const Times& t) {
      return fmt::format(
          R"({{"side": "{}", "threads": "{}", "wall_min": {:.4f}, "wall_median": {:.4f}, )"
          R"("wall_max": {:.4f}, "cpu_median": {:.4f}}})",
          name, threads, *std::min_element(t.wall.begin(), t.wall.end()), median(t.wall),
          *std::max_element(t.wall.begin(), t.wall.end()), median(t.cpu));
    };
    std::cout << fmt::format(
        R"({{"scene": "{}", "width": {}, "height": {}, "triangles": {}, "reps": {}, )"
        R"("lp_num_threads": "{}", "sides": [{}, {}], "fill_pixels_per_s": {:.6g}, )"
        R"("ceiling_pixels_per_s": {:.6g}, "differing_pixels": {}, "pixels": {}, )"
        R"("process_threads": {}}})"
        "\n",
        std::filesystem::path(opt.file).filename().string(), scene.width, scene.height,
        gs.triangles, reps, lp_threads, side("frustum", frustum_threads, frustum_times),
        side("llvmpipe", lp_threads, llvmpipe_times), fill_rate, ceiling, differ, pixels, threads);
  } else {
    std::cout << fmt::format(
        "{}: {} × {}, {} triangles ({} drawn after clipping and culling); {} runs a side, "
        "interleaved\n",
        opt.file, scene.width, scene.height, gs.triangles, gs.window, reps);
    std::cout << fmt::format(
        "LP_NUM_THREADS={}{}; Frustum renders with --threads {}{}; this process runs {} threads "
        "after llvmpipe's runs (the application's own and llvmpipe's, which rasterize beside "
        "it)\n",
        lp_threads, lp_env ? "" : " (Mesa's default: one per core)", asked,
        asked == 1 ? std::string(" (one thread)")
        : zbuffer_banded(scene, asked)
            ? fmt::format(" (the geometry in {} parts, then the frame in bands)", asked)
            : fmt::format(" (streamed by {} threads, each drawing its strips of rows)", asked),
        threads);
    std::cout << "side      threads  wall min / median / max (s)  CPU median (s)\n";
    auto row = [](const char* name, const std::string& threads, const Times& t) {
      return fmt::format("{:<9} {:>7}  {:>8.3f} / {:.3f} / {:.3f}  {:>14.3f}\n", name, threads,
                         *std::min_element(t.wall.begin(), t.wall.end()), median(t.wall),
                         *std::max_element(t.wall.begin(), t.wall.end()), median(t.cpu));
    };
    std::cout << row("frustum", frustum_threads, frustum_times)
              << row("llvmpipe", lp_threads, llvmpipe_times);
    std::cout << fmt::format(
        "Frustum is {:.2f}× llvmpipe's speed in wall time (median), {:.2f}× in CPU time\n", speedup,
        cpu_ratio);
    std::cout << fmt::format(
        "fill on this scene: {} fragments at {:.3f} G px/s; bandwidth ceiling in this run "
        "{:.3f} G px/s (12 B a fragment): {:.0f} %\n",
        fs.fragments, fill_rate / 1e9, ceiling / 1e9, 100 * fill_rate / ceiling);
    std::cout << fmt::format(
        "images: {} of {} pixels ({:.3f} %) differ by more than 2 levels ({} and {})\n", differ,
        pixels, 100.0 * static_cast<double>(differ) / static_cast<double>(pixels), frustum_png,
        llvmpipe_png);
  }
  if (static_cast<double>(differ) > max_differ * static_cast<double>(pixels)) {
    std::cerr << fmt::format("more than {} of the pixels differ\n", max_differ);
    return 1;
  }
  return 0;
}

}  // namespace
}  // namespace frustum

int main(int argc, char** argv) { return frustum::race(argc, argv); }
