#include "report/gradescope.hpp"

#include <fmt/format.h>

#include "report/feedback.hpp"
#include "solver/derivation/formats.hpp"

namespace frustum {

using json = nlohmann::ordered_json;

json gradescope_results(const GradeReport& r, Lang lang) {
  return gradescope_results(r, problem_feedback_markdown(r, lang));
}

json gradescope_results(const GradeReport& r, const std::vector<std::string>& problem_markdown) {
  json j;
  j["score"] = number_json(r.score);
  std::string summary = fmt::format("{} / {}", r.score, r.max_score);
  for (const Diagnostic& d : r.errors) summary += "\n\n- `" + markdown_code(d.format()) + "`";
  j["output"] = summary;
  j["output_format"] = "md";
  j["visibility"] = "visible";
  j["stdout_visibility"] = "hidden";
  json tests = json::array();
  for (std::size_t i = 0; i < r.problems.size(); ++i) {
    const ProblemGrade& p = r.problems[i];
    json t;
    t["name"] = p.id;
    t["score"] = number_json(p.score);
    t["max_score"] = number_json(p.max_score);
    t["status"] = !p.error && p.score >= p.max_score ? "passed" : "failed";
    t["output"] = problem_markdown.at(i);
    t["output_format"] = "md";
    t["visibility"] = "visible";
    tests.push_back(t);
  }
  j["tests"] = tests;
  return j;
}

json gradescope_failure(const std::string& reason) {
  return json{{"score", 0},
              {"output", "The submission could not be graded: " + markdown_escape(reason)},
              {"output_format", "md"},
              {"visibility", "visible"},
              {"tests", json::array()}};
}

}  // namespace frustum
