// The scene pipeline, the z-buffer and scan-line renderers, the render kind and
// `frustum render`: cross-checks against the plane method, coverage properties over random
// meshes, and the paper-plane seed.
#include "solver/kinds/render.hpp"

#include <fmt/format.h>
#include <png.h>
#include <sys/wait.h>
#include <zlib.h>

#include <array>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "app/commands.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/raster/certified_trace.hpp"
#include "solver/raster/fill.hpp"
#include "solver/raster/scanline.hpp"
#include "solver/raster_fast/png_writer.hpp"
#include "solver/raster_fast/striped_render.hpp"
#include "solver/raster_fast/threaded_zbuffer.hpp"
#include "solver/util/side_by_side.hpp"
#include "solver/visibility/mesh.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// Uniform on the 1/256 grid in [lo, hi].
double grid_value(std::mt19937& rng, double lo, double hi) {
  std::uniform_int_distribution<long> d(static_cast<long>(lo * 256), static_cast<long>(hi * 256));
  return static_cast<double>(d(rng)) / 256.0;
}

WindowTriangle random_triangle(std::mt19937& rng, double size, int width, int height) {
  std::uniform_real_distribution<double> u(0, 1);
  const double cx = grid_value(rng, -size / 2, width + size / 2),
               cy = grid_value(rng, -size / 2, height + size / 2);
  WindowTriangle t;
  for (Vec3d& v : t.v)
    v = Vec3d(cx + grid_value(rng, -size, size), cy + grid_value(rng, -size, size), u(rng));
  t.color = {static_cast<std::uint8_t>(rng() % 256), static_cast<std::uint8_t>(rng() % 256), 7};
  return t;
}

// The z-buffer written naively: every pixel of the box through covers() and depth_at().
Frame reference_frame(const std::vector<WindowTriangle>& tris, int w, int h, Rgb bg) {
  Frame f(w, h, bg);
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const RasterTriangle t = setup_raster(tris[k], static_cast<int>(k));
    for (int j = std::max(t.setup.j_min, 0); j <= std::min(t.setup.j_max, h - 1); ++j)
      for (int i = std::max(t.setup.i_min, 0); i <= std::min(t.setup.i_max, w - 1); ++i) {
        if (!covers(t.setup, i, j)) continue;
        const float z = depth_at(t, i, j);
        if (z < f.depth.at(i, j)) {
          f.depth.at(i, j) = z;
          f.color.at(i, j) = t.color;
        }
      }
  }
  return f;
}

// The z-buffer's frame of `tris` equals the naive reference's, bit for bit; its stats.
FillStats expect_reference_frame(const std::vector<WindowTriangle>& tris, int w, int h, Rgb bg) {
  const Frame ref = reference_frame(tris, w, h, bg);
  FillStats fs;
  const Frame z = render_zbuffer(tris, w, h, bg, &fs);
  EXPECT_EQ(z.color.data, ref.color.data);
  EXPECT_EQ(z.depth.data, ref.depth.data);
  return fs;
}

// w made a sliver: its third vertex within `jitter` pixels (across x) of the segment v0 v1.
void make_sliver(std::mt19937& rng, WindowTriangle& w, double jitter) {
  const Vec3d d = w.v[1] - w.v[0];
  w.v[2] = w.v[0] + d * grid_value(rng, 0, 1) + Vec3d(grid_value(rng, -jitter, jitter), 0, 0);
}

std::string scene_yaml(const std::string& api, const std::string& objects,
                       const std::string& pixels, const std::string& extra = "") {
  return "conventions: {api: " + api +
         "}\nproblems:\n  - id: p\n    kind: render\n    given:\n      scene:\n"
         "        viewport: {width: 64, height: 48}\n"
         "        camera: {eye: [0, 0, 10], center: [0, 0, 0], up: [0, 1, 0]}\n"
         "        perspective: {fovy: 60, aspect: 4/3, near: 1, far: 100}\n" +
         extra + "        objects:\n" + objects + "      pixels: " + pixels + "\n";
}

// ---------------------------------------------------------------- raster stages

TEST(Pipeline, DepthAtPixelCentreEqualsThePlaneMethod) {
  // The depth_at_pixel kind (seed 001's plane method, exact) on the same window-space
  // triangle, at every covered pixel centre of a few random triangles.
  std::mt19937 rng(4);
  int checked = 0;
  for (int n = 0; n < 12; ++n) {
    const WindowTriangle w = random_triangle(rng, 6, 20, 20);
    const RasterTriangle t = setup_raster(w);
    if (t.setup.degenerate) continue;
    const std::vector<Fragment> frags = rasterize(t.setup);
    for (std::size_t f = 0; f < frags.size(); f += 3) {
      const int i = frags[f].i, j = frags[f].j;
      const std::string given =
          fmt::format("{{triangle: [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]], pixel: [{}, {}]}}",
                      w.v[0](0), w.v[0](1), w.v[0](2), w.v[1](0), w.v[1](1), w.v[1](2), w.v[2](0),
                      w.v[2](1), w.v[2](2), i + 0.5, j + 0.5);
      const ProblemResult r = test::solve_yaml(test::one("depth_at_pixel", given), false);
      ASSERT_FALSE(r.error) << test::error_text(r);
      const double plane_z = r.answers.find("z")->numbers[0];
      EXPECT_NEAR(depth_at(t, i, j), plane_z, 1e-6 * std::max(1.0, std::abs(plane_z))) << given;
      ++checked;
    }
  }
  EXPECT_GT(checked, 40);
}

TEST(Pipeline, SpansEqualPerPixelCoverage) {
  std::mt19937 rng(11);
  for (int n = 0; n < 2000; ++n) {
    const WindowTriangle w = random_triangle(rng, n % 2 ? 3 : 40, 50, 50);
    const TriangleSetup t = setup_raster(w).setup;
    for (int j = t.j_min - 1; j <= t.j_max + 1; ++j) {
      const Span s = span_on_row(t, j);
      for (int i = t.i_min - 1; i <= t.i_max + 1; ++i)
        ASSERT_EQ(covers(t, i, j), i >= s.i0 && i <= s.i1)
            << "triangle " << n << " pixel " << i << "," << j;
    }
  }
}

// RowSpans steps each edge's bound from row to row with additions; every row must be the span
// span_on_row computes with divisions, for small, large and thin triangles, horizontal and
// vertical edges, and coordinates far from the origin.
TEST(Pipeline, SteppedSpansEqualSpansRowByRow) {
  std::mt19937 rng(12);
  long rows = 0;
  for (int n = 0; n < 4000; ++n) {
    WindowTriangle w = random_triangle(rng, n % 3 == 0 ? 3 : (n % 3 == 1 ? 40 : 400), 500, 500);
    if (n % 4 == 1) make_sliver(rng, w, 0.5);
    if (n % 7 == 2) w.v[1](1) = w.v[0](1);   // a horizontal edge
    if (n % 11 == 3) w.v[2](0) = w.v[0](0);  // a vertical edge
    if (n % 13 == 4)
      for (Vec3d& v : w.v) v += Vec3d(900000, -700000, 0);
    const TriangleSetup t = setup_raster(w).setup;
    if (t.degenerate) continue;
    RowSpans spans(t, t.j_min);
    for (int j = t.j_min; j <= t.j_max; ++j, ++rows) {
      const Span a = spans.next(), b = span_on_row(t, j);
      ASSERT_TRUE(a.i0 > a.i1 ? b.i0 > b.i1 : a.i0 == b.i0 && a.i1 == b.i1)
          << "triangle " << n << " row " << j << ": " << a.i0 << ".." << a.i1 << " vs " << b.i0
          << ".." << b.i1;
    }
  }
  EXPECT_GT(rows, 100000);
}

