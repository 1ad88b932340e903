// libFuzzer target: an answer file from arbitrary bytes is graded against one of the fixed
// seed problem sets (chosen by the first byte) and the report rendered as text and JSON.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "grader/grade.hpp"
#include "report/report.hpp"

namespace {

// The seed sets, each solved once (as a batch does), so every run grades only the answers.
struct SeedSet {
  frustum::ProblemSet set;
  frustum::SolvedSet solved;
};

const std::vector<SeedSet>& seed_sets() {
  static const std::vector<SeedSet> sets = [] {
    std::vector<SeedSet> out;
    for (const char* name : {"000_projection_and_hidden_surfaces", "001_zbuffer_plane_method",
                             "002_transforms_and_view_volume", "003_polygons_backface",
                             "004_placing_and_projecting"}) {
      SeedSet s;
      s.set = frustum::load_problem_set(std::string(FRUSTUM_SOURCE_DIR) + "/problems/seeds/" +
                                        name + ".yaml");
      s.solved = frustum::solve_for_grading(s.set);
      out.push_back(std::move(s));
    }
    return out;
  }();
  return sets;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // "0".."4" pick seed 000..004, so corpus files can start with a readable digit.
  const std::uint8_t pick = static_cast<std::uint8_t>(data[0] - std::uint8_t{'0'});
  const SeedSet& seed = seed_sets()[pick % seed_sets().size()];
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const frustum::Submission sub = frustum::load_submission_from_string(text, "answers.yaml");
  const frustum::GradeReport report = frustum::grade(seed.set, sub, &seed.solved);
  (void)frustum::render_grade_text(report, frustum::TextStyle{});
  (void)frustum::json_text(frustum::render_grade_json(report));
  return 0;
}
