#include "grader/samples.hpp"

#include <fmt/format.h>

#include <cmath>

namespace frustum {

namespace {

// The verdict of a sample's answers taken together.
SampleVerdict verdict_of(const std::vector<AnswerGrade>& answers, double score, double max) {
  bool all_right = true;
  for (const AnswerGrade& a : answers) {
    if (a.verdict == Verdict::Unparseable) return SampleVerdict::Unparseable;
    all_right = all_right && a.verdict == Verdict::Correct;
  }
  if (all_right || (max > 0 && score >= max)) return SampleVerdict::Right;
  return score > 0 ? SampleVerdict::Partly : SampleVerdict::Wrong;
}

// In English, as every diagnostic of `check` is (the instructor's self-test of the set).
std::string answers_said(const std::vector<AnswerGrade>& answers) {
  std::string out;
  for (const AnswerGrade& a : answers)
    out +=
        fmt::format("{}{}: {}", out.empty() ? "" : "; ", a.name, to_string(a.verdict)) +
        (a.feedback.empty() || a.verdict == Verdict::Correct ? "" : " (" + a.feedback.en() + ")");
  return out;
}

SampleOutcome judge(const ProblemSpec& spec, const Sample& sample, const ProblemGrade& graded) {
  SampleOutcome o;
  o.sample = &sample;
  o.problem = spec.id;
  double score = 0, max = 0;
  for (const AnswerGrade& a : graded.answers)
    if (sample.answers[a.name].IsDefined()) {
      o.answers.push_back(a);
      score += a.score;
      max += a.max_score;
    }
  o.verdict = verdict_of(o.answers, score, max);
  o.credit = max > 0 ? score / max : (o.verdict == SampleVerdict::Right ? 1 : 0);
  const bool verdict_ok = !sample.expect || *sample.expect == o.verdict;
  const bool credit_ok =
      !sample.credit || std::abs(*sample.credit - o.credit) <= kSampleCreditTolerance;
  o.as_expected = verdict_ok && credit_ok;
  if (!o.as_expected) {
    const std::string expected =
        sample.expect ? std::string(to_string(*sample.expect)) +
                            (sample.credit ? fmt::format(", credit {:g}", *sample.credit) : "")
                      : fmt::format("credit {:g}", *sample.credit);
    o.mismatch =
        Diagnostic{sample.where, sample.field,
                   fmt::format("expected {}, graded {} with credit {:.3g} — {}{}", expected,
                               to_string(o.verdict), o.credit, answers_said(o.answers),
                               sample.note.empty() ? "" : " (note: " + sample.note + ")")};
  }
  return o;
}

}  // namespace

std::vector<SampleOutcome> grade_samples(const ProblemSet& set, const SolvedSet* solved) {
  std::vector<SampleOutcome> out;
  for (std::size_t i = 0; i < set.problems.size(); ++i) {
    const ProblemSpec& spec = set.problems[i];
    if (spec.samples.empty() || spec.error) continue;
    // The problem alone, so that each sample grades one problem, not the whole set.
    ProblemSet one;
    one.file = set.file;
    one.lang = set.lang;
    one.problems = {spec};
    SolvedSet key;
    if (solved && i < solved->results.size()) {
      key.results = {solved->results[i]};
      key.mistakes = {solved->mistakes[i]};
      key.judging = {solved->judging[i]};
    } else {
      key = solve_for_grading(one);
    }
    if (key.results.empty() || key.results.front().error) continue;
    for (const Sample& sample : spec.samples) {
      Submission submission;
      submission.file = set.file;
      submission.answers[spec.id] = sample.answers;
      const GradeReport report = grade(one, submission, &key);
      if (report.problems.empty()) continue;
      out.push_back(judge(spec, sample, report.problems.front()));
    }
  }
  return out;
}

}  // namespace frustum
