// Pictures: the SVG writer, hidden lines removed per segment (cross-checked by ray
// casting), painter vs z-buffer, and `frustum draw`.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>

#include "app/commands.hpp"
#include "solver/derivation/svg.hpp"
#include "solver/visibility/hidden_lines.hpp"
#include "solver/visibility/painter_vs_zbuffer.hpp"
#include "solver/visibility/pictures.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// ---- A simple well-formedness check: balanced tags, one <svg> root ------------------------

struct XmlCheck {
  bool ok = true;
  std::string problem;
  std::map<std::string, int> elements;  // tag → count
};

XmlCheck check_xml(const std::string& s) {
  XmlCheck c;
  std::vector<std::string> open;
  int roots = 0;
  for (std::size_t at = s.find('<'); at != std::string::npos; at = s.find('<', at + 1)) {
    const std::size_t end = s.find('>', at);
    if (end == std::string::npos) return {false, "unterminated tag", {}};
    const std::string tag = s.substr(at + 1, end - at - 1);
    if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0)
      return {false, "unbalanced quotes in <" + tag + ">", {}};
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1))
        return {false, "unexpected </" + tag.substr(1) + ">", {}};
      open.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" \n/"));
    ++c.elements[name];
    if (open.empty()) ++roots;
    if (tag.back() != '/') open.push_back(name);
  }
  if (!open.empty()) return {false, "<" + open.back() + "> not closed", {}};
  if (roots != 1 || c.elements["svg"] != 1) return {false, "expected one <svg> root", {}};
  // Text between tags must not hold a raw '&' that is not an entity.
  for (std::size_t at = s.find('&'); at != std::string::npos; at = s.find('&', at + 1))
    if (s.find(';', at) == std::string::npos || s.find(';', at) - at > 6)
      return {false, "raw &", {}};
  return c;
}

int count_of(const std::string& s, const std::string& what) {
  int n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

TEST(Svg, WritesAWellFormedDocumentWithEscapedText) {
  Svg svg(100, 50);
  svg.title("a < b & \"c\"");
  svg.style("    .x { stroke: red; }\n");
  svg.begin_group("g1");
  svg.line({0, 0}, {10.126, -3}, "x");
  svg.polygon({{0, 0}, {1, 0}, {0, 1}}, "", "fill=\"#fff\"");
  svg.rect(1, 2, 3, 4, "r");
  svg.circle({5, 5}, 2, "c");
  svg.end_group();
  svg.text({1, 1}, "x < y && 'z'", "t");
  const std::string s = svg.str();
  const XmlCheck c = check_xml(s);
  ASSERT_TRUE(c.ok) << c.problem << "\n" << s;
  EXPECT_EQ(c.elements.at("line"), 1);
  EXPECT_EQ(c.elements.at("g"), 1);
  EXPECT_NE(s.find("x2=\"10.13\" y2=\"-3\""), std::string::npos) << s;
  EXPECT_NE(s.find("<title>a &lt; b &amp; &quot;c&quot;</title>"), std::string::npos) << s;
  EXPECT_NE(s.find(">x &lt; y &amp;&amp; &#39;z&#39;</text>"), std::string::npos) << s;
  EXPECT_NE(s.find("viewBox=\"0 0 100 50\""), std::string::npos);
  EXPECT_EQ(svg_number(-0.001), "0");
  EXPECT_EQ(svg_number(2.5), "2.5");
  EXPECT_THROW(svg_number(std::nan("")), std::invalid_argument);
  Svg open(10, 10);
  open.begin_group("g");
  EXPECT_THROW((void)open.str(), std::logic_error);
  EXPECT_THROW(Svg(1, 1).end_group(), std::logic_error);
}

// ---- Hidden lines per segment -----------------------------------------------------------

// Brute force, independent of hidden_lines: does the ray from x to the eye cross a face's
// interior (the crossing point inside the face polygon by the crossing-number rule)? Rays that
// pass within kGraze of a face's boundary are ties (integer scenes make them common: an edge
// seen exactly behind another) and are reported as such, not judged.
enum class Ray { Clear, Blocked, Grazing };
constexpr double kGraze = 1e-7;

double segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b) {
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (a + t * (b - a) - p).norm();
}

