// A problem set as quiz questions for platforms that grade by themselves (Canvas QTI, Moodle
// XML, paper): each asked answer becomes fields a quiz engine can check — numbers with the
// window `frustum grade` accepts, a choice among words, or an exact text — or is left out
// with the reason when no field type can express its equivalence (a plane up to scale, a
// polygon up to rotation, sets and orders of labels).
#pragma once

#include <string>
#include <vector>

#include "solver/problem/kind.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/util/said.hpp"

namespace frustum {

// Words the quiz exports say in more than one file (quiz_items.cpp and the exports).
namespace quiz_phrases {

inline constexpr Phrase kNoStatementIsTrue{"None of the statements above is true",
                                           "上の記述はどれも正しくない",
                                           "Ни одно из утверждений выше не верно"};

}  // namespace quiz_phrases

// How a key writes +∞ (a z-buffer's background depth) in a number field, which cannot hold ∞.
constexpr double kQuizInfinity = 1e30;

struct QuizField {
  // Checkboxes: several choices may be right (which statements are true), each ticked one
  // scored as the platform scores multiple answers.
  enum class Type { Number, Choice, Text, Checkboxes };
  Type type = Type::Number;
  std::string label;                 // "x", "row 2, column 3"; empty for a single field
  double value = 0;                  // Number
  double window = 0;                 // Number: accepted half-width
  std::vector<std::string> choices;  // Choice
  std::string correct;               // Choice and Text: the right word or text; Checkboxes: the
                                     // right choices' numbers ("1, 3"), as a student writes them
  std::vector<std::string> also;     // Text, Choice: other spellings `frustum grade` accepts as
                                     // right (a word as written in the set, beside its
                                     // translation)
  std::vector<bool> right;           // Checkboxes: which choices are right
  std::vector<std::string> reasons;  // Checkboxes: why each choice is right or wrong ("" if none)
};

struct QuizAnswer {
  std::string name;    // the kind's answer name ("normal")
  std::string prompt;  // what to enter ("normal (scaled to length 1)")
  double points = 1;
  std::vector<QuizField> fields;
};

struct QuizQuestion {
  std::string id;  // the problem's id
  std::string kind;
  std::string text;                // the problem's text, or the kind's summary
  std::vector<std::string> given;  // "triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]]", one per field
  std::vector<QuizAnswer> answers;
  std::vector<std::string> left_out;  // "plane: an equation is right up to any factor"
};

// One drawn variant of a set as questions ("seed7-0", or the student id; "" for the set itself).
struct QuizVariant {
  std::string name;
  std::vector<QuizQuestion> questions;
};

// The fields a quiz asks for the question, over all its answers.
std::size_t field_count(const QuizQuestion& q);
// The question as HTML, as every quiz platform shows it: its text and its givens (a list of
// code lines); and the note naming the answers not asked here, with why ("" when none is left
// out), in the students' language.
std::string question_html(const QuizQuestion& q);
std::string left_out_html(const QuizQuestion& q, Lang lang);

// What a student reads: the problem's text in `lang` with its {field}s filled (the kind's
// summary, translated, when it has none). A drawn variant whose text names no field adds that the
// values are those given below, since such a text may quote the template's numbers.
std::string question_text(const ProblemSet& set, const ProblemSpec& problem, Lang lang = Lang::En);
// The given fields as "name: value" lines (YAML flow values); none for a problem whose given
// is its key (the truths of `statements`), which students must not see.
std::vector<std::string> given_lines(const ProblemSpec& problem);

// The statements of a `statements` problem as students read them (never their truths), in
// `lang` where the set gives it; empty for any other problem.
std::vector<std::string> statement_texts(const ProblemSpec& problem, Lang lang = Lang::En);

// One checkbox per statement of a `statements` problem: its text, its truth in `key` (the
// answer true_statements), and its reason.
QuizField statement_checkboxes(const ProblemSpec& problem, const Value& key, Lang lang = Lang::En);

// The questions of a set (a generated variant, or a set with fixed givens), solved exactly.
// Problems that do not solve are left out (quiz_questions never throws for them). Texts are
// in `lang` where the set gives it (its own language otherwise).
std::vector<QuizQuestion> quiz_questions(const ProblemSet& set, Lang lang = Lang::En);

}  // namespace frustum
