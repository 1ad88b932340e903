// The `statements` kind's vocabulary, shared with the grader: how a statement's truth may be
// written, in the set (the instructor's key) and in a student's answer alike.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace frustum {

// Statements in one problem, and the bytes of one statement or reason: far above any quiz.
inline constexpr std::size_t kMaxStatements = 50;
inline constexpr std::size_t kMaxStatementBytes = 2000;

// A truth as written: true/false, yes/no, t/f, ○/〇/×/✕, and the Japanese and Russian words
// (正しい/誤り, 正/誤, 真/偽, はい/いいえ, верно/неверно, истина/ложь, да/нет), in any case.
// Digits are not truths here: in an answer, 1 is the number of a statement.
std::optional<bool> truth_word(std::string_view written);

}  // namespace frustum