Ray cast_ray(const Mesh& m, const MeshEdge& e, const Eigen::Vector3d& x,
             const Eigen::Vector3d& eye) {
  Ray result = Ray::Clear;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const std::vector<int>& face = m.faces[f];
    if (std::count(face.begin(), face.end(), e.i) && std::count(face.begin(), face.end(), e.j))
      continue;
    std::vector<Eigen::Vector3d> v;
    for (int k : face) v.push_back(to_double(m.vertices[static_cast<std::size_t>(k)]));
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < v.size(); ++k) n += v[k].cross(v[(k + 1) % v.size()]);
    n.normalize();
    const Eigen::Vector3d dir = eye - x;
    const double denom = n.dot(dir);
    if (std::abs(denom) < kGraze * dir.norm()) {
      if (std::abs(n.dot(v[0] - x)) < kGraze)
        result = Ray::Grazing;  // the ray runs in the face's plane
      continue;
    }
    const double s = n.dot(v[0] - x) / denom;
    if (s * dir.norm() < kGraze) continue;  // x itself on the face's plane, or the face behind x
    if (s >= 1) continue;
    const Eigen::Vector3d y = x + s * dir;
    double boundary = 1e300;
    for (std::size_t k = 0; k < v.size(); ++k)
      boundary = std::min(boundary, segment_distance(y, v[k], v[(k + 1) % v.size()]));
    if (boundary < kGraze) {
      result = Ray::Grazing;
      continue;
    }
    // Crossing number in the face's plane (faces may be concave), dropping n's largest axis.
    int drop = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(n(k)) > std::abs(n(drop))) drop = k;
    const int u = (drop + 1) % 3, w = (drop + 2) % 3;
    bool inside = false;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const Eigen::Vector3d &p = v[k], &q = v[(k + 1) % v.size()];
      if ((p(w) > y(w)) != (q(w) > y(w)) &&
          y(u) < p(u) + (y(w) - p(w)) * (q(u) - p(u)) / (q(w) - p(w)))
        inside = !inside;
    }
    if (inside) return Ray::Blocked;
  }
  return result;
}

// Compares every edge's spans with brute force at many sample points (away from the cut
// points, where a sample could fall on either side by rounding). Returns the samples checked;
// an eye in a face's plane is skipped (grazing rays are a tie the brute force cannot judge).
int compare_with_rays(const Mesh& m, const Vec3<Exact>& eye, int* split_edges = nullptr) {
  const HiddenLines h = hidden_lines(m, eye);
  if (std::any_of(h.faces.begin(), h.faces.end(),
                  [](const FaceTest& f) { return f.facing == Facing::EdgeOn; }))
    return 0;
  const Eigen::Vector3d e = to_double(eye);
  int checked = 0;
  for (const EdgeLines& l : h.edges) {
    EXPECT_FALSE(l.spans.empty());
    EXPECT_EQ(l.spans.front().t0, 0.0);
    EXPECT_EQ(l.spans.back().t1, 1.0);
    for (std::size_t k = 1; k < l.spans.size(); ++k) {
      EXPECT_EQ(l.spans[k].t0, l.spans[k - 1].t1) << l.edge.name();
      EXPECT_NE(l.spans[k].visible, l.spans[k - 1].visible) << l.edge.name();
    }
    const Eigen::Vector3d a = to_double(m.vertices[static_cast<std::size_t>(l.edge.i)]);
    const Eigen::Vector3d b = to_double(m.vertices[static_cast<std::size_t>(l.edge.j)]);
    for (int s = 1; s < 40; ++s) {
      const double t = s / 40.0;
      bool near_cut = false, visible = true;
      for (const EdgeSpan& span : l.spans) {
        near_cut |= std::abs(t - span.t0) < 1e-6 || std::abs(t - span.t1) < 1e-6;
        if (t >= span.t0 && t <= span.t1) visible = span.visible;
      }
      const Ray ray = cast_ray(m, l.edge, a + t * (b - a), e);
      if (near_cut || ray == Ray::Grazing) continue;
      EXPECT_EQ(visible, ray == Ray::Clear)
          << "edge " << l.edge.name() << " at t = " << t << " from eye " << e.transpose();
      ++checked;
    }
  }
  if (split_edges) *split_edges += h.split_edges;
  return checked;
}

Mesh cube_at(const Eigen::Vector3i& offset, int half) {
  Mesh c = named_solid("cube");
  for (Vec3<Exact>& v : c.vertices)
    for (int k = 0; k < 3; ++k) v(k) = canonical(v(k) * half + offset(k));
  return c;
}

