#include "grader/statement_choice.hpp"

#include <fmt/format.h>

#include <string_view>
#include <vector>

#include "solver/kinds/statements.hpp"
#include "solver/util/expression.hpp"
#include "solver/util/words.hpp"

namespace frustum {

namespace {

// Statement numbers longer than this are out of range whatever the problem.
constexpr std::size_t kMaxNumberDigits = 4;

// The UTF-8 characters of s.
std::vector<std::string> characters(std::string_view s) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < s.size();) {
    std::size_t n = 1;
    while (i + n < s.size() && (static_cast<unsigned char>(s[i + n]) & 0xC0) == 0x80) ++n;
    out.emplace_back(s.substr(i, n));
    i += n;
  }
  return out;
}

// Full-width digits (１２) as ASCII; empty when the token is not all digits. Leading zeros go.
std::string digits_of(std::string_view token) {
  std::string out;
  for (const std::string& c : characters(token)) {
    if (c.size() == 1 && c[0] >= '0' && c[0] <= '9')
      out += c;
    else if (c.size() == 3 && c.compare(0, 2, "\xEF\xBC") == 0 &&
             static_cast<unsigned char>(c[2]) >= 0x90 && static_cast<unsigned char>(c[2]) <= 0x99)
      out += static_cast<char>('0' + (static_cast<unsigned char>(c[2]) - 0x90));
    else
      return {};
  }
  const std::size_t nonzero = out.find_first_not_of('0');
  return nonzero == std::string::npos ? (out.empty() ? "" : "0") : out.substr(nonzero);
}

// "1, 3", "[1, 3]", "1 3", "1、3", "true, false": the tokens between separators; a run of marks
// written together ("○×××") is one truth per mark.
std::vector<std::string> tokens_of(std::string_view text) {
  std::vector<std::string> out;
  std::string cur;
  const auto flush = [&] {
    if (!cur.empty()) out.push_back(cur);
    cur.clear();
  };
  for (const std::string& c : characters(text)) {
    if (c == "," || c == ";" || c == " " || c == "\t" || c == "\n" || c == "、" || c == "，" ||
        c == "[" || c == "]" || c == "(" || c == ")" || c == "　")
      flush();
    else
      cur += c;
  }
  flush();
  if (out.size() == 1 && !truth_word(out[0])) {
    const std::vector<std::string> marks = characters(out[0]);
    bool all_marks = marks.size() > 1;
    for (const std::string& m : marks) all_marks = all_marks && truth_word(m) && m.size() > 1;
    if (all_marks) return marks;
  }
  return out;
}

StatementChoice failed(std::string why) { return {Value::null(), std::move(why)}; }

// A list of tokens as numbers or as truths, never both.
StatementChoice from_tokens(const std::vector<std::string>& tokens) {
  std::vector<std::string> numbers;
  std::vector<std::pair<std::string, std::string>> truths;
  for (const std::string& t : tokens) {
    if (const std::string d = digits_of(t); !d.empty()) {
      if (d == "0") return failed("there is no statement 0: the statements are numbered from 1");
      numbers.push_back(d);
    } else if (const std::optional<bool> b = truth_word(t)) {
      truths.emplace_back(std::to_string(truths.size() + 1), *b ? "true" : "false");
    } else {
      return failed(quote_excerpt(t) + " is neither the number of a statement nor true or false");
    }
  }
  if (!numbers.empty() && !truths.empty())
    return failed(
        "the answer mixes statement numbers and true/false: write the numbers of the true "
        "statements, like [1, 3], or one true/false per statement, like [true, false, true]");
  if (!truths.empty()) return {Value::word_map(std::move(truths)), ""};
  return {Value::word_list(std::move(numbers)), ""};
}

Comparison judged(Verdict v, double credit, std::string why) {
  return {v, credit, std::move(why), {}, false, {}};
}

// The index of statement `number` (as read) among n, or nothing when there is no such statement.
std::optional<std::size_t> index_of(const std::string& number, std::size_t n) {
  if (number.empty() || number.size() > kMaxNumberDigits) return std::nullopt;
  const std::size_t k = std::stoul(number);
  if (k < 1 || k > n) return std::nullopt;
  return k - 1;
}

std::string no_such(const std::string& number, std::size_t n) {
  const std::string shown = number.size() > 8 ? number.substr(0, 8) + "…" : number;
  return fmt::format("there is no statement {}: the statements are numbered 1 to {}", shown, n);
}

}  // namespace

