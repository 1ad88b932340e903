// Rendering a grade report: text for a person (the derivation once per problem, each wrong
// answer pointing at its step) and the JSON of problem-format.md §3.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "grader/grade.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/util/said.hpp"

namespace frustum {

// The words of the grade reports (text, Markdown, HTML): said by report.cpp and feedback.cpp.
namespace report_phrases {

inline constexpr Phrase kStudent{"Student", "学生", "Студент"};
inline constexpr Phrase kUnnamed{"(unnamed)", "(名前なし)", "(без имени)"};
inline constexpr Phrase kWarning{"warning", "警告", "предупреждение"};
inline constexpr Phrase kError{"error", "エラー", "ошибка"};
inline constexpr Phrase kCommonMistake{"Common mistake", "よくある誤り", "Типичная ошибка"};
inline constexpr Phrase kHowToGetIt{"How to get it", "求め方", "Как получить"};

inline constexpr Phrase kCorrect{"correct", "正解", "верно"};
inline constexpr Phrase kIncorrect{"incorrect", "不正解", "неверно"};
inline constexpr Phrase kPartial{"partial", "部分点", "частично"};
inline constexpr Phrase kUnparseable{"unparseable", "解釈できない", "не распознано"};
inline constexpr Phrase kMissing{"missing", "未解答", "нет ответа"};

}  // namespace report_phrases

// A verdict as a student reads it ("correct", 正解, верно); to_string(v) is its key.
inline const Phrase& verdict_phrase(Verdict v) {
  switch (v) {
    case Verdict::Correct:
      return report_phrases::kCorrect;
    case Verdict::Incorrect:
      return report_phrases::kIncorrect;
    case Verdict::Partial:
      return report_phrases::kPartial;
    case Verdict::Unparseable:
      return report_phrases::kUnparseable;
    case Verdict::Missing:
      return report_phrases::kMissing;
  }
  return report_phrases::kIncorrect;
}

// A score as a teacher writes it: at most two decimals, trailing zeros dropped (21.33, 2, 0.5).
std::string score_text(double v);
// An answer's common mistake as feedback states it, in `lang`: the misconception, then where
// the derivation goes wrong when that is known ("… (Where it goes wrong: …)").
std::string misconception_text(const AnswerGrade& a, Lang lang);
std::string render_grade_text(const GradeReport& r, const TextStyle& style);
nlohmann::ordered_json render_grade_json(const GradeReport& r);

}  // namespace frustum