// Two cubes in one mesh: a large one behind and beside a small one.
Mesh two_cubes() {
  Mesh m = cube_at({0, 0, 0}, 1);
  const Mesh back = cube_at({2, 1, -5}, 2);
  const int base = static_cast<int>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), back.vertices.begin(), back.vertices.end());
  for (std::vector<int> f : back.faces) {
    for (int& k : f) k += base;
    m.faces.push_back(f);
  }
  return m;
}

TEST(HiddenLines, TwoCubesAgreeWithRayCastingPerSegment) {
  const Mesh m = two_cubes();
  ASSERT_TRUE(check_mesh(m).closed);
  std::mt19937 rng(5005);
  std::uniform_int_distribution<int> d(-6, 6);
  int checked = 0, split = 0;
  for (int trial = 0; trial < 24; ++trial) {
    const Vec3<Exact> eye(d(rng), d(rng), 9 + trial % 4);
    checked += compare_with_rays(m, eye, &split);
  }
  EXPECT_GT(checked, 5000);
  EXPECT_GT(split, 12) << "the scene must make the front cube cover parts of the back cube's edges";
}

TEST(HiddenLines, ConcaveLPrismAgreesWithRayCastingPerSegment) {
  const ProblemSet set = load_problem_set(test::source_path("problems/examples/visibility.yaml"));
  const ProblemSpec* spec = set.find("notched-prism-culling");
  ASSERT_NE(spec, nullptr);
  const Mesh m = spec->info->drawable(spec->given).mesh;
  int split = 0, checked = 0;
  // Low eyes beside an arm see it cover part of the other arm's notch face.
  const Exact half = Exact(1) / 2;
  for (const Vec3<Exact>& eye :
       {Vec3<Exact>(5, 5, 3), Vec3<Exact>(6, 4, 5), Vec3<Exact>(-2, 7, 4), Vec3<Exact>(4, 8, -3),
        Vec3<Exact>(8, -4, half), Vec3<Exact>(-4, 8, half)})
    checked += compare_with_rays(m, eye, &split);
  EXPECT_GT(checked, 3000);
  EXPECT_GT(split, 0) << "the notch must hide part of an edge from some eye";
}

