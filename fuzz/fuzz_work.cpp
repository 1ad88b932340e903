// libFuzzer target: the total work of a command stays within its stated bound for any input
// the limits accept, measured as work done (pixels filled, pairs tested, fields kept), not as
// time, so that a slow machine never makes it fail. The first byte chooses the input:
//   's' (or any other) a `frustum render` scene file: read, priced (price_frame), drawn by the
//       z-buffer on one thread and on two and by the scan line. The three refuse the same
//       scenes, naming the bound; a frame they draw filled at most its price, and the price is
//       at most the bound. The one-thread and two-thread frames are the same.
//   'c' a CSV roster: every row at most kMaxCsvColumns fields, every field at most
//       kMaxCsvCellBytes, at most kMaxCsvRows rows and kMaxCsvCells fields in all; each answers
//       file it becomes at most kMaxSubmissionBytes of answers and names (8 times that as YAML).
//   'd' a problem set: each drawable problem drawn as `frustum draw` does; a hidden-line
//       picture drawn tested at most its bound of edge–face pairs.
// The bounds are lowered here (kFuzz*) so that an input stays fast under the sanitizers; the
// mechanism that enforces them is the one the real limits go through.
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "batch/batch.hpp"
#include "batch/csv.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/raster/fill.hpp"
#include "solver/raster/frame_work.hpp"
#include "solver/raster/scanline.hpp"
#include "solver/raster_fast/threaded_zbuffer.hpp"
#include "solver/shared/scene_reader.hpp"
#include "solver/visibility/edge_classes.hpp"
#include "solver/visibility/pictures.hpp"

namespace {

constexpr std::int64_t kFuzzFrameWork = std::int64_t{1} << 20;
constexpr int kFuzzSide = 256;
constexpr long kFuzzTriangles = 20'000;
constexpr std::int64_t kFuzzHiddenLinePairs = 20'000;

bool names_frame_bound(const frustum::DomainError& e) {
  return std::string(e.what()).find("(the limit is " + std::to_string(kFuzzFrameWork) +
                                    " pixel tests a frame") != std::string::npos;
}

// Renders with `run`; true when drawn, false when refused for its work (any other refusal, a
// coordinate the rasterizer cannot take, is `other`).
template <typename Run>
bool drawn(Run run, bool& other) {
  try {
    run();
    return true;
  } catch (const frustum::DomainError& e) {
    if (!names_frame_bound(e)) other = true;
    return false;
  }
}

void scene(const std::string& text) {
  const frustum::YamlDocument doc = frustum::parse_yaml(text, "scene.yaml");
  if (doc.error || !doc.root.IsMap()) return;
  frustum::Scene s;
  try {
    frustum::GivenReader root(doc.root, "scene.yaml", "", {"title", "conventions", "scene"});
    const frustum::Conventions c =
        frustum::read_conventions(doc.root["conventions"], "scene.yaml", "conventions", {});
    frustum::GivenReader r = root.child("scene", frustum::scene_fields());
    const frustum::SceneSpec spec = frustum::read_scene(r, c);
    if (spec.triangles > kFuzzTriangles) return;
    s = spec.scene;
  } catch (const frustum::InputError&) {
    return;
  } catch (const frustum::DomainError&) {
    return;
  }
  s.width = std::min(s.width, kFuzzSide);
  s.height = std::min(s.height, kFuzzSide);
  s.max_work = kFuzzFrameWork;
  std::int64_t price = -1;
  try {
    price = frustum::price_frame(s);
    if (price < 0 || price > kFuzzFrameWork) std::abort();
  } catch (const frustum::DomainError& e) {
    if (!names_frame_bound(e)) std::abort();
  }
  bool other = false;
  frustum::Frame one, two;
  frustum::FillStats fill;
  const bool z1 = drawn([&] { frustum::render_zbuffer(s, one, nullptr, &fill, 1); }, other);
  const bool z2 = drawn([&] { frustum::render_zbuffer(s, two, nullptr, nullptr, 2); }, other);
  frustum::ScanlineStats st;
  const bool sl = drawn(
      [&] {
        const std::vector<frustum::WindowTriangle> tris =
            frustum::geometry(s, frustum::flatten(s, false));
        (void)frustum::render_scanline(tris, s.width, s.height, s.background, &st, nullptr,
                                       s.max_work);
      },
      other);
  if (other) return;  // refused for a coordinate, not for its work
  // The same scenes refused everywhere, and a drawn frame within its price.
  if (z1 != (price >= 0) || z2 != z1 || sl != z1) std::abort();
  if (z1 && (fill.fragments > price || one.color.data != two.color.data)) std::abort();
}

void roster(const std::string& text) {
  const frustum::CsvTable table = frustum::parse_csv(text);
  if (table.error) {
    if (table.error_line < 1 || table.error_column < 1) std::abort();
  } else {
    std::size_t cells = 0;
    if (table.rows.size() > frustum::kMaxCsvRows) std::abort();
    for (const frustum::CsvRow& row : table.rows) {
      if (row.fields.size() > frustum::kMaxCsvColumns) std::abort();
      cells += row.fields.size();
      for (const std::string& f : row.fields)
        if (f.size() > frustum::kMaxCsvCellBytes) std::abort();
    }
    if (cells > frustum::kMaxCsvCells) std::abort();
  }
  const std::string path = "/tmp/frustum-fuzz-work-" + std::to_string(getpid()) + ".csv";
  std::ofstream(path, std::ios::binary) << text;
  try {
    // A row's file is at most kMaxSubmissionBytes of answers with their names; YAML's quoting
    // and escapes (\xNN for a byte) at most quadruple them, and indentation adds a little.
    for (const frustum::BatchEntry& e : frustum::collect_submissions(path))
      if (e.yaml.size() > 8 * frustum::kMaxSubmissionBytes) std::abort();
  } catch (const frustum::InputError& e) {
    if (e.diagnostic().where.file != path) std::abort();
  }
  unlink(path.c_str());
}

void draw(const std::string& text) {
  const frustum::ProblemSet set = frustum::load_problem_set_from_string(text, "set.yaml");
  for (const frustum::ProblemSpec& p : set.problems) {
    if (p.error || !p.info || !p.info->drawable) continue;
    if (frustum::solve_problem(p, set.file, false).error) continue;
    try {
      const frustum::Drawable d = p.info->drawable(p.given);
      frustum::PictureOptions o;
      o.api = p.conventions.api;
      o.max_hidden_line_pairs = kFuzzHiddenLinePairs;
      (void)frustum::draw_picture(d, o);
      if (d.picture != frustum::Drawable::Picture::HiddenLines || !d.viewer.eye) continue;
      // The pairs hidden_lines tested: every edge that is not back–back, every face triangle.
      const std::vector<frustum::MeshEdge> edges = frustum::mesh_edges(d.mesh);
      const std::vector<frustum::EdgeClass> classes = frustum::classify_edges(
          edges, frustum::face_tests(d.mesh, frustum::face_normals(d.mesh), *d.viewer.eye));
      const auto tested = static_cast<std::int64_t>(
          std::count_if(classes.begin(), classes.end(),
                        [](frustum::EdgeClass c) { return c != frustum::EdgeClass::Hidden; }));
      const auto triangles = static_cast<std::int64_t>(frustum::face_triangles(d.mesh).size());
      if (tested * triangles > kFuzzHiddenLinePairs) std::abort();
    } catch (const frustum::DomainError&) {
    } catch (const frustum::InputError&) {
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  switch (data[0]) {
    case 'c':
      roster(text);
      break;
    case 'd':
      draw(text);
      break;
    default:
      scene(text);
  }
  return 0;
}
