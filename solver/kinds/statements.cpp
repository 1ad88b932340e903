// "Which of these statements are true?" (seed 003's back-face culling quiz). The statements are
// matters of concept: the instructor gives each one's truth and reason, and the derivation lists
// them, each with ○ or × as the lecture marks them. Nothing is computed and nothing varies.
#include "solver/kinds/statements.hpp"

#include <array>
#include <utility>

#include "solver/derivation/local_text.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/input/text_reader.hpp"
#include "solver/problem/registry.hpp"
#include "solver/util/words.hpp"

namespace frustum {

std::optional<bool> truth_word(std::string_view written) {
  static constexpr std::array<std::pair<std::string_view, bool>, 32> kWords = {{
      {"true", true},      {"false", false},       {"yes", true},     {"no", false},
      {"t", true},         {"f", false},           {"y", true},       {"n", false},
      {"○", true},         {"〇", true},           {"◯", true},       {"×", false},
      {"✕", false},        {"x", false},           {"正しい", true},  {"誤り", false},
      {"正", true},        {"誤", false},          {"真", true},      {"偽", false},
      {"はい", true},      {"いいえ", false},      {"верно", true},   {"неверно", false},
      {"правильно", true}, {"неправильно", false}, {"истина", true},  {"ложь", false},
      {"да", true},        {"нет", false},         {"истинно", true}, {"ложно", false},
  }};
  const std::string w = trim_lower(std::string(written));
  for (const auto& [word, truth] : kWords)
    if (w == word) return truth;
  return std::nullopt;
}

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kTrueStatements{"true_statements", "正しい記述", "верные утверждения"};

constexpr Phrase kStatement{"Statement {0}: {1}", "記述 {0}: {1}", "Утверждение {0}: {1}"};
constexpr Phrase kTheTrueStatements{"The true statements", "正しい記述", "Верные утверждения"};
constexpr Phrase kReason{"Reason: {0}", "理由: {0}", "Обоснование: {0}"};
constexpr Phrase kTrue{"True", "正しい", "верно"};
constexpr Phrase kFalse{"False", "誤り", "неверно"};

// Line breaks and runs of spaces in a YAML block scalar, as one line.
std::string one_line(const std::string& s) {
  std::string out;
  for (const char c : s) {
    const bool space = c == ' ' || c == '\n' || c == '\r' || c == '\t';
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

struct Statements {
  static constexpr const char* kName = "statements";
  static constexpr Phrase kSummary{"which of the given statements are true",
                                   "与えられた記述のうちどれが正しいか",
                                   "какие из данных утверждений верны"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  static constexpr bool kFixed = true;
  struct Statement {
    LocalText text;  // in every language the set gives (text_reader.hpp)
    bool truth = false;
    LocalText reason;  // may be empty
  };
  struct Given {
    std::vector<Statement> statements;
  };
  static std::vector<std::string> given_fields() { return {"statements"}; }
  static std::vector<AnswerSpec> answers() {
    return {
        {.name = "true_statements", .kind = AnswerKind::Statements, .label = say(kTrueStatements)}};
  }

  // A text field of one statement, in each language the set gives: one line, bounded.
  static LocalText text(GivenReader& item, const char* key, bool required) {
    const YAML::Node n = item.node()[key];
    if (!n.IsDefined() || n.IsNull()) {
      if (required) item.fail(key, "missing required field");
      return LocalText{item.text_lang(), "", {}};
    }
    LocalText t;
    try {
      t = read_local_text(n, item.file(), "", item.text_lang(), kMaxStatementBytes);
    } catch (const InputError& e) {
      // Where read_local_text found it, named by this statement's path (".ja" of a mapping).
      Diagnostic d = e.diagnostic();
      d.field = item.locate(key + d.field, "").field;
      throw InputError(d);
    }
    t = t.map(one_line);
    for (const auto& [lang, s] : t.all())
      if (s.empty() && required)
        item.fail(n.IsMap() ? std::string(key) + "." + std::string(to_string(lang)) : key,
                  "is empty");
    return t;
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    const std::size_t n = r.list_size("statements", 1, kMaxStatements);
    for (std::size_t i = 0; i < n; ++i) {
      if (!r.node()["statements"][i].IsMap())
        r.fail("statements",
               "statement " + std::to_string(i + 1) +
                   " is not a mapping: write {text: ..., truth: true or false, reason: ...}");
      GivenReader item = r.item("statements", i, {"text", "truth", "reason"});
      Statement s;
      s.text = text(item, "text", true);
      const YAML::Node t = item.node()["truth"];
      if (!t.IsDefined() || t.IsNull())
        item.fail("truth", "missing: every statement needs its truth (true or false) for the key");
      const std::optional<bool> truth = t.IsScalar() ? truth_word(t.Scalar()) : std::nullopt;
      if (!truth) item.fail("truth", "expected true or false (also yes/no, ○/×)");
      s.truth = *truth;
      s.reason = text(item, "reason", false);
      item.finish();
      g.statements.push_back(std::move(s));
    }
    return g;
  }

  static MathText mark(bool truth) {
    return truth ? tex("\\bigcirc\\;") + word(kTrue) : tex("\\mathord{\\times}\\;") + word(kFalse);
  }

  static Answers solve(const Given& g, Derivation* steps) {
    std::vector<std::pair<std::string, std::string>> entries;
    MathText key, chosen;
    for (std::size_t i = 0; i < g.statements.size(); ++i) {
      const Statement& s = g.statements[i];
      const std::string number = std::to_string(i + 1);
      entries.emplace_back(number, s.truth ? "true" : "false");
      const MathText sep = key.empty() ? MathText{} : tex(",\\;");
      key += sep + tex(number + (s.truth ? "\\,\\bigcirc" : "\\,\\mathord{\\times}"));
      if (s.truth) chosen += (chosen.empty() ? MathText{} : tex(",\\;")) + math(number);
      if (steps) {
        // The statement and its reason quoted in each language the set gives them in.
        Step& step = steps->add(say(kStatement, number, said(s.text)), {}, {}, mark(s.truth));
        if (!s.reason.empty()) step.note = say(kReason, said(s.reason));
      }
    }
    Value v = Value::word_map(std::move(entries));
    v.display = key;
    if (steps)
      steps->add(say(kTheTrueStatements), {}, {}, chosen.empty() ? word(words::kNone) : chosen)
          .yields("true_statements");
    Answers out;
    out.set("true_statements", std::move(v));
    return out;
  }
};

}  // namespace

KindInfo statements_kind() {
  KindInfo k = make_kind<Statements>();
  k.order = 200;
  k.doc_given =
      "`statements`: a list of {`text`, `truth` (true/false, ○/×, yes/no, 正しい/誤り, "
      "верно/неверно), optional `reason`} — the instructor's key";
  k.doc_answers = "`true_statements`";
  return k;
}

}  // namespace frustum