// A single convex solid: per-segment removal finds nothing the edge classes do not (no edge
// split, back–back edges covered, the rest visible), from many eyes.
TEST(HiddenLines, ConvexSolidsNeedNoSplittingFromRandomEyes) {
  std::mt19937 rng(303);
  std::uniform_int_distribution<int> d(-20, 20);
  int checked = 0;
  for (const std::string& name : solid_names()) {
    const Mesh m = named_solid(name);
    for (int trial = 0; trial < 30; ++trial) {
      const Vec3<Exact> eye(Exact(d(rng)) / 3, Exact(d(rng)) / 3, Exact(d(rng)) / 3);
      if (to_double(eye).norm() < 2.5) continue;
      const HiddenLines h = hidden_lines(m, eye);
      if (std::any_of(h.faces.begin(), h.faces.end(),
                      [](const FaceTest& f) { return f.facing == Facing::EdgeOn; }))
        continue;
      EXPECT_EQ(h.split_edges, 0) << name << " eye " << to_double(eye).transpose();
      for (const EdgeLines& l : h.edges) {
        ASSERT_EQ(l.spans.size(), 1u) << name << " " << l.edge.name();
        EXPECT_EQ(l.spans[0].visible, l.cls != EdgeClass::Hidden) << name << " " << l.edge.name();
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  // Seed 003's icosahedron from the seed set's eye (3, 5, 7), sampled along every edge.
  EXPECT_GT(compare_with_rays(named_solid("icosahedron"), Vec3<Exact>(3, 5, 7)), 1000);
}

TEST(HiddenLines, IntervalsMergeAndDropSlivers) {
  EXPECT_EQ(merge_intervals({{0.5, 0.7}, {0.1, 0.2}, {0.65, 0.9}, {0.3, 0.3 + 1e-12}, {-1, 0.05}}),
            (std::vector<Interval>{{0, 0.05}, {0.1, 0.2}, {0.5, 0.9}}));
  // A triangle in z = 0 covering the middle of a segment behind it, seen from above.
  const Occluder o{
      {Eigen::Vector3d(-1, -1, 0), Eigen::Vector3d(1, -1, 0), Eigen::Vector3d(0, 2, 0)}, 0};
  const std::vector<Interval> c = covered_by({-4, 0, -1}, {4, 0, -1}, {0, 0, 10}, o);
  ASSERT_EQ(c.size(), 1u);
  // Seen from (0, 0, 10) the segment at z = −1 projects scaled by 10/11: x ∈ [−4, 4] → the
  // triangle's edge at y = 0 spans x ∈ [−2/3, 2/3]·(11/10)… cut points t = (4 ± x·11/10)/8.
  const double x_edge = 2.0 / 3.0 * 11.0 / 10.0;
  EXPECT_NEAR(c[0].first, (4 - x_edge) / 8, 1e-12);
  EXPECT_NEAR(c[0].second, (4 + x_edge) / 8, 1e-12);
  // In front of the triangle, nothing is covered; seen edge-on, nothing either.
  EXPECT_TRUE(covered_by({-4, 0, 1}, {4, 0, 1}, {0, 0, 10}, o).empty());
  EXPECT_TRUE(covered_by({-4, 0, -1}, {4, 0, -1}, {0, 5, 0}, o).empty());
}

// ---- Pictures ---------------------------------------------------------------------------

const ProblemSpec& seed_problem(const ProblemSet& set, const std::string& id) {
  const ProblemSpec* p = set.find(id);
  if (!p) throw std::runtime_error("no problem " + id);
  return *p;
}

TEST(Pictures, Seed003IcosahedronHasOneLinePerEdgeByClass) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/003_polygons_backface.yaml"));
  const ProblemSpec& spec = seed_problem(set, "seed003-ico-hidden-lines");
  const ProblemResult solved = solve_problem(spec, set.file, false);
  ASSERT_FALSE(solved.error) << test::error_text(solved);
  std::map<std::string, int> want;
  for (const auto& [edge, cls] : solved.answers.find("edges")->entries) ++want[cls];
  PictureOptions o;
  o.title = spec.id;
  const Picture p = draw_picture(spec.info->drawable(spec.given), o);
  const XmlCheck c = check_xml(p.svg);
  ASSERT_TRUE(c.ok) << c.problem;
  EXPECT_EQ(c.elements.at("line"), 30);  // one per edge: none is split
  EXPECT_EQ(count_of(p.svg, "class=\"visible\""), want["visible"]);
  EXPECT_EQ(count_of(p.svg, "class=\"silhouette\""), want["silhouette"]);
  EXPECT_EQ(count_of(p.svg, "class=\"hidden\""), want["hidden"]);
  EXPECT_EQ(want["visible"] + want["silhouette"] + want["hidden"], 30);
  EXPECT_GT(want["silhouette"], 0);
  EXPECT_EQ(count_of(p.svg, "class=\"vertex\"") + count_of(p.svg, "class=\"vertex-back\""), 12);
  EXPECT_NE(p.summary.find("0 split"), std::string::npos) << p.summary;
}

TEST(PainterVsZBuffer, SeparableSceneHasNoDifferingPixels) {
  // Parallel squares at z = −2, −8, −5, overlapping on screen, seen from an eye and along −z.
  const std::vector<Polygon3<Exact>> polys = {
      {Vec3<Exact>(-1, -1, -2), Vec3<Exact>(1, -1, -2), Vec3<Exact>(1, 1, -2),
       Vec3<Exact>(-1, 1, -2)},
      {Vec3<Exact>(-3, -3, -8), Vec3<Exact>(3, -3, -8), Vec3<Exact>(3, 3, -8),
       Vec3<Exact>(-3, 3, -8)},
      {Vec3<Exact>(0, 0, -5), Vec3<Exact>(2, 0, -5), Vec3<Exact>(2, 2, -5), Vec3<Exact>(0, 2, -5)}};
  for (const DepthViewer& v : {DepthViewer{Vec3<Exact>(0, 0, 4), std::nullopt},
                               DepthViewer{std::nullopt, Vec3<Exact>(0, 0, -1)}}) {
    const PainterVsZBuffer r = painter_vs_zbuffer(polys, v, Api::OpenGL, 40);
    EXPECT_TRUE(r.differing.empty()) << r.differing.size();
    EXPECT_TRUE(r.sort.conflicts.empty());
    std::set<std::string> seen;
    for (const std::string& label : r.zbuffer.data) seen.insert(label);
    EXPECT_EQ(seen, (std::set<std::string>{".", "0", "1", "2"})) << "every square shows somewhere";
  }
}

TEST(PainterVsZBuffer, FailureCasesDifferWhereThePainterIsWrong) {
  for (const char* id : {"depth-sort-cyclic", "depth-sort-interpenetrating"}) {
    const ProblemSet set = load_problem_set(test::source_path("problems/examples/visibility.yaml"));
    const Drawable d = seed_problem(set, id).info->drawable(seed_problem(set, id).given);
    const PainterVsZBuffer r = painter_vs_zbuffer(d.polygons, d.viewer, Api::OpenGL, 48);
    EXPECT_GT(r.differing.size(), 10u) << id;
    EXPECT_FALSE(r.sort.conflicts.empty()) << id;
    // Each differing pixel is covered in both frames, and the painter shows a polygon it drew
    // after the nearest one (a farther polygon painted over it).
    std::map<std::string, std::size_t> position;
    for (std::size_t k = 0; k < r.sort.order.size(); ++k)
      position[std::to_string(r.sort.order[k])] = k;
    for (const auto& [i, j] : r.differing) {
      ASSERT_NE(r.painter.at(i, j), kBackground);
      ASSERT_NE(r.zbuffer.at(i, j), kBackground);
      EXPECT_GT(position.at(r.painter.at(i, j)), position.at(r.zbuffer.at(i, j)))
          << id << " pixel " << i << ", " << j;
    }
  }
}

TEST(Pictures, PainterPictureIsWellFormedAndMarksTheDifferences) {
  const ProblemSet set = load_problem_set(test::source_path("problems/examples/visibility.yaml"));
  const ProblemSpec& spec = seed_problem(set, "depth-sort-cyclic");
  PictureOptions o;
  o.raster = 32;
  const Picture p = draw_picture(spec.info->drawable(spec.given), o);
  const XmlCheck c = check_xml(p.svg);
  ASSERT_TRUE(c.ok) << c.problem;
  const PainterVsZBuffer r =
      painter_vs_zbuffer(spec.info->drawable(spec.given).polygons,
                         spec.info->drawable(spec.given).viewer, Api::OpenGL, 32);
  EXPECT_EQ(count_of(p.svg, "class=\"diff\""), 2 * static_cast<int>(r.differing.size()));
  EXPECT_EQ(count_of(p.svg, "class=\"outline\""), 6);
  EXPECT_NE(p.summary.find(fmt::format("{} pixels differ", r.differing.size())), std::string::npos)
      << p.summary;
}

// ---- frustum draw -----------------------------------------------------------------------

struct DrawRun {
  int status;
  std::string out, err;
};

DrawRun draw(const std::string& set, const std::string& id, const std::string& output = "") {
  std::ostringstream out, err;
  const int status =
      app::run_draw(test::source_path(set), id, output, 24, app::Output{out, err, false}, Lang::En);
  return {status, out.str(), err.str()};
}

TEST(DrawCommand, WritesTheSvgAndSaysWhatItDrew) {
  const std::string file = ::testing::TempDir() + "frustum_draw_test.svg";
  const DrawRun r =
      draw("problems/seeds/003_polygons_backface.yaml", "seed003-ico-hidden-lines", file);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("30 edges"), std::string::npos) << r.out;
  std::ifstream in(file);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(check_xml(svg).ok);
  std::remove(file.c_str());
  const DrawRun stdout_run =
      draw("problems/examples/visibility.yaml", "depth-sort-interpenetrating");
  ASSERT_EQ(stdout_run.status, 0) << stdout_run.err;
  EXPECT_TRUE(check_xml(stdout_run.out).ok);
}

TEST(DrawCommand, ClearErrorsForUndrawableKindsAndBadProblems) {
  const DrawRun vectors =
      draw("problems/seeds/003_polygons_backface.yaml", "seed003-cross-product");
  EXPECT_EQ(vectors.status, 1);
  EXPECT_NE(vectors.err.find("kind vectors, which cannot be drawn"), std::string::npos)
      << vectors.err;
  EXPECT_NE(vectors.err.find("edge_visibility"), std::string::npos) << vectors.err;
  const DrawRun missing = draw("problems/seeds/003_polygons_backface.yaml", "no-such-id");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("no problem with id 'no-such-id'"), std::string::npos);
  const DrawRun unwritable = draw("problems/seeds/003_polygons_backface.yaml",
                                  "seed003-ico-hidden-lines", "/nonexistent-dir/x.svg");
  EXPECT_EQ(unwritable.status, 1);
  EXPECT_NE(unwritable.err.find("cannot write"), std::string::npos);
}