TEST(Pipeline, SharedEdgesCoverEachPixelExactlyOnce) {
  // Random triangulated grids (jittered interior vertices, random diagonals): every pixel
  // centre inside the outer rectangle is covered by exactly one triangle.
  std::mt19937 rng(7);
  for (int mesh = 0; mesh < 40; ++mesh) {
    const int cells = 3 + mesh % 6;
    const double cell = 2.0 + (mesh % 5) * 1.7, x0 = 0.25 + (mesh % 3), y0 = 0.75;
    std::vector<std::vector<Vec3d>> p(cells + 1, std::vector<Vec3d>(cells + 1));
    for (int a = 0; a <= cells; ++a)
      for (int b = 0; b <= cells; ++b) {
        const bool inner = a > 0 && b > 0 && a < cells && b < cells;
        const double jx = inner ? grid_value(rng, -0.3 * cell, 0.3 * cell) : 0;
        const double jy = inner ? grid_value(rng, -0.3 * cell, 0.3 * cell) : 0;
        p[a][b] = Vec3d(x0 + a * cell + jx, y0 + b * cell + jy, 0.5);
      }
    const int size = static_cast<int>(x0 + cells * cell) + 3;
    std::vector<int> count(static_cast<std::size_t>(size * size), 0);
    auto add = [&](const Vec3d& a, const Vec3d& b, const Vec3d& c) {
      const TriangleSetup t = setup_raster(WindowTriangle{{a, b, c}, {}, 0, true}).setup;
      for (int j = t.j_min; j <= t.j_max; ++j) {
        const Span s = span_on_row(t, j);
        for (int i = s.i0; i <= s.i1; ++i) ++count[static_cast<std::size_t>(j * size + i)];
      }
    };
    for (int a = 0; a < cells; ++a)
      for (int b = 0; b < cells; ++b) {
        if (rng() % 2) {
          add(p[a][b], p[a + 1][b], p[a + 1][b + 1]);
          add(p[a][b], p[a + 1][b + 1], p[a][b + 1]);
        } else {
          add(p[a][b], p[a + 1][b], p[a][b + 1]);
          add(p[a + 1][b], p[a + 1][b + 1], p[a][b + 1]);
        }
      }
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const double xc = i + 0.5, yc = j + 0.5;
        const bool inside = xc > x0 && xc < x0 + cells * cell && yc > y0 && yc < y0 + cells * cell;
        ASSERT_EQ(count[static_cast<std::size_t>(j * size + i)], inside ? 1 : 0)
            << "mesh " << mesh << " pixel " << i << "," << j;
      }
  }
}

TEST(Pipeline, ZBufferEqualsTheNaiveReferenceAndScanline) {
  std::mt19937 rng(5);
  std::vector<WindowTriangle> tris;
  for (int n = 0; n < 300; ++n) tris.push_back(random_triangle(rng, n % 3 ? 4 : 30, 90, 70));
  const Rgb bg{1, 2, 3};
  EXPECT_GT(expect_reference_frame(tris, 90, 70, bg).written, 1000);
  const Frame ref = reference_frame(tris, 90, 70, bg);
  ScanlineStats st;
  Image<float> depth;
  const Image<std::uint32_t> s = render_scanline(tris, 90, 70, bg, &st, &depth);
  EXPECT_EQ(s.data, ref.color.data);
  EXPECT_EQ(depth.data, ref.depth.data);
  EXPECT_EQ(st.row_depth_bytes, 90 * sizeof(float));
  EXPECT_EQ(st.zbuffer_depth_bytes, 90 * 70 * sizeof(float));
  // The query path agrees with the frame at every pixel it is asked about.
  for (int k = 0; k < 200; ++k) {
    const int i = static_cast<int>(rng() % 90), j = static_cast<int>(rng() % 70);
    const PixelTrace t = trace_pixel(tris, i, j, bg);
    EXPECT_EQ(pack(t.color), ref.color.at(i, j));
    EXPECT_EQ(t.depth, ref.depth.at(i, j));
  }
}

// Thin triangles (many rows, a pixel or none on each) and tiny ones take the fill's other paths
// (stepped spans, the plain loop for short spans, the test of every pixel of a small box): the
// frame must still be the naive reference's, bit for bit.
TEST(Pipeline, ThinAndTinyTrianglesFillAsTheNaiveReference) {
  std::mt19937 rng(31);
  std::vector<WindowTriangle> tris;
  for (int n = 0; n < 600; ++n) {
    WindowTriangle w = random_triangle(rng, n % 2 ? 1.5 : 25, 120, 90);
    if (n % 3 == 0) make_sliver(rng, w, 0.6);
    tris.push_back(w);
  }
  EXPECT_GT(expect_reference_frame(tris, 120, 90, {9, 8, 7}).written, 2000);
}

TEST(Pipeline, ClippingKeepsEveryVertexInFrontOfTheEye) {
  // Triangles with vertices behind the eye (w < 0) come out inside the NDC cube, w > 0.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3, 3);
  Scene s;
  s.api = Api::OpenGL;
  s.camera = {Vec3d(0, 0, 0), Vec3d(0, 0, -1), Vec3d(0, 1, 0)};
  s.clip_from_eye << 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1.02, -0.202, 0, 0, -1, 0;  // near 0.1, far 10
  const Mat4d m = clip_from_world(s);
  int crossing = 0;
  for (int n = 0; n < 500; ++n) {
    std::array<Vec4d, 3> c;
    bool behind = false;
    for (Vec4d& v : c) {
      v = to_clip(m, Vec3d(u(rng), u(rng), u(rng)));
      behind = behind || v(3) <= 0;
    }
    crossing += behind;
    for (const Vec4d& v : clip_to_volume(c, Api::OpenGL)) {
      ASSERT_GT(v(3), 0);
      const Vec3d ndc = perspective_divide(v);
      for (int a = 0; a < 3; ++a) ASSERT_LE(std::abs(ndc(a)), 1 + 1e-9);
    }
  }
  EXPECT_GT(crossing, 100);
}

// ---------------------------------------------------------------- scenes

TEST(Scene, FrontFacesPointAtTheEyeInEveryApi) {
  // A cube seen from many eyes: the pipeline's front flag (window winding) agrees with
  // n·(eye − v₀) > 0 in world coordinates, and culling keeps exactly those faces.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-6, 6);
  for (Api api : {Api::OpenGL, Api::Processing, Api::DirectX}) {
    for (int n = 0; n < 30; ++n) {
      Scene s;
      s.api = api;
      s.width = 80;
      s.height = 60;
      Vec3d eye(u(rng), u(rng), u(rng));
      if (eye.norm() < 6) eye = eye.normalized() * 6;  // the whole cube in view
      s.camera = {eye, Vec3d(0, 0, 0), Vec3d(0.1, 1, 0.2)};
      const Volume<double> v = perspective_volume(1.0, 4.0 / 3.0, 0.5, 50.0);
      s.clip_from_eye = Mat4d(frustum_matrix(v, api));
      SceneObject cube = box_object(2, 2, 2);
      cube.cull = Cull::Back;
      s.objects.push_back(cube);
      const FlatScene flat = flatten(s);
      const std::vector<WindowTriangle> tris = geometry(s, flat);
      int expected = 0;
      for (const WorldTriangle& t : flat.triangles)
        expected += (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]).dot(eye - t.v[0]) > 0;
      std::set<int> drawn;
      for (const WindowTriangle& w : tris) drawn.insert(w.source);  // a clipped triangle is a fan
      ASSERT_EQ(static_cast<int>(drawn.size()), expected) << to_string(api);
      for (const WindowTriangle& w : tris) {
        const WorldTriangle& t = flat.triangles[static_cast<std::size_t>(w.source)];
        ASSERT_TRUE(w.front);
        ASSERT_GT((t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]).dot(eye - t.v[0]), 0) << to_string(api);
      }
    }
  }
}

