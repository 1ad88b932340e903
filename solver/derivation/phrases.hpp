// The translation catalogue, as data: each phrase in English, Japanese and Russian. In the
// English, {0}, {1} … stand for a value or name that the translations place where their
// grammar wants it. Japanese follows the vocabulary of the course's Japanese lectures
// (視体積, 正規化視体積, 後方クリッピング面, 画角, 稜線, 輪郭線); Russian that of its Russian
// lecture (однородные координаты, матрица проекции, матрица вида, порт просмотра).
#pragma once

#include <span>
#include <string_view>

#include "solver/util/said.hpp"

namespace frustum {

std::span<const Phrase> step_phrases();     // step titles and words in formulas
std::span<const Phrase> note_phrases();     // the notes under steps, conventions, warnings
std::span<const Phrase> grading_phrases();  // the grader's interface, verdicts and feedback

// A word counted by a number in a formula ("3 front" → "3 лицевые"): its English singular (for
// 1), and the three forms Russian agreement takes: one (1, 21, 31 …), few (2–4, 22–24 …) and
// many (0, 5–20, 25–30 …).
struct CountForms {
  std::string_view en, en_one, one, few, many;
};
std::span<const CountForms> count_forms();

}  // namespace frustum