TEST(DrawCommand, EyeInsideTheSolidIsAnErrorAtTheEye) {
  const ProblemSet set = load_problem_set_from_string(
      test::one("edge_visibility", "{solid: cube, eye: [\"1/2\", 0, 0]}"), "inside.yaml");
  const ProblemSpec& spec = set.problems.at(0);
  EXPECT_THROW(draw_picture(spec.info->drawable(spec.given), PictureOptions{}), DomainError);
  try {
    draw_picture(spec.info->drawable(spec.given), PictureOptions{});
  } catch (const DomainError& e) {
    EXPECT_EQ(e.field(), "eye");
    EXPECT_NE(std::string(e.what()).find("not in front of the eye"), std::string::npos) << e.what();
  }
}

// What a picture says in words: its <title>, and the caption lines and panel names (the <text>
// elements without a class; vertex and polygon numbers have one), one a line, as escaped.
std::string picture_words(const std::string& svg) {
  std::string out;
  for (const std::string_view open : {"<title>", "<text x="}) {
    for (std::size_t at = svg.find(open); at != std::string::npos; at = svg.find(open, at + 1)) {
      const std::size_t from = svg.find('>', at) + 1;
      out += svg.substr(from, svg.find('<', from) - from) + "\n";
    }
  }
  return out;
}