// A copy of a repeat that only moves is placed as p + offset: it must be T(offset)·p bit for bit,
// the sign of a zero included (vertices and steps that cancel, −0 coordinates, negative steps),
// and its names, fills and faces as the walk gives them.
TEST(Scene, TranslatedCopiesAreTheTranslationsProductBitForBit) {
  std::mt19937 rng(77);
  std::uniform_int_distribution<int> pick(-4, 4);
  for (int trial = 0; trial < 40; ++trial) {
    Scene s;
    SceneObject o;
    for (int v = 0; v < 6; ++v) {
      Vec3d p(pick(rng) * 0.25, pick(rng) * 0.5, pick(rng) * 0.125);
      if (v == 5) p = Vec3d(-0.0, 0.0, -0.0);
      o.vertices.push_back(p);
    }
    o.triangles = {{0, 1, 2}, {3, 4, 5}};
    o.fill = Rgb{1, 2, 3};
    const Vec3d step(pick(rng) * 0.25, pick(rng) * 0.5, trial % 2 ? -0.125 : 0.125);
    o.repeat = SceneObject::Repeat{{-2, -1, 0}, {2, 1, 2}, step};
    s.objects.push_back(o);
    const FlatScene flat = flatten(s);
    ASSERT_EQ(flat.triangles.size(), 2u * 5 * 3 * 3);
    EXPECT_EQ(world_triangle_count(s), flat.triangles.size());
    std::size_t n = 0;
    for (int i = -2; i <= 2; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int l = 0; l <= 2; ++l) {
          Mat4d t = Mat4d::Identity();
          t.block<3, 1>(0, 3) = Vec3d(i * step(0), j * step(1), l * step(2));
          for (std::size_t f = 0; f < 2; ++f, ++n) {
            const WorldTriangle& w = flat.triangles[n];
            EXPECT_EQ(w.face, static_cast<int>(f));
            EXPECT_EQ(w.fill, (Rgb{1, 2, 3}));
            for (int v = 0; v < 3; ++v) {
              const Vec3d& p = o.vertices[static_cast<std::size_t>(o.triangles[f][v])];
              const Vec3d expected = (t * Vec4d(p(0), p(1), p(2), 1.0)).head<3>();
              for (int a = 0; a < 3; ++a)
                ASSERT_EQ(std::bit_cast<std::uint64_t>(w.v[v](a)),
                          std::bit_cast<std::uint64_t>(expected(a)))
                    << "copy " << i << "," << j << "," << l << " vertex " << v << " axis " << a
                    << ": " << w.v[v](a) << " vs " << expected(a);
            }
          }
          EXPECT_EQ(flat.objects[static_cast<std::size_t>(flat.triangles[n - 1].object)],
                    fmt::format("objects[0][{},{},{}]", i, j, l));
        }
  }
}

TEST(Scene, HierarchyComposesParentThenChild) {
  Scene s;
  SceneObject parent, child;
  parent.transform.block<3, 1>(0, 3) = Vec3d(10, 0, 0);
  parent.transform.block<3, 3>(0, 0) << 0, -1, 0, 1, 0, 0, 0, 0, 1;  // rotate_z 90°
  child.transform.block<3, 1>(0, 3) = Vec3d(1, 0, 0);
  child.vertices = {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 1, 0)};
  child.triangles = {{0, 1, 2}};
  child.fill = Rgb{9, 9, 9};
  child.repeat = SceneObject::Repeat{{0, 0, 0}, {0, 0, 2}, Vec3d(0, 0, 5)};
  parent.children.push_back(child);
  s.objects.push_back(parent);
  const FlatScene flat = flatten(s);
  ASSERT_EQ(flat.triangles.size(), 3u);
  // Counted without the walk: the parent's none, the child's one triangle three times.
  EXPECT_EQ(world_triangle_count(s), 3u);
  s.objects.push_back(child);  // and once more at the top level, three copies again
  EXPECT_EQ(world_triangle_count(s), 6u);
  EXPECT_EQ(flatten(s).triangles.size(), 6u);
  // M = T(10,0,0)·R_z(90°)·T(0,0,5k)·T(1,0,0): the child's origin lands at (10, 1, 5k).
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(flat.triangles[k].v[0].isApprox(Vec3d(10, 1, 5.0 * k)))
        << flat.triangles[k].v[0].transpose();
    EXPECT_TRUE(flat.triangles[k].v[1].isApprox(Vec3d(10, 2, 5.0 * k)));
    EXPECT_EQ(flat.triangles[k].fill, (Rgb{9, 9, 9}));
  }
  EXPECT_EQ(flat.objects[static_cast<std::size_t>(flat.triangles[2].object)],
            "objects[0].children[0][2]");
}

TEST(Scene, ProcessingLightsFromAboveShadeBoxTopsFully) {
  // seed 000: rotateX(PI/2); lights() sends the light along +y (down in Processing).
  WorldTriangle top;
  top.v = {Vec3d(-1, -5, 1), Vec3d(1, -5, -1), Vec3d(1, -5, 1)};  // n = (0, −4, 0): up
  top.fill = {0, 50, 0};
  DirectionalLight light;
  light.direction = Vec3d(0, 1, 0);
  EXPECT_EQ(shade(top, true, light), (Rgb{0, 50, 0}));  // (128 + 128)/255 ≈ 1.004
  WorldTriangle side = top;
  side.v = {Vec3d(1, -5, 1), Vec3d(1, 5, 1), Vec3d(1, 5, -1)};
  EXPECT_EQ(shade(side, true, light), (Rgb{0, 25, 0}));  // ambient only: 50·128/255
  EXPECT_EQ(shade(top, false, light), (Rgb{0, 25, 0}));  // seen from below: lit side away
  EXPECT_EQ(shade(top, true, std::nullopt), (Rgb{0, 50, 0}));
}

// ---------------------------------------------------------------- the render kind

TEST(RenderKind, ProcessingWindowYPointsDown) {
  // A triangle below the centre in Processing's y-down world shows in the lower half.
  const std::string objects =
      "          - {triangle: [[-2, 1, 0], [2, 1, 0], [0, 3, 0]], fill: '#ff0000'}\n";
  const ProblemResult r =
      test::solve_yaml(scene_yaml("processing", objects, "[[32, 34], [32, 13]]"));
  ASSERT_FALSE(r.error) << test::error_text(r);
  EXPECT_EQ(test::exact_text(r, "color"), "255, 0, 0, 0, 0, 0");
  const Value* obj = r.answers.find("object");
  EXPECT_EQ(obj->words, (std::vector<std::string>{"objects[0]", "background"}));
  const Value* d = r.answers.find("depth");
  // Window depth of a point 10 in front of the eye: (n+f)/(f−n)... → z_w = (1/n − 1/z)/(1/n − 1/f).
  EXPECT_NEAR(d->numbers[0], (1.0 - 1.0 / 10) / (1.0 - 1.0 / 100), 1e-6);
  EXPECT_EQ(d->numbers[1], 1.0);
}

