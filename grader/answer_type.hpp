// An answer type: everything about one AnswerKind in one file of grader/answer_types/ — how a
// student may write it (its rows of the answer-syntax table in docs/answers.md), how it is
// read, how it is compared with the key, which trivial answers it has, and how a quiz platform
// asks for it. The grader, the reports and the exports find a type through answer_type().
//
// A new answer type: a value in AnswerKind (solver/problem/kind.hpp) and a file
// grader/answer_types/<name>.cpp defining `AnswerType <name>_answer_type()` (CMake lists the
// files; a type missing from the list, or listed twice, is a logic error at the first use).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "grader/answer_parser.hpp"
#include "grader/compare.hpp"
#include "solver/core/work_budget.hpp"
#include "solver/derivation/math_text.hpp"
#include "solver/problem/registry.hpp"

namespace frustum {

// One row of the answer-syntax table: the Markdown of its cells but the answers, which are
// listed from the kinds (every answer of this type that `covers`).
struct AnswerSyntax {
  std::string type;      // "number"
  std::string forms;     // the forms accepted
  std::string examples;  // each in backticks, as YAML values (`z: 8` gives the answer's name)
  bool (*covers)(const AnswerSpec&) = nullptr;  // null: every answer of the type
};

// What a reader of the type gets besides the node: the set's angle unit and the answer's work
// budget (one for the whole answer, shared by its numbers).
struct AnswerReading {
  AngleUnit angles;
  WorkBudget& budget;
};

// How a quiz that grades by itself (Moodle, Canvas QTI, paper) asks for one answer, from the
// key: fields the export builds, or why no field can (the answer is then left out).
struct QuizAsk {
  enum class Field { Numbers, Choice, Text, Statements };
  Field field = Field::Numbers;
  Value numbers;                   // Numbers: the values asked for (the key, or rescaled)
  std::vector<std::string> words;  // Choice: the words offered (as in the set)
  std::string right;               // Choice: the right word; Text: the right text
  std::vector<std::string> also;   // Text: other texts as right
  std::vector<Said> notes;         // said after the prompt, each in parentheses
  Said refused;                    // why no quiz field can ask it (then nothing else is used)
};

// How a platform that sends answers back to Frustum (PrairieLearn) takes the answer.
enum class TypedInput { Text, Choice, Checkboxes };

struct AnswerType {
  AnswerKind kind{};
  std::vector<AnswerSyntax> syntax;

  // Reads the answer into p.value (and p.form where the type has several); returns why it
  // cannot be read (empty: read). Called after what every type shares: the length bound,
  // `none`, the answer's own name before `=` (unless `own_equals`).
  Said (*read)(const YAML::Node& node, const AnswerSpec& spec, AnswerReading& reading,
               ParsedAnswer& p) = nullptr;
  // Compares a read answer with the key (neither is `none`, unless `compares_none`).
  Comparison (*compare)(const Value& expected, const Value& got,
                        const AnswerRules& rules) = nullptr;
  // How a quiz asks for it, from the key (in the problem's conventions).
  QuizAsk (*quiz)(const AnswerSpec& spec, const Value& key, const Conventions& c) = nullptr;
  // Choice inputs: the words offered, and the key's word among them.
  std::vector<std::string> (*choices)(const AnswerSpec& spec) = nullptr;
  std::string (*chosen)(const Value& key) = nullptr;
  // How the read answer is shown back to the student when the value's own form would not be
  // what they wrote (a plane as its equation); null: the value as derivations show it.
  MathText (*shown)(const Value& value) = nullptr;

  TypedInput input = TypedInput::Text;
  const Phrase* typed_hint = nullptr;  // what to type in a text input ("a vector such as …")

  bool numeric = true;         // numbers (compared scaled when beyond double's range)
  bool componentwise = true;   // each component within its own window (the windows can be said)
  bool own_equals = false;     // written as an equation: a leading "name =" is not dropped
  bool compares_none = false;  // `none` is one of its answers, compared by `compare`
  // Tolerance magnitudes of a square matrix by block (linear part, translation, bottom row)
  // rather than by row.
  bool block_magnitudes = false;
  // Trivial answers: the transposed key is the other vector convention (not a plain transpose),
  // and a point copied from the given counts in homogeneous form too (w = 1 appended).
  bool transposed_is_convention = false;
  bool homogeneous_copies = false;
};

// The type of an answer kind (every AnswerKind has exactly one).
const AnswerType& answer_type(AnswerKind kind);
// Every answer type, in AnswerKind's order.
const std::vector<AnswerType>& answer_types();

// The answer-syntax table of docs/answers.md (Markdown): one row per AnswerSyntax, the answers
// each covers listed from the registry's kinds.
std::string answer_syntax_markdown(const Registry& registry);

}  // namespace frustum