// Runs of two or more Latin letters that are not an api's name (as the set writes it: opengl).
std::vector<std::string> latin_words(const std::string& text) {
  std::vector<std::string> out;
  const auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  for (std::size_t i = 0; i < text.size();) {
    std::size_t j = i;
    while (j < text.size() && letter(text[j])) ++j;
    const std::string word = text.substr(i, j - i);
    if (word.size() >= 2 && !parse_api(word)) out.push_back(word);
    i = j == i ? i + 1 : j;
  }
  return out;
}

// The captions, the <title> and the summary in the reader's language: the lecture's words, no
// English word (numbers, coordinates, the api's name and pair names stay as written); English
// as before.
// Every bundled picture's caption writes its points as a student would: no rounding residue
// (−1.85037e−17 for 0; a scene of size 1e100 keeps its exponents), no −0.
TEST(Pictures, CaptionsWritePointsWithoutRoundingResidue) {
  int drawn = 0;
  for (const char* dir : {"problems/seeds", "problems/examples", "problems/hard"})
    for (const auto& f : std::filesystem::directory_iterator(test::source_path(dir))) {
      if (f.path().extension() != ".yaml") continue;
      const ProblemSet set = load_problem_set(f.path().string());
      for (const ProblemSpec& spec : set.problems) {
        if (spec.error || !spec.info || !spec.info->drawable) continue;
        Picture p;
        try {
          p = draw_picture(spec.info->drawable(spec.given), PictureOptions{});
        } catch (const DomainError&) {
          continue;  // not drawable (said so by draw's own tests)
        }
        ++drawn;
        const std::string said = picture_words(p.svg);
        EXPECT_FALSE(std::regex_search(said, std::regex(R"([0-9]e-[0-9])")))
            << spec.id << ": " << said;
        EXPECT_FALSE(std::regex_search(said, std::regex(R"((^|[^0-9.])-0([^.0-9]|$))")))
            << spec.id << ": " << said;
      }
    }
  EXPECT_GE(drawn, 8);
}