TEST(RenderKind, NearerTriangleWinsWhateverTheOrder) {
  const std::string objects =
      "          - {name: far, triangle: [[-3, -3, -5], [3, -3, -5], [0, 3, -5]], fill: [0, 0, "
      "255]}\n"
      "          - {name: near, triangle: [[-3, -3, 0], [3, -3, 0], [0, 3, 0]], fill: [0, 255, "
      "0]}\n"
      "          - {name: hidden, triangle: [[-3, -3, -2], [3, -3, -2], [0, 3, -2]], fill: [255, "
      "0, 0]}\n";
  const ProblemResult r = test::solve_yaml(scene_yaml("opengl", objects, "[[32, 24]]"));
  ASSERT_FALSE(r.error) << test::error_text(r);
  EXPECT_EQ(test::exact_text(r, "color"), "0, 255, 0");
  EXPECT_EQ(r.answers.find("object")->words[0], "near");
  // The trace lists all three in drawing order: written, written, hidden.
  std::string trace;
  for (const Step& s : r.derivation.steps())
    if (s.title.en() == "Pixel (32, 24)") trace = s.note.en();
  EXPECT_NE(trace.find("1. triangle 0 (far"), std::string::npos) << trace;
  EXPECT_NE(trace.find("2. triangle 1 (near"), std::string::npos) << trace;
  EXPECT_NE(trace.find("3. triangle 2 (hidden"), std::string::npos) << trace;
  EXPECT_NE(trace.find("→ hidden"), std::string::npos) << trace;
}

TEST(RenderKind, BadInputIsLocated) {
  const std::string good = "          - {triangle: [[-2, 1, 0], [2, 1, 0], [0, 3, 0]]}\n";
  struct Case {
    std::string yaml, where;
  };
  const std::vector<Case> cases = {
      {scene_yaml("opengl",
                  "          - {triangle: [[-2, 1, 0], [2, 1, 0], [0, 3, 0]], fill: '#12345'}\n",
                  "[[1, 1]]"),
       "objects[0].fill: expected a colour"},
      {scene_yaml("opengl", good, "[[64, 1]]"),
       "pixels[0][0]: expected a pixel index from 0 to 63"},
      {scene_yaml("opengl", "          - {box: [1, 2], fill: [0, 0, 0]}\n", "[[1, 1]]"),
       "objects[0].box"},
      {scene_yaml("opengl", "          - {solid: cub}\n", "[[1, 1]]"), "objects[0].solid"},
      {scene_yaml("opengl",
                  "          - {triangle: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], fill: [0, 300, 0]}\n",
                  "[[1, 1]]"),
       "objects[0].fill[1]: expected an integer from 0 to 255"},
      {scene_yaml("opengl",
                  "          - {mesh: {vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces: [[0, 1, "
                  "3]]}}\n",
                  "[[1, 1]]"),
       "faces[0][2]: expected a vertex index from 0 to 2"},
      {scene_yaml("opengl", good, "[[1, 1]]", "        light: {direction: [0, 0, 0]}\n"),
       "light.direction: the zero vector is not a direction"},
      {scene_yaml("opengl", good, "[[1, 1]]", "        method: scanlines\n"), "method"},
  };
  for (const Case& c : cases) {
    const ProblemSet set = load_problem_set_from_string(c.yaml, "scene.yaml");
    std::string message = set.errors.empty() ? "" : set.errors[0].format();
    if (!set.problems.empty() && set.problems[0].error) message = set.problems[0].error->format();
    EXPECT_NE(message.find(c.where), std::string::npos) << c.where << " | " << message;
    EXPECT_EQ(message.rfind("scene.yaml:", 0), 0u) << message;
  }
}

TEST(RenderKind, PaperplaneSeedSolves) {
  const ProblemSet set = load_problem_set(test::source_path("problems/seeds/paperplane.yaml"));
  ASSERT_TRUE(set.errors.empty());
  const SetResult r = solve_set(set, true);
  ASSERT_EQ(r.problems.size(), 1u);
  ASSERT_FALSE(r.problems[0].error) << r.problems[0].error->format();
  const Value* obj = r.problems[0].answers.find("object");
  EXPECT_EQ(obj->words, (std::vector<std::string>{"plane", "ground[0,0]", "background"}));
  // Box tops face the light from above: 50·(128 + 128)/255 rounds to 50; the plane is
  // tilted a little away from it.
  EXPECT_EQ(test::exact_text(r.problems[0], "color"), "253, 253, 253, 0, 50, 0, 50, 50, 100");
  const Value* depth = r.problems[0].answers.find("depth");
  EXPECT_LT(depth->numbers[0], depth->numbers[1]);  // the plane is nearer than the ground
  EXPECT_EQ(depth->numbers[2], 1.0);
}

TEST(RenderKind, ScanlineImageOfThePaperplaneEqualsTheZBuffer) {
  const ProblemSet set = load_problem_set(test::source_path("problems/seeds/paperplane.yaml"));
  ASSERT_FALSE(set.problems.empty());
  const Scene& scene = std::any_cast<const RenderGiven&>(set.problems[0].given).spec.scene;
  const std::vector<WindowTriangle> tris = geometry(scene, flatten(scene));
  const Frame z = render_zbuffer(tris, scene.width, scene.height, scene.background);
  const Image<std::uint32_t> s = render_scanline(tris, scene.width, scene.height, scene.background);
  EXPECT_EQ(s.data, z.color.data);
  long plane = 0;
  for (std::uint32_t c : z.color.data) plane += unpack(c).r > 200;
  EXPECT_GT(plane, 200);  // the white plane is drawn, lit from above
}

