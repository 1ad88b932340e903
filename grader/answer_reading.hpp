// What the answer types' readers share (grader/answer_types/): numbers, tuples, rows and
// words as students write them, each with the reason when it cannot be read. Defined in
// answer_parser.cpp.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "solver/core/exact.hpp"
#include "solver/core/work_budget.hpp"
#include "solver/util/said.hpp"

namespace frustum::reading {

// Untrusted text as a message quotes it ('1+1+1...'), without the quotes: a phrase places it
// in each language's own quotes.
std::string excerpt(std::string_view text);
// A word of an answer's category or truth value as the key prints it in each language.
Said word_said(const std::string& word);
// The word a student wrote, as one of `candidates` when it is one of them in English, a listed
// synonym, or the Japanese or Russian word the derivations print for it (what the key shows a
// student reading in that language is accepted back). Unchanged otherwise.
std::string known_word(const std::string& written, const std::vector<std::string>& candidates);
std::string trimmed(std::string s);

inline constexpr Phrase kExpectedOneNumber{"expected one number", "数が一つ必要です",
                                           "ожидалось одно число"};

// One number or exact expression written alone; returns why it cannot be read (empty: read into
// `value`).
Said read_number(const YAML::Node& node, WorkBudget& budget, Exact& value);

struct Numbers {
  std::vector<Exact> values;
  Said error;
};

// One number or exact expression. `infinity`: where an answer holds +∞ as a stand-in number
// (AnswerSpec::infinity), +∞ written inf, ∞ or infinity (or YAML's .inf) is that number; 0: +∞
// is no answer.
Exact parse_one(const std::string& text, Said& error, WorkBudget& budget, double infinity = 0);
// Splits "(a, b, c)" or "a, b, c" at top-level commas.
std::vector<std::string> split_list(std::string s);
// A point list written as text, in the usual forms: "(0, 4), (8, 8)", "[[0, 4], [8, 8]]",
// "(0, 4); (8, 8)". Empty when the text is not a list of bracketed tuples.
std::vector<std::string> split_rows(std::string s);
// A list of numbers: a YAML list, "(a, b, c)", or a number times a tuple ("(1/√21)(−2, 1, 4)").
Numbers read_numbers(const YAML::Node& n, WorkBudget& budget, double infinity = 0);

struct Rows {
  std::vector<std::vector<Exact>> values;
  Said error;
};
// A matrix (`vertices` false: its rows) or a vertex list: a YAML list of rows (each a list or
// "(a, b)"), or one text in a usual written form ("(0, 4), (8, 8)").
Rows read_rows(const YAML::Node& node, bool vertices, WorkBudget& budget, double infinity = 0);

// A list of words (items of a set or a sequence): a YAML list, or one text of items separated
// by commas; with `unordered_pairs`, a pair also as [i, j] or "(i, j)". Returns why it cannot be
// read (empty: read into `words`).
Said read_word_list(const YAML::Node& node, bool unordered_pairs, std::vector<std::string>& words);

}  // namespace frustum::reading