// A caption longer than the drawing widens the canvas instead of running off its edge: in
// every language, for both kinds of picture.
TEST(Pictures, LongCaptionsWidenTheCanvas) {
  EXPECT_GT(text_width("視点から見る透視投影", 12), text_width("perspective", 12));
  EXPECT_NEAR(text_width("abc", 10), 3 * 6.2, 1e-9);
  const ProblemSet examples =
      load_problem_set(test::source_path("problems/examples/visibility.yaml"));
  const std::regex width_attr(R"re(<svg [^>]*width="([0-9.]+)")re");
  for (const char* id : {"ico-hidden-lines", "depth-sort-cyclic"})
    for (const Lang lang : {Lang::En, Lang::Ja, Lang::Ru}) {
      const ProblemSpec& spec = seed_problem(examples, id);
      PictureOptions o;
      o.lang = lang;
      const Picture plain = draw_picture(spec.info->drawable(spec.given), o);
      o.title = std::string(80, 'W') + " " + std::string(80, 'm');
      const Picture titled = draw_picture(spec.info->drawable(spec.given), o);
      std::smatch a, b;
      ASSERT_TRUE(std::regex_search(plain.svg, a, width_attr));
      ASSERT_TRUE(std::regex_search(titled.svg, b, width_attr));
      EXPECT_GE(std::stod(b[1]), 24 + text_width(o.title, 12)) << id;
      EXPECT_GT(std::stod(b[1]), std::stod(a[1])) << id;
    }
}

TEST(Pictures, CaptionsAndSummaryAreInTheReadersLanguage) {
  const ProblemSet seeds =
      load_problem_set(test::source_path("problems/seeds/003_polygons_backface.yaml"));
  const ProblemSet examples =
      load_problem_set(test::source_path("problems/examples/visibility.yaml"));
  const ProblemSpec& ico = seed_problem(seeds, "seed003-ico-hidden-lines");
  const ProblemSpec& cyclic = seed_problem(examples, "depth-sort-cyclic");
  struct Want {
    Lang lang;
    std::vector<std::string> hidden_lines, painter;
  };
  const std::vector<Want> wants = {
      {Lang::Ja,
       {"隠線消去", "視点 (3, 5, 7) から", "透視投影", "実線: 可視", "太線: 輪郭線", "破線: 不可視",
        "稜線 30 本", "(processing, 画面の y は下向き)"},
       {"画家のアルゴリズムと Zバッファ", "画家のアルゴリズム (奥行きソート)", "Zバッファ", "画素",
        "矛盾: "}},
      {Lang::Ru,
       {"удаление невидимых линий", "перспектива из глаза (3, 5, 7)", "видимое ребро", "силуэт",
        "невидимое или закрытое", "рёбер: 30", "(processing, ось y окна вниз)"},
       {"алгоритм художника и z-буфер", "алгоритм художника (сортировка по глубине)", "z-буфер",
        "пикселей", "конфликты: "}}};
  for (const Want& w : wants)
    for (const auto& [spec, words] :
         {std::pair{&ico, &w.hidden_lines}, std::pair{&cyclic, &w.painter}}) {
      PictureOptions o;
      o.lang = w.lang;
      o.api = Api::Processing;  // "(processing, window y down)" in their words
      const Picture p = draw_picture(spec->info->drawable(spec->given), o);
      const XmlCheck c = check_xml(p.svg);
      ASSERT_TRUE(c.ok) << c.problem;
      const std::string said = picture_words(p.svg) + p.summary;
      for (const std::string& word : *words)
        EXPECT_NE(said.find(word), std::string::npos) << word << " in\n" << said;
      EXPECT_EQ(latin_words(said), std::vector<std::string>{}) << said;
      EXPECT_EQ(said.find("visible"), std::string::npos) << said;
      EXPECT_EQ(said.find("hidden"), std::string::npos) << said;
    }
  // English: the caption as it always was.
  const Picture en = draw_picture(ico.info->drawable(ico.given), PictureOptions{});
  for (const char* line :
       {"<title>hidden lines</title>", ">perspective from the eye (3, 5, 7) toward ",
        ">solid: visible · bold: silhouette · dashed: hidden or covered<",
        " split where other faces cover them<"})
    EXPECT_NE(en.svg.find(line), std::string::npos) << line << " in\n" << en.svg;
  EXPECT_EQ(en.summary.rfind("30 edges: ", 0), 0u) << en.summary;
  // `frustum draw --lang ru`: the summary it prints.
  const std::string file = ::testing::TempDir() + "frustum_draw_lang_test.svg";
  std::ostringstream out, err;
  ASSERT_EQ(
      app::run_draw(test::source_path("problems/seeds/003_polygons_backface.yaml"),
                    "seed003-ico-hidden-lines", file, 24, app::Output{out, err, false}, Lang::Ru),
      0)
      << err.str();
  std::remove(file.c_str());
  EXPECT_NE(out.str().find(": рёбер: 30; видимых: "), std::string::npos) << out.str();
}

}  // namespace
}  // namespace frustum