// `frustum render` streams each world triangle through geometry into the frame: the same
// colours, depths and statistics as the stages run one after the other over whole arrays
// (the paper plane clips 240 triangles and drops 1,894 outside the volume).
TEST(RenderKind, StreamedZBufferEqualsTheStagesOneAfterTheOther) {
  const ProblemSet set = load_problem_set(test::source_path("problems/seeds/paperplane.yaml"));
  ASSERT_FALSE(set.problems.empty());
  const Scene& scene = std::any_cast<const RenderGiven&>(set.problems[0].given).spec.scene;
  GeometryStats gs, streamed_gs;
  FillStats fs, streamed_fs;
  const std::vector<WindowTriangle> tris = geometry(scene, flatten(scene), &gs);
  const Frame z = render_zbuffer(tris, scene.width, scene.height, scene.background, &fs);
  const Frame streamed = render_zbuffer(scene, &streamed_gs, &streamed_fs);
  EXPECT_EQ(streamed.color.data, z.color.data);
  EXPECT_EQ(streamed.depth.data, z.depth.data);
  EXPECT_GT(gs.clipped, 0);
  EXPECT_GT(gs.outside, 0);
  EXPECT_EQ(streamed_gs.clipped, gs.clipped);
  EXPECT_EQ(streamed_gs.outside, gs.outside);
  EXPECT_EQ(streamed_gs.window, gs.window);
  EXPECT_EQ(streamed_fs.fragments, fs.fragments);
  EXPECT_EQ(streamed_fs.written, fs.written);
  // With threads, the scene (5,296 world triangles) set up whole and filled band by band, the
  // threads taking bands in turn: the same frame.
  ASSERT_EQ(world_triangle_count(scene), flatten(scene).triangles.size());
  // Also on a team of threads kept from one render to the next (as `frustum render` keeps one
  // for a render and its PNG), with as many threads as asked for, fewer, or more.
  ThreadTeam team(3);
  for (const int threads : {2, 4, -2, -3, -5}) {  // negative: that many, on the team
    GeometryStats threaded_gs;
    FillStats threaded_fs;
    Frame threaded;
    render_zbuffer(scene, threaded, &threaded_gs, &threaded_fs, std::abs(threads),
                   threads < 0 ? &team : nullptr);
    EXPECT_EQ(threaded.color.data, z.color.data) << threads;
    EXPECT_EQ(threaded.depth.data, z.depth.data) << threads;
    EXPECT_EQ(threaded_gs.window, gs.window) << threads;
    EXPECT_EQ(threaded_fs.written, fs.written) << threads;
  }
  // Without names the walk yields the same triangles, and counts the same objects.
  const FlatScene named = flatten(scene), unnamed = flatten(scene, false);
  ASSERT_EQ(named.triangles.size(), unnamed.triangles.size());
  EXPECT_TRUE(unnamed.objects.empty());
  EXPECT_EQ(unnamed.triangles.back().object, named.triangles.back().object);
  EXPECT_EQ(unnamed.triangles.back().v, named.triangles.back().v);
}

// A scene of more world triangles than a modelled one (kBandedTriangles) streams: with threads,
// each walks the scene and draws its own strips of rows. Boxes in a grid, some cut by the near
// plane and some off to the sides: the same frame, depths and statistics as on one thread, and
// as the stages run one after the other, for any number of threads, on a team or not, and for
// frames whose height is not a multiple of the strips', in every API's conventions (y-down
// windows included), back faces culled or not.
TEST(RenderKind, ALargeSceneStreamedWithThreadsGivesTheFrameOfOneThread) {
  ThreadTeam team(3);
  for (const auto& [api, height, cull] :
       std::vector<std::tuple<Api, int, Cull>>{{Api::OpenGL, 64, Cull::None},
                                               {Api::OpenGL, 61, Cull::Back},
                                               {Api::OpenGL, 7, Cull::None},
                                               {Api::Processing, 61, Cull::Back},
                                               {Api::DirectX, 53, Cull::None}}) {
    Scene s;
    s.api = api;
    s.width = 96;
    s.height = height;
    s.camera = {Vec3d(0.3, 2.5, 4), Vec3d(0, 0, -20), Vec3d(0, 1, 0)};
    s.clip_from_eye = Mat4d(frustum_matrix(perspective_volume(1.2, 1.5, 1.0, 80.0), api));
    s.light = DirectionalLight{};
    SceneObject box = box_object(0.8, 0.6, 0.7);
    box.fill = Rgb{90, 160, 220};
    box.cull = cull;
    box.repeat = SceneObject::Repeat{{-40, 0, -70}, {40, 0, 0}, Vec3d(1.0, 0, 1.0)};
    s.objects.push_back(box);
    ASSERT_GT(world_triangle_count(s), kBandedTriangles);
    GeometryStats gs, one_gs;
    FillStats fs, one_fs;
    const std::vector<WindowTriangle> tris = geometry(s, flatten(s, false), &gs);
    const Frame staged = render_zbuffer(tris, s.width, s.height, s.background, &fs);
    const Frame one = render_zbuffer(s, &one_gs, &one_fs, 1);
    EXPECT_GT(gs.clipped, 0);
    EXPECT_GT(gs.outside, 0);
    EXPECT_GT(fs.written, 30 * height);
    EXPECT_EQ(one.color.data, staged.color.data);
    EXPECT_EQ(one.depth.data, staged.depth.data);
    for (const int threads : {2, 3, 4, 7, -2, -3, -5}) {  // negative: that many, on the team
      GeometryStats threaded_gs;
      FillStats threaded_fs;
      Frame threaded;
      render_zbuffer(s, threaded, &threaded_gs, &threaded_fs, std::abs(threads),
                     threads < 0 ? &team : nullptr);
      EXPECT_EQ(threaded.color.data, staged.color.data) << threads << " " << height;
      EXPECT_EQ(threaded.depth.data, staged.depth.data) << threads << " " << height;
      EXPECT_EQ(threaded_gs.culled > 0, cull == Cull::Back);
      EXPECT_EQ(threaded_gs.triangles, gs.triangles);
      EXPECT_EQ(threaded_gs.window, gs.window);
      EXPECT_EQ(threaded_gs.clipped, gs.clipped);
      EXPECT_EQ(threaded_gs.outside, gs.outside);
      EXPECT_EQ(threaded_gs.culled, gs.culled);
      EXPECT_EQ(threaded_fs.triangles, fs.triangles);
      EXPECT_EQ(threaded_fs.fragments, fs.fragments);
      EXPECT_EQ(threaded_fs.written, fs.written);
    }
  }
}

// Strips: about four a thread, between 8 and 64 rows, so that every thread has a share of any
// frame and few small triangles straddle two.
TEST(RenderKind, StripsGiveEveryThreadAShareOfTheFrame) {
  EXPECT_EQ(strip_rows(1080, 1), 64);
  EXPECT_EQ(strip_rows(1080, 2), 64);
  EXPECT_EQ(strip_rows(1080, 8), 33);
  EXPECT_EQ(strip_rows(1080, 64), 8);
  EXPECT_EQ(strip_rows(7, 2), 8);
  for (const int height : {7, 100, 1080, 4320})
    for (const int threads : {2, 3, 8}) {
      const int rows = strip_rows(height, threads);
      const int strips = (height + rows - 1) / rows;
      if (height >= 4 * threads * kMinStripRows) {
        EXPECT_GE(strips, 2 * threads) << height;
      }
    }
}

// The hierarchy walk copies nothing of the scene (not the exact coordinates a scene read for the
// render kind keeps, whose reference counts are not atomic): threads walking one scene side by
// side each get every world triangle, in order, as one walk does.
TEST(RenderKind, ThreadsWalkOneSceneSideBySide) {
  const ProblemSet set = load_problem_set(test::source_path("problems/seeds/paperplane.yaml"));
  ASSERT_FALSE(set.problems.empty());
  const Scene& plane = std::any_cast<const RenderGiven&>(set.problems[0].given).spec.scene;
  ASSERT_FALSE(plane.objects.empty());
  const FlatScene flat = flatten(plane, false);
  ASSERT_GT(flat.triangles.size(), 1000u);
  std::vector<std::vector<WorldTriangle>> walked(4);
  side_by_side(4, [&](int k) {
    for (int round = 0; round < 20; ++round) {
      std::vector<WorldTriangle>& mine = walked[static_cast<std::size_t>(k)];
      mine.clear();
      for_each_world_triangle(plane, [&](const WorldTriangle& t) { mine.push_back(t); });
    }
  });
  for (const std::vector<WorldTriangle>& mine : walked) {
    ASSERT_EQ(mine.size(), flat.triangles.size());
    for (std::size_t t = 0; t < mine.size(); ++t) {
      EXPECT_EQ(mine[t].v, flat.triangles[t].v) << t;
      EXPECT_EQ(mine[t].object, flat.triangles[t].object) << t;
      EXPECT_EQ(mine[t].face, flat.triangles[t].face) << t;
    }
  }
}

