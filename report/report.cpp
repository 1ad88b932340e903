#include "report/report.hpp"

#include <fmt/format.h>

#include <cmath>

#include "grader/visible_text.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

using json = nlohmann::ordered_json;
using namespace report_phrases;

namespace {

constexpr Phrase kWhereItGoesWrong{"Where it goes wrong", "誤りの生じるステップ",
                                   "Где возникает ошибка"};
constexpr Phrase kSeeStep{"See step", "参照ステップ", "См. шаг"};
// Inside a line of the text report ("— you wrote 3; expected 2"); a colon after the words where
// they are a label.
constexpr Phrase kYouWroteInline{"you wrote", "あなたの解答:", "Ваш ответ:"};
constexpr Phrase kExpectedInline{"expected", "正解:", "Верный ответ:"};

// The number a step has in the rendered derivation (notes and warnings are not numbered).
int step_number(const std::vector<Step>& steps) {
  int n = 0;
  for (const Step& s : steps) n += s.level == Step::Level::Info;
  return n;
}

std::string mark(Verdict v, bool color) {
  const char* on = "";
  const char* symbol = "?";
  switch (v) {
    case Verdict::Correct:
      on = "\033[32m";
      symbol = "✓";
      break;
    case Verdict::Partial:
      on = "\033[33m";
      symbol = "½";
      break;
    case Verdict::Incorrect:
      on = "\033[31m";
      symbol = "✗";
      break;
    case Verdict::Unparseable:
      on = "\033[35m";
      symbol = "?";
      break;
    case Verdict::Missing:
      on = "\033[2m";
      symbol = "–";
      break;
  }
  return color ? std::string(on) + symbol + "\033[0m" : symbol;
}

}  // namespace

std::string misconception_text(const AnswerGrade& a, Lang lang) {
  std::string out = a.misconception.in(lang);
  if (!a.wrong_step.empty())
    out += fmt::format(" ({}: {})", kWhereItGoesWrong.in(lang), a.wrong_step.in(lang));
  return out;
}

// A score as a teacher writes it: at most two decimals, trailing zeros dropped (21.33, 2, 0.5).
std::string score_text(double v) {
  // Whole marks (most scores) need no decimal formatting.
  if (std::abs(v) < 1e15 && v == std::trunc(v)) return std::to_string(static_cast<long long>(v));
  std::string s = fmt::format("{:.2f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string render_grade_text(const GradeReport& r, const TextStyle& style) {
  const Lang lang = style.lang;
  std::string out =
      fmt::format("{} {}: {} / {}\n", kStudent.in(lang),
                  r.student.empty() ? std::string(kUnnamed.in(lang)) : visible_text(r.student),
                  score_text(r.score), score_text(r.max_score));
  if (!r.variant.empty()) out += "  " + visible_text(r.variant) + "\n";
  for (const Diagnostic& d : r.errors)
    out += fmt::format("  {}: {}\n", kWarning.in(lang), visible_text(d.format()));
  for (const ProblemGrade& p : r.problems) {
    out += fmt::format("\n{} ({}): {} / {}\n", p.id, p.kind, score_text(p.score),
                       score_text(p.max_score));
    if (p.error) {
      out += fmt::format("  {}: {}\n", kError.in(lang), visible_text(p.error->format()));
      continue;
    }
    // The derivation is printed once per problem, after its answers: the longest of the wrong
    // answers' derivations (each is a prefix of the problem's), and every wrong answer points
    // at the step that gives it.
    const std::vector<Step>* derivation = nullptr;
    for (const AnswerGrade& a : p.answers)
      if (a.verdict != Verdict::Correct && !a.derivation.empty() &&
          (!derivation || a.derivation.size() > derivation->size()))
        derivation = &a.derivation;
    for (const AnswerGrade& a : p.answers) {
      out += fmt::format("  {} {}: {}", mark(a.verdict, style.color), a.name,
                         verdict_phrase(a.verdict).in(lang));
      if (a.verdict != Verdict::Missing)
        out += fmt::format(" — {} {}", kYouWroteInline.in(lang), visible_text(a.got_text));
      if (a.verdict != Verdict::Correct)
        out +=
            fmt::format("; {} {}", kExpectedInline.in(lang), tr(a.expected.shown(), lang).unicode);
      out += "\n";
      if (!a.misconception.empty())
        out += fmt::format("      {}: {}\n", kCommonMistake.in(lang), misconception_text(a, lang));
      if (!a.feedback.empty() && a.verdict != Verdict::Correct)
        out += "      " + visible_text(a.feedback.in(lang)) + "\n";
      if (a.verdict != Verdict::Correct && !a.derivation.empty() &&
          !a.derivation.back().answers.empty())
        out += fmt::format("      {} {}: {}\n", kSeeStep.in(lang), step_number(a.derivation),
                           a.derivation.back().title.in(lang));
    }
    if (derivation) {
      out += fmt::format("  {}:\n", kHowToGetIt.in(lang));
      out += render_steps_text(*derivation, style, "    ");
    }
  }
  return out;
}

json render_grade_json(const GradeReport& r) {
  json j;
  j["student"] = r.student;
  if (!r.variant.empty()) j["variant"] = r.variant;
  j["score"] = number_json(r.score);
  j["max_score"] = number_json(r.max_score);
  json problems = json::array();
  for (const ProblemGrade& p : r.problems) {
    json pj = {
        {"id", p.id}, {"score", number_json(p.score)}, {"max_score", number_json(p.max_score)}};
    if (p.error) pj["error"] = p.error->format();
    json answers = json::object();
    for (const AnswerGrade& a : p.answers) {
      json aj = {{"verdict", std::string(to_string(a.verdict))},
                 {"score", number_json(a.score)},
                 {"max_score", number_json(a.max_score)},
                 {"expected", value_json(a.expected)}};
      const json exact = exact_json(a.expected);
      if (!exact.is_null()) aj["expected_exact"] = exact;
      aj["got"] =
          a.got ? value_json(*a.got) : (a.got_text.empty() ? json(nullptr) : json(a.got_text));
      if (a.verdict != Verdict::Missing) aj["got_text"] = a.got_text;
      // The JSON report is for programs and keeps one language: the grader's English.
      aj["feedback"] = a.feedback.en();
      if (!a.misconception.empty()) {
        aj["misconception"] = a.misconception.en();
        aj["wrong_step"] = a.wrong_step.en();
      }
      if (a.carried_forward) aj["carried_forward"] = true;
      if (!a.derivation.empty()) aj["derivation"] = steps_json(a.derivation);
      answers[a.name] = aj;
    }
    pj["answers"] = answers;
    problems.push_back(pj);
  }
  j["problems"] = problems;
  if (!r.errors.empty()) {
    json errs = json::array();
    for (const Diagnostic& d : r.errors) errs.push_back(d.format());
    j["errors"] = errs;
  }
  return j;
}

}  // namespace frustum