StatementChoice read_statement_choice(const YAML::Node& node) {
  if (node.IsSequence()) {
    std::vector<std::string> tokens;
    for (std::size_t i = 0; i < node.size(); ++i) {
      if (!node[i].IsScalar())
        return failed(fmt::format("item {} is not a statement number or true/false", i + 1));
      tokens.push_back(trim_lower(node[i].Scalar()));
      if (tokens.back().empty()) return failed(fmt::format("item {} is empty", i + 1));
    }
    return from_tokens(tokens);
  }
  if (node.IsMap()) {
    std::vector<std::pair<std::string, std::string>> entries;
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string key = it->first.IsScalar() ? digits_of(trim_lower(it->first.Scalar())) : "";
      if (key.empty() || key == "0")
        return failed("a mapping's keys are statement numbers 1, 2, …, like {1: true, 2: false}");
      const std::optional<bool> b =
          it->second.IsScalar() ? truth_word(it->second.Scalar()) : std::nullopt;
      if (!b)
        return failed(fmt::format("statement {}: expected true or false",
                                  key.size() > 8 ? key.substr(0, 8) + "…" : key));
      entries.emplace_back(key, *b ? "true" : "false");
    }
    return {Value::word_map(std::move(entries)), ""};
  }
  if (!node.IsScalar()) return failed("expected the numbers of the true statements");
  const std::string text = trim_lower(node.Scalar());
  // "none" and なし are read before any answer type; these say it in words of their own.
  for (const char* none : {"ни одного", "нет верных", "ない", "正しいものはない"})
    if (text == none) return {Value::null(), ""};
  const std::vector<std::string> tokens = tokens_of(text);
  if (tokens.empty())
    return failed("empty answer: write the numbers of the true statements, or none");
  return from_tokens(tokens);
}

Comparison compare_statement_choice(const Value& expected, const Value& got) {
  const std::size_t n = expected.entries.size();
  std::vector<bool> truth(n), chosen(n, false);
  std::size_t trues = 0;
  for (std::size_t i = 0; i < n; ++i) trues += (truth[i] = expected.entries[i].second == "true");
  if (got.shape == Value::Shape::WordList) {
    for (const std::string& w : got.words) {
      const std::optional<std::size_t> i = index_of(w, n);
      if (!i) return judged(Verdict::Unparseable, 0, no_such(w, n));
      chosen[*i] = true;
    }
  } else if (got.shape == Value::Shape::WordMap) {
    std::vector<bool> seen(n, false);
    for (const auto& [k, w] : got.entries) {
      const std::optional<std::size_t> i = index_of(k, n);
      if (!i) return judged(Verdict::Unparseable, 0, no_such(k, n));
      if (seen[*i])
        return judged(Verdict::Unparseable, 0, fmt::format("statement {} is given twice", k));
      seen[*i] = true;
      chosen[*i] = w == "true";
    }
    if (got.entries.size() != n)
      return judged(Verdict::Unparseable, 0,
                    fmt::format("{} statements, but {} true/false values: give one per statement, "
                                "or the numbers of the true ones",
                                n, got.entries.size()));
  } else if (got.shape != Value::Shape::Null) {
    return judged(Verdict::Unparseable, 0, "expected the numbers of the true statements");
  }
  const std::size_t falses = n - trues;
  std::size_t right_chosen = 0, wrong_chosen = 0;
  std::string why;
  for (std::size_t i = 0; i < n; ++i) {
    right_chosen += chosen[i] && truth[i];
    wrong_chosen += chosen[i] && !truth[i];
    if (chosen[i] != truth[i])
      // The kind derives statement k in step k (it states no conventions before them).
      why += fmt::format("{}Statement {} is {}, not {} (see step {}).", why.empty() ? "" : " ",
                         i + 1, truth[i] ? "true" : "false", truth[i] ? "false" : "true", i + 1);
  }
  if (why.empty()) return judged(Verdict::Correct, 1, "");
  // Each true statement chosen earns 1/T, each false one chosen costs 1/F.
  const double earned =
      trues ? static_cast<double>(right_chosen) / static_cast<double>(trues) : 1.0;
  const double lost =
      falses ? static_cast<double>(wrong_chosen) / static_cast<double>(falses) : 0.0;
  const double credit = std::max(0.0, earned - lost);
  if (trues && falses)
    why += fmt::format(
        " You chose {} of the {} true statements and {} of the {} false ones. Each true statement "
        "chosen earns 1/{} of the points; each false one chosen takes 1/{} away.",
        right_chosen, trues, wrong_chosen, falses, trues, falses);
  return judged(credit > 0 ? Verdict::Partial : Verdict::Incorrect, credit, why);
}

}  // namespace frustum