// A render target kept from one frame to the next (as a GL context keeps its framebuffer): each
// render into it clears it first, and a new size reallocates it, so every frame is the one a
// fresh target gets, whatever was drawn into it before.
TEST(RenderKind, AReusedRenderTargetGivesTheFramesOfFreshOnes) {
  const ProblemSet set = load_problem_set(test::source_path("problems/seeds/paperplane.yaml"));
  ASSERT_FALSE(set.problems.empty());
  const Scene& plane = std::any_cast<const RenderGiven&>(set.problems[0].given).spec.scene;
  Scene small = plane, dark = plane;
  small.width = plane.width / 2 + 3;
  small.height = plane.height / 3 + 1;
  dark.background = Rgb{7, 9, 11};
  Frame target;
  int turn = 0;
  for (const Scene* s : std::vector<const Scene*>{&plane, &small, &dark, &plane, &small}) {
    FillStats reused, fresh;
    // One thread and two in turn (two fill the target band by band, clearing each band).
    render_zbuffer(*s, target, nullptr, &reused, 1 + turn++ % 2);
    const Frame expected = render_zbuffer(*s, nullptr, &fresh);
    EXPECT_EQ(target.color.width, s->width);
    EXPECT_EQ(target.color.height, s->height);
    EXPECT_EQ(target.depth.width, s->width);
    EXPECT_EQ(target.color.data, expected.color.data);
    EXPECT_EQ(target.depth.data, expected.depth.data);
    EXPECT_EQ(reused.written, fresh.written);
    EXPECT_GT(fresh.written, 0);
  }
  // The dark background shows where nothing is drawn, and only in the dark scene's frame.
  const auto dark_pixels = [&] {
    return std::count(target.color.data.begin(), target.color.data.end(), pack(Rgb{7, 9, 11}));
  };
  render_zbuffer(dark, target);
  EXPECT_GT(dark_pixels(), 1000);
  render_zbuffer(plane, target);
  EXPECT_EQ(dark_pixels(), 0);
}

// ---------------------------------------------------------------- exact decisions

// What the float pipeline (geometry() and trace_pixel() on doubles, no exact fallback) shows
// at a pixel of the API's window: the winning object's name.
std::string float_pipeline_winner(const Scene& s, int i, int window_row) {
  const FlatScene flat = flatten(s);
  const std::vector<WindowTriangle> tris = geometry(s, flat);
  const PixelTrace t = trace_pixel(tris, i, raster_row(window_row, s.height, s.api), s.background);
  if (t.winner < 0) return "background";
  const WorldTriangle& w =
      flat.triangles[static_cast<std::size_t>(tris[static_cast<std::size_t>(t.winner)].source)];
  return flat.objects[static_cast<std::size_t>(w.object)];
}

// problems/hard/render.yaml: each pair (on the boundary, 10⁻³⁰ off it) rounds to the same
// doubles, so the float pipeline answers both alike, one of them wrongly; the render kind
// answers each as exact arithmetic does, and its derivation says exact arithmetic decided.
TEST(RenderKind, HardCasesAreDecidedExactlyWhereFloatsCannot) {
  const ProblemSet set = load_problem_set(test::source_path("problems/hard/render.yaml"));
  ASSERT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
  const SetResult solved = solve_set(set, true);
  ASSERT_EQ(solved.problems.size(), 6u);
  std::map<std::string, std::string> exact, floats;
  for (std::size_t k = 0; k < set.problems.size(); ++k) {
    const ProblemResult& r = solved.problems[k];
    ASSERT_FALSE(r.error) << r.id;
    const RenderGiven& g = std::any_cast<const RenderGiven&>(set.problems[k].given);
    exact[r.id] = r.answers.find("object")->words.at(0);
    floats[r.id] = float_pipeline_winner(g.spec.scene, g.pixels[0][0], g.pixels[0][1]);
    bool said = false;
    for (const Step& st : r.derivation.steps())
      said =
          said ||
          st.note.en().find("xact arithmetic on the given numbers decided") != std::string::npos ||
          st.note.en().find("decided by exact arithmetic") != std::string::npos;
    EXPECT_TRUE(said) << r.id;
  }
  const std::map<std::string, std::string> want = {{"render-vertex-on-half-grid", "background"},
                                                   {"render-edge-through-centre", "t"},
                                                   {"render-face-edge-on", "background"},
                                                   {"render-face-1e-30-front", "s1"},
                                                   {"render-equal-depths", "p1"},
                                                   {"render-second-1e-30-nearer", "p2"}};
  EXPECT_EQ(exact, want);
  const std::pair<const char*, const char*> pairs[] = {
      {"render-vertex-on-half-grid", "render-edge-through-centre"},
      {"render-face-edge-on", "render-face-1e-30-front"},
      {"render-equal-depths", "render-second-1e-30-nearer"}};
  int wrong = 0;
  for (const auto& [a, b] : pairs) {
    EXPECT_EQ(floats[a], floats[b]) << a;  // the same doubles
    wrong += (floats[a] != want.at(a)) + (floats[b] != want.at(b));
  }
  EXPECT_EQ(wrong, 3);  // one of each pair
}

// On ordinary scenes (random decimal coordinates: no tie, no vertex on a half-grid point) the
// exact decisions are the float pipeline's: the same winner at every pixel and the same depth.
// Most decisions are proven on the doubles; the exact fallback is rare.
TEST(RenderKind, ExactDecisionsAgreeWithTheFloatPipelineOnOrdinaryScenes) {
  std::mt19937 rng(14);
  std::uniform_int_distribution<int> coord(-6000, 6000), depth(-8000, 4000), channel(0, 255);
  const char* apis[] = {"opengl", "directx", "processing"};
  long pixels = 0, exact_geometry = 0, triangles = 0;
  for (int n = 0; n < 12; ++n) {
    std::string objects;
    for (int k = 0; k < 5; ++k) {
      objects += fmt::format("          - {{name: o{}, triangle: [", k);
      for (int v = 0; v < 3; ++v)
        objects += fmt::format("{}[{}, {}, {}]", v ? ", " : "", coord(rng) / 1000.0,
                               coord(rng) / 1000.0, depth(rng) / 1000.0);
      objects += fmt::format("], fill: [{}, {}, {}]{}}}\n", channel(rng), channel(rng),
                             channel(rng), k % 2 ? ", cull: back" : "");
    }
    const ProblemSet set =
        load_problem_set_from_string(scene_yaml(apis[n % 3], objects, "[[0, 0]]"), "s.yaml");
    ASSERT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
    const RenderGiven& g = std::any_cast<const RenderGiven&>(set.problems[0].given);
    const Scene& s = g.spec.scene;
    const FlatScene flat = flatten(s);
    const std::vector<WindowTriangle> tris = geometry(s, flat);
    CertifiedScene cs = certified_geometry(s, flat, exact_clip_from_world(g.spec, s.api));
    exact_geometry += cs.exact_geometry;
    triangles += cs.stats.triangles;
    for (int j = 0; j < s.height; j += 2)
      for (int i = 0; i < s.width; i += 2) {
        const PixelTrace f = trace_pixel(tris, i, j, s.background);
        bool exact_depths = false;
        const PixelTrace e = certified_trace(cs, s, flat, i, j, exact_depths);
        ASSERT_EQ(f.winner < 0, e.winner < 0) << n << " " << i << " " << j;
        if (f.winner >= 0) {
          EXPECT_EQ(tris[static_cast<std::size_t>(f.winner)].source,
                    cs.pieces[static_cast<std::size_t>(e.winner)].source);
        }
        EXPECT_NEAR(f.depth, e.depth, 1e-6);
        EXPECT_EQ(f.color, e.color);
        EXPECT_FALSE(exact_depths);
        ++pixels;
      }
  }
  EXPECT_EQ(pixels, 12L * 32 * 24);
  EXPECT_EQ(triangles, 60);
  EXPECT_LE(exact_geometry, 1);
}

