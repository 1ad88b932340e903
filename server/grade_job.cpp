#include "server/grade_job.hpp"

#include <nlohmann/json.hpp>

#include "report/report.hpp"
#include "server/answer_text.hpp"
#include "solver/derivation/formats.hpp"

namespace frustum::server {

namespace {

using Json = nlohmann::ordered_json;

GradeRecord failed(const SubmissionRecord& s, const std::string& worker, Millis now,
                   const std::string& why) {
  GradeRecord g;
  g.submission = s.id;
  g.result = json_text(Json{{"error", why}}, -1);
  g.set_version = s.set_version;
  g.graded_by = worker;
  g.graded = now;
  g.failed = true;
  return g;
}

// The student's own texts of the answers that carried credit used (the kind's dependencies).
Json carried_from(const ProblemSpec& spec, const AnswerGrade& a, const Json& written) {
  Json out = Json::array();
  const AnswerSpec* answer = spec.info->answer(a.name);
  if (!answer || !a.carried_forward) return out;
  for (const std::string& d : answer->depends_on)
    if (written.contains(d)) out.push_back(Json{{"name", d}, {"text", written[d]}});
  return out;
}

Json answer_json(const ProblemSpec& spec, const AnswerGrade& a, const Json& written, Lang lang) {
  const MathText key = tr(a.expected.shown(), lang);
  return Json{{"name", a.name},
              {"verdict", std::string(to_string(a.verdict))},
              {"score", a.score},
              {"max_score", a.max_score},
              {"got_text", a.got_text},
              {"got_tex", a.got ? a.got->shown().latex : ""},
              {"key_text", key.unicode},
              {"key_tex", key.latex},
              {"feedback", a.feedback.in(lang)},
              {"mistake", a.misconception.in(lang)},
              {"wrong_step", a.wrong_step.in(lang)},
              {"carried_forward", a.carried_forward},
              {"carried_from", carried_from(spec, a, written)},
              {"derivation_html", a.derivation.empty() ? "" : html_steps(a.derivation, lang)}};
}

}  // namespace

std::shared_ptr<const SolvedSet> SolvedCache::get(const std::string& version,
                                                  const std::string& variant,
                                                  const ProblemSet& set) {
  const std::string key = version + "\x1f" + variant;
  if (const auto it = cache_.find(key); it != cache_.end()) return it->second;
  if (cache_.size() >= capacity_) cache_.erase(cache_.begin());
  ++solves_;
  auto solved = std::make_shared<const SolvedSet>(solve_for_grading(set));
  cache_.emplace(key, solved);
  return solved;
}

GradeRecord grade_submission(const Course& course, SolvedCache& cache, const SubmissionRecord& s,
                             const std::string& worker, Millis now) {
  const CourseSet* cs = course.find(s.set);
  const ProblemSet* variant = cs ? cs->for_student(s.student) : nullptr;
  const ProblemSpec* spec = variant ? variant->find(s.problem) : nullptr;
  if (!spec) return failed(s, worker, now, "the set, the student or the problem is not served");
  const Json written = Json::parse(s.answers, nullptr, false);
  if (!written.is_object()) return failed(s, worker, now, "the stored answers are not JSON");
  std::map<std::string, std::string> texts;
  for (const auto& [name, text] : written.items())
    if (text.is_string()) texts.emplace(name, text.get<std::string>());
  const Submission submission =
      load_submission_from_string(answers_yaml(s.student, s.problem, texts), "submission");
  const GradeReport report =
      grade(*variant, submission, cache.get(cs->version, s.variant, *variant).get());
  for (const ProblemGrade& p : report.problems) {
    if (p.id != s.problem) continue;
    if (p.error) return failed(s, worker, now, p.error->format());
    Json answers = Json::array();
    for (const AnswerGrade& a : p.answers)
      answers.push_back(answer_json(*spec, a, written, variant->lang));
    GradeRecord g;
    g.submission = s.id;
    g.result =
        json_text(Json{{"score", p.score}, {"max_score", p.max_score}, {"answers", answers}}, -1);
    g.score = p.score;
    g.max_score = p.max_score;
    g.set_version = cs->version;
    g.graded_by = worker;
    g.graded = now;
    return g;
  }
  return failed(s, worker, now, "the problem was not graded");
}

}  // namespace frustum::server