// ---------------------------------------------------------------- frustum render

int run_cli(const std::string& args) { return test::frustum_run(args).status; }

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(RenderCli, WritesPngAndScanlineGivesTheSameImage) {
  const std::string seed = test::source_path("problems/seeds/paperplane.yaml");
  const std::string dir = ::testing::TempDir();
  ASSERT_EQ(
      run_cli("render " + seed + " -o " + dir + "z.png --depth " + dir + "d.png --size 160x120"),
      0);
  ASSERT_EQ(run_cli("render " + seed + " -o " + dir + "s.png --size 160x120 --method scanline"), 0);
  const std::string z = file_bytes(dir + "z.png");
  ASSERT_GT(z.size(), 100u);
  EXPECT_EQ(z.substr(1, 3), "PNG");
  EXPECT_EQ(z, file_bytes(dir + "s.png"));
  EXPECT_EQ(file_bytes(dir + "d.png").substr(1, 3), "PNG");
  EXPECT_EQ(run_cli("render " + seed + " -o " + dir + "x.png --id nope"), 1);
  EXPECT_EQ(run_cli("render " + seed + " -o " + dir + "x.png --size 0x5"), 2);
}

// The file as zlib reads it, independently of libpng: every chunk's CRC, and the image data
// (the IDAT chunks joined) inflated with its Adler-32 checked. Returns the inflated length, or
// −1 when a check fails or it is longer than `capacity`.
long inflated_image_data(const std::string& bytes, std::size_t capacity) {
  std::string idat;
  for (std::size_t at = 8; at + 12 <= bytes.size();) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(bytes[k]); };
    const std::size_t n = std::size_t{byte(at)} << 24 | std::size_t{byte(at + 1)} << 16 |
                          std::size_t{byte(at + 2)} << 8 | byte(at + 3);
    if (at + 12 + n > bytes.size()) return -1;
    const std::string type_and_body = bytes.substr(at + 4, 4 + n);
    const uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(type_and_body.data()),
                            static_cast<uInt>(type_and_body.size()));
    uLong stored = 0;
    for (int k = 0; k < 4; ++k) stored = stored << 8 | byte(at + 8 + n + k);
    if (crc != stored) return -1;
    if (type_and_body.compare(0, 4, "IDAT") == 0) idat += type_and_body.substr(4);
    at += 12 + n;
  }
  std::vector<Bytef> out(capacity);
  uLongf length = out.size();
  if (uncompress(out.data(), &length, reinterpret_cast<const Bytef*>(idat.data()),
                 static_cast<uLong>(idat.size())) != Z_OK)
    return -1;
  return static_cast<long>(length);
}

// Writes the frame with `frustum render`'s writer, reads it back with libpng's own reader and
// checks every channel of every pixel: row r of the file is the frame's row height − 1 − r
// (raster rows go up, a PNG's down). Returns the file's colour type (−1 after a failure).
// Written again with the frame scanned by 2, 3 and 8 threads, started or a team's, into new
// files: the same bytes. The first file is written over a longer one (the writer writes over a
// file in place and cuts it to length): nothing of the older file is left after the image.
int png_round_trip(const Image<std::uint32_t>& img, const std::string& name) {
  const std::string path = ::testing::TempDir() + name;
  std::filesystem::remove(path);
  {
    std::ofstream older(path, std::ios::binary);
    older << std::string(std::size_t(1) << 20, '\xAB');
  }
  if (!write_color_png(path, img)) {
    ADD_FAILURE() << path << ": not written";
    return -1;
  }
  ThreadTeam team(3);
  for (const int threads : {2, 3, 8, -2, -3, -8}) {  // negative: on the team's threads
    const std::string again = ::testing::TempDir() + std::to_string(threads) + name;
    std::filesystem::remove(again);
    EXPECT_TRUE(write_color_png(again, img, std::abs(threads), threads < 0 ? &team : nullptr));
    EXPECT_EQ(file_bytes(again), file_bytes(path)) << threads << " threads";
  }
  png_image read{};
  read.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&read, path.c_str())) {
    ADD_FAILURE() << path << ": not read";
    return -1;
  }
  read.format = PNG_FORMAT_RGBA;
  EXPECT_EQ(read.width, static_cast<png_uint_32>(img.width));
  EXPECT_EQ(read.height, static_cast<png_uint_32>(img.height));
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(read));
  if (!png_image_finish_read(&read, nullptr, pixels.data(), 0, nullptr)) {
    ADD_FAILURE() << path << ": not decoded";
    return -1;
  }
  for (int r = 0; r < img.height; ++r)
    for (int x = 0; x < img.width; ++x) {
      const std::uint32_t want = img.at(x, img.height - 1 - r);
      const std::uint8_t* got = &pixels[(static_cast<std::size_t>(r) * img.width + x) * 4];
      for (int c = 0; c < 4; ++c)
        if (got[c] != ((want >> (8 * c)) & 0xFF)) {
          ADD_FAILURE() << path << ": row " << r << " x " << x << " channel " << c;
          return -1;
        }
    }
  // zlib's own reading: the CRCs and the Adler-32 hold, and the data is one filter byte and
  // the row's samples per row.
  const std::string bytes = file_bytes(path);
  const int bits = static_cast<unsigned char>(bytes.at(24));
  const int channels = static_cast<unsigned char>(bytes.at(25)) == PNG_COLOR_TYPE_RGBA ? 4 : 1;
  const long expected = static_cast<long>(img.height) * (1 + (img.width * channels * bits + 7) / 8);
  EXPECT_EQ(inflated_image_data(bytes, static_cast<std::size_t>(expected) + 1), expected) << path;
  // The IHDR chunk's colour type, byte 25 of the file.
  return static_cast<unsigned char>(bytes.at(25));
}

// The PNG holds the frame pixel for pixel: decoded by libpng's own reader, row r of the file is
// the frame's row height − 1 − r (raster rows go up, a PNG's down), every channel of every pixel
// (each pixel distinct here, alpha included).
TEST(RenderCli, PngHoldsTheFramePixelForPixel) {
  Image<std::uint32_t> img;
  img.width = 37;
  img.height = 23;
  img.data.resize(static_cast<std::size_t>(img.width) * img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.at(x, y) = static_cast<std::uint32_t>(x * 7) | static_cast<std::uint32_t>(y * 11) << 8 |
                     static_cast<std::uint32_t>((x * y) & 0xFF) << 16 |
                     static_cast<std::uint32_t>(255 - x) << 24;
  EXPECT_EQ(png_round_trip(img, "frame.png"), PNG_COLOR_TYPE_RGBA);
}

// A frame of at most 256 opaque colours is written as a palette image (1, 2, 4 or 8 bits a
// pixel: at most 2, 4, 16 or 256 colours), any other as RGBA; each holds the frame pixel for
// pixel. Runs and scattered pixels, on rows of 301 pixels (the last byte of a packed row partly
// padding), and every palette size on either side of a bit depth's limit; 200 rows, so that two
// or three threads each scan a part (a colour may first appear in any part).
TEST(RenderCli, FewOpaqueColoursMakeAPaletteImageWithTheSamePixels) {
  for (const int colours : {1, 2, 3, 4, 5, 16, 17, 255, 256, 257, 4000}) {
    Image<std::uint32_t> img;
    img.width = 301;
    img.height = 200;
    img.data.resize(static_cast<std::size_t>(img.width) * img.height);
    std::mt19937 rng(static_cast<unsigned>(colours));
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        // Runs of equal pixels, scattered pixels, and in the 14 bottom raster rows (the file's
        // last) every colour in turn, so that all of them appear.
        const int k = y >= img.height - 14 ? (y * img.width + x) % colours
                      : x % 41 < 40        ? static_cast<int>(rng() % colours)
                                           : (y + x) % colours;
        img.at(x, y) = pack(Rgb{static_cast<std::uint8_t>(k * 37), static_cast<std::uint8_t>(k),
                                static_cast<std::uint8_t>(k >> 8)});
        if (y < img.height - 14 && x > 0 && x % 7 != 0) img.at(x, y) = img.at(x - 1, y);
      }
    std::set<std::uint32_t> used(img.data.begin(), img.data.end());
    ASSERT_EQ(static_cast<int>(used.size()), colours);
    IndexedImage indexed;
    EXPECT_EQ(index_colors(img, indexed), colours <= 256) << colours;
    if (colours <= 256) {
      EXPECT_EQ(static_cast<int>(indexed.palette.size()), colours);
      EXPECT_EQ(indexed.palette[0], img.at(0, img.height - 1));  // the top row's first pixel
      EXPECT_EQ(indexed.indices[0], 0);
    }
    const std::string name = fmt::format("c{}.png", colours);
    EXPECT_EQ(png_round_trip(img, name),
              colours <= 256 ? PNG_COLOR_TYPE_PALETTE : PNG_COLOR_TYPE_RGBA)
        << colours;
    // The IHDR's bit depth, byte 24 of the file.
    const int bits = colours <= 2 ? 1 : colours <= 4 ? 2 : colours <= 16 ? 4 : 8;
    EXPECT_EQ(static_cast<int>(file_bytes(::testing::TempDir() + name).at(24)), bits) << colours;
  }
  // Heights about a piece of the compressed stream (64 rows) and a single row.
  for (const int height : {1, 63, 64, 65, 129}) {
    Image<std::uint32_t> img(45, height, pack(Rgb{9, 8, 7}));
    for (int y = 0; y < height; ++y)
      img.at((y * 7) % 45, y) = pack(Rgb{200, 100, static_cast<std::uint8_t>(y % 2 ? 50 : 0)});
    EXPECT_EQ(png_round_trip(img, fmt::format("h{}.png", height)), PNG_COLOR_TYPE_PALETTE);
  }
  // One pixel not opaque among few colours: RGBA, so that its alpha is kept.
  Image<std::uint32_t> img(40, 30, pack(Rgb{1, 2, 3}));
  img.at(5, 6) &= 0x7fffffffu;
  EXPECT_EQ(png_round_trip(img, "alpha.png"), PNG_COLOR_TYPE_RGBA);
}

// The image data's Adler-32 taken from the rows' runs is zlib's over the bytes: rows of every bit
// depth, widths that end a byte part-way, runs from one pixel to the whole row, and runs that
// begin and end inside a byte (a byte shared by two or more runs).
TEST(RenderCli, TheChecksumFromTheRunsIsZlibsOverTheBytes) {
  std::mt19937 rng(7);
  for (const int colours : {2, 3, 4, 5, 16, 17, 256})
    for (const int width : {1, 7, 8, 9, 301, 1920}) {
      Image<std::uint32_t> img(width, 40, 0);
      for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < width;) {
          // Short runs on some rows, long ones on others, one colour on the last row.
          const int n = y == 0 ? width : 1 + static_cast<int>(rng() % (y % 3 == 0 ? 3 : 600));
          const auto k = static_cast<std::uint8_t>(rng() % colours);
          for (int i = x; i < std::min(width, x + n); ++i)
            img.at(i, y) = pack(Rgb{k, static_cast<std::uint8_t>(k / 3), 1});
          x += n;
        }
      FrameRuns runs;
      ASSERT_TRUE(frame_runs(img, runs));
      const int bits = palette_bit_depth(runs.palette.size());
      std::vector<std::uint8_t> row(1 + static_cast<std::size_t>((width * bits + 7) / 8));
      uLong zlib = adler32(0L, Z_NULL, 0);
      std::uint32_t ours = 1;
      for (int r = 0; r < img.height; ++r) {
        row[0] = 0;
        pack_row(runs, r, bits, row.data() + 1);
        zlib = adler32(zlib, row.data(), static_cast<uInt>(row.size()));
        ours = adler32_packed_row(ours, runs, r, bits, row.data() + 1);
        ASSERT_EQ(ours, zlib) << colours << " colours, width " << width << ", row " << r;
      }
    }
  // Rows of 2²⁰ pixels: of one colour (the closed forms' products), and of 256 colours changing
  // at every pixel (2²⁰ bytes summed one by one before the row's reduction) — within 64 bits.
  for (const int colours : {1, 256}) {
    Image<std::uint32_t> wide(1 << 20, 2, 0);
    for (int x = 0; x < wide.width; ++x)
      for (int y = 0; y < 2; ++y)
        wide.at(x, y) = pack(Rgb{static_cast<std::uint8_t>(x % colours + y), 255, 255});
    FrameRuns runs;
    ASSERT_TRUE(frame_runs(wide, runs));
    const int bits = palette_bit_depth(runs.palette.size());
    std::vector<std::uint8_t> row(1 + static_cast<std::size_t>(wide.width) * bits / 8);
    uLong zlib = adler32(0L, Z_NULL, 0);
    std::uint32_t ours = 1;
    for (int r = 0; r < 2; ++r) {
      row[0] = 0;
      pack_row(runs, r, bits, row.data() + 1);
      zlib = adler32(zlib, row.data(), static_cast<uInt>(row.size()));
      ours = adler32_packed_row(ours, runs, r, bits, row.data() + 1);
    }
    EXPECT_EQ(ours, zlib) << colours << " colours";
  }
}

// The paper plane (a lit, flat-shaded scene) is a palette image of the rendered frame.
TEST(RenderCli, ThePaperPlaneIsAPaletteImageOfItsFrame) {
  const ProblemSet set = load_problem_set(test::source_path("problems/seeds/paperplane.yaml"));
  ASSERT_FALSE(set.problems.empty());
  const Scene& scene = std::any_cast<const RenderGiven&>(set.problems[0].given).spec.scene;
  const Frame frame = render_zbuffer(scene);
  EXPECT_EQ(png_round_trip(frame.color, "plane.png"), PNG_COLOR_TYPE_PALETTE);
}

}  // namespace
}  // namespace frustum
