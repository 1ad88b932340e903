#include "grader/answer_parser.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "solver/core/exact.hpp"
#include "solver/core/work_budget.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/util/expression.hpp"
#include "solver/util/words.hpp"

namespace frustum {

namespace reading {

// Why an answer cannot be read, and how it was read when not exactly.
constexpr Phrase kAnswerTooLong{"the answer is too long (more than {0} bytes)",
                                "解答が長すぎます ({0} バイトを超えています)",
                                "ответ слишком длинный (больше {0} байт)"};
constexpr Phrase kEmptyAnswer{"empty answer", "空の解答", "пустой ответ"};
constexpr Phrase kReadNumerically{
    "too complex to compare exactly, so its value was computed to {0} significant digits and "
    "compared within the tolerance",
    "厳密に比較するには複雑すぎるので, 値を有効数字 {0} 桁で計算し, 許容誤差内で比較しました",
    "слишком сложен для точного сравнения, поэтому его значение вычислено с {0} значащими "
    "цифрами и сравнено в пределах допуска"};
// A number. '{0}' is the answer's text quoted (quote_excerpt without its quotes), kept as
// written in every language.
constexpr Phrase kCannotRead{"cannot read '{0}': {1}", "`{0}` を読めません: {1}",
                             "не удаётся прочитать `{0}`: {1}"};
constexpr Phrase kNotRealNumber{"'{0}' is not a real number", "`{0}` は実数ではありません",
                                "`{0}` — не действительное число"};
constexpr Phrase kCannotEvaluate{"'{0}' cannot be evaluated as a number",
                                 "`{0}` は数として評価できません",
                                 "`{0}` нельзя вычислить как число"};
// Lists of numbers, vectors, rows and vertices.
constexpr Phrase kCannotDivideVector{"cannot divide the vector by '{0}', which is 0",
                                     "ベクトルを `{0}` で割れません (0 です)",
                                     "нельзя разделить вектор на `{0}`: это 0"};
constexpr Phrase kItemNotNumber{"item {0} is not a number", "要素 {0} は数ではありません",
                                "элемент {0} — не число"};
constexpr Phrase kExpectedNumbers{"expected a list of numbers", "数のリストが必要です",
                                  "ожидался список чисел"};
constexpr Phrase kExpectedRows{"expected a list of rows, like {0} or {1}",
                               "行のリストが必要です (例: {0} または {1})",
                               "ожидался список строк, например {0} или {1}"};
constexpr Phrase kExpectedVertices{"expected a list of vertices, like {0} or {1}",
                                   "頂点のリストが必要です (例: {0} または {1})",
                                   "ожидался список вершин, например {0} или {1}"};
constexpr Phrase kInRow{"row {0}: {1}", "行 {0}: {1}", "строка {0}: {1}"};
constexpr Phrase kInVertex{"vertex {0}: {1}", "頂点 {0}: {1}", "вершина {0}: {1}"};
constexpr Phrase kRowsDifferentLengths{"the rows have different lengths",
                                       "行の長さがそろっていません", "строки разной длины"};
constexpr Phrase kVertexWrongCoordinates{"vertex {0}: wrong number of coordinates",
                                         "頂点 {0}: 座標の個数が違います",
                                         "вершина {0}: неверное число координат"};
// A list of words.
constexpr Phrase kItemNotWord{"item {0} is not a word", "要素 {0} は語ではありません",
                              "элемент {0} — не слово"};
constexpr Phrase kExpectedList{"expected a list", "リストが必要です", "ожидался список"};

// Untrusted text as a message quotes it ('1+1+1...'), without the quotes: a phrase places it
// in each language's own quotes.
std::string excerpt(std::string_view text) {
  const std::string q = quote_excerpt(text);
  return q.substr(1, q.size() - 2);
}

// A word of an answer's category or truth value as the key prints it in each language.
Said word_said(const std::string& word) { return words::vocabulary_word(word); }

// Words a student may write for each category and boolean, with Japanese equivalents.
const std::vector<std::pair<std::string, std::string>> kWordSynonyms = {
    {"front", "front"},        {"表", "front"},         {"おもて", "front"},
    {"front-facing", "front"}, {"back", "back"},        {"裏", "back"},
    {"うら", "back"},          {"back-facing", "back"}, {"edge_on", "edge_on"},
    {"edge-on", "edge_on"},    {"edge on", "edge_on"},  {"真横", "edge_on"},
    {"visible", "visible"},    {"可視", "visible"},     {"silhouette", "silhouette"},
    {"輪郭線", "silhouette"},  {"輪郭", "silhouette"},  {"hidden", "hidden"},
    {"不可視", "hidden"},      {"見える", "visible"},   {"隠れる", "hidden"},
    {"concave", "not convex"}, {"凹", "not convex"},    {"内部", "inside"},
    {"外部", "outside"},       {"вне", "outside"}};

// The word a student wrote, as one of `candidates` when it is one of them in English, a listed
// synonym, or the Japanese or Russian word the derivations print for it (what the key shows a
// student reading in that language is accepted back). Unchanged otherwise.
std::string known_word(const std::string& written, const std::vector<std::string>& candidates) {
  std::string w = trim_lower(written);
  for (const auto& [syn, canon] : kWordSynonyms)
    if (syn == w) return canon;
  for (const std::string& c : candidates) {
    const Said said = word_said(c);
    for (const Lang lang : {Lang::Ja, Lang::Ru})
      if (trim_lower(said.in(lang)) == w) return c;
  }
  return w;
}

// An answer too complex to simplify within its work budget keeps only its value, computed
// with this many digits and rounded to a double; parse_answer then drops the exact form.
constexpr long kNumericFallbackDigits = 40;

// `infinity`: where an answer holds +∞ as a stand-in number (AnswerSpec::infinity), +∞ written
// inf, ∞ or infinity (or YAML's .inf) is that number; 0: +∞ is no answer.
Exact parse_one(const std::string& text, Said& error, WorkBudget& budget, double infinity) {
  // YAML's spellings of NaN and infinity (the expression parser knows nan, inf and ∞).
  const std::string t = trim_lower(text);
  const std::string body = !t.empty() && (t[0] == '+' || t[0] == '-') ? t.substr(1) : t;
  if (infinity != 0 && (t.empty() || t[0] != '-') &&
      (body == "inf" || body == ".inf" || body == "infinity" || body == "∞"))
    return exact_from_double(infinity);
  if (body == ".nan" || body == ".inf") {
    error = say(kNotFiniteNumber, excerpt(text));
    return 0;
  }
  ExpressionOptions options;
  options.degree_sign = true;
  const ExpressionResult r = parse_expression(text, options);
  if (!r) {
    error = say(kCannotRead, excerpt(text), r.error);
    return 0;
  }
  if (!is_real_constant(*r.value)) {
    error = say(kNotRealNumber, excerpt(text));
    return 0;
  }
  const Exact e = canonical(*r.value, budget);
  if (!budget.exceeded()) return e;
  const double v = to_double(e);  // kNumericFallbackDigits digits, then rounded
  if (!std::isfinite(v)) error = say(kCannotEvaluate, excerpt(text));
  return std::isfinite(v) ? exact_from_double(v) : Exact(0);
}

namespace {

// One bracket pair around the whole text: "(1, 2)", not "(0, 3), (1, 2)".
bool wrapped(const std::string& s) {
  if (s.size() < 2 ||
      !((s.front() == '(' && s.back() == ')') || (s.front() == '[' && s.back() == ']')))
    return false;
  int depth = 0;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    if (s[i] == '(' || s[i] == '[') ++depth;
    if (s[i] == ')' || s[i] == ']') --depth;
    if (depth == 0) return false;  // the first bracket closed before the end
  }
  return true;
}

}  // namespace

std::string trimmed(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

namespace {

// Splits "a, b, c" at top-level separators (commas; with `semicolons`, also ';').
std::vector<std::string> split_top(const std::string& s, bool semicolons = false) {
  std::vector<std::string> out;
  int depth = 0;
  std::string cur;
  for (char c : s) {
    if (c == '(' || c == '[') ++depth;
    if (c == ')' || c == ']') --depth;
    if ((c == ',' || (semicolons && c == ';')) && depth == 0) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

}  // namespace

std::vector<std::string> split_list(std::string s) {
  s = trimmed(s);
  if (wrapped(s)) s = s.substr(1, s.size() - 2);
  return split_top(s);
}

std::vector<std::string> split_rows(std::string s) {
  s = trimmed(s);
  if (wrapped(s)) {
    const std::string inner = trimmed(s.substr(1, s.size() - 2));
    if (!inner.empty() && (inner.front() == '(' || inner.front() == '[') &&
        split_top(inner, true).size() > 1)
      s = inner;
  }
  std::vector<std::string> rows = split_top(s, true);
  for (std::string& r : rows) {
    r = trimmed(r);
    if (!wrapped(r)) return {};
  }
  return rows;
}

namespace {

// "(1/√21)(−2, 1, 4)", "1/sqrt(21)*(-2, 1, 4)", "(-2, 1, 4)/sqrt(21)", "−(1, 2, 3)": one tuple
// (a bracket group holding commas) with a factor before it, or "/ FACTOR" or "* FACTOR" after
// it, read as the tuple's components times the factor, exactly and within the answer's work
// budget. Nothing when the text is not of this form (a plain list is read as before).
std::optional<Numbers> read_scaled_tuple(const std::string& text, WorkBudget& budget) {
  const std::string s = trimmed(text);
  // The top-level bracket groups; exactly one of them must hold a comma.
  std::size_t open = std::string::npos, close = std::string::npos;
  int depth = 0, tuples = 0;
  std::size_t start = 0;
  bool comma = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '(' || c == '[') {
      if (depth++ == 0) {
        start = i;
        comma = false;
      }
    } else if (c == ')' || c == ']') {
      if (--depth < 0) return std::nullopt;
      if (depth == 0 && comma) {
        ++tuples;
        open = start;
        close = i;
      }
    } else if (c == ',') {
      if (depth == 0) return std::nullopt;  // a plain list "a, b, c"
      if (depth == 1) comma = true;
    }
  }
  if (depth != 0 || tuples != 1) return std::nullopt;
  std::string before = trimmed(s.substr(0, open)), after = trimmed(s.substr(close + 1));
  if (before.empty() && after.empty()) return std::nullopt;
  Numbers out;
  Exact factor = 1;
  const auto times = [&](std::string f, bool divide) {
    f = trimmed(f);
    if (f.empty()) return false;
    Said error;
    const Exact v = parse_one(f, error, budget);
    if (!error.empty()) {
      out.error = error;
      return false;
    }
    if (divide && v.is_zero()) {
      out.error = say(kCannotDivideVector, excerpt(f));
      return false;
    }
    factor = divide ? factor / v : factor * v;
    return true;
  };
  for (const char* op : {"*", "·", "⋅"})
    if (before.size() > std::string(op).size() &&
        before.compare(before.size() - std::string(op).size(), std::string::npos, op) == 0) {
      before = trimmed(before.substr(0, before.size() - std::string(op).size()));
      break;
    }
  if (before == "-" || before == "−")
    factor = -1;
  else if (!before.empty() && !times(before, false))
    return out.error.empty() ? std::nullopt : std::optional<Numbers>(out);
  if (!after.empty()) {
    const bool divide = after[0] == '/';
    std::size_t op = after[0] == '/' || after[0] == '*' ? 1 : 0;
    if (op == 0)
      for (const char* mul : {"·", "⋅"})
        if (after.compare(0, std::string(mul).size(), mul) == 0) op = std::string(mul).size();
    if (op == 0) return std::nullopt;
    if (!times(after.substr(op), divide))
      return out.error.empty() ? std::nullopt : std::optional<Numbers>(out);
  }
  for (const std::string& item : split_top(s.substr(open + 1, close - open - 1))) {
    const Exact v = parse_one(item, out.error, budget);
    if (!out.error.empty()) return out;
    out.values.push_back(canonical(v * factor, budget));
  }
  return out;
}

}  // namespace

Numbers read_numbers(const YAML::Node& n, WorkBudget& budget, double infinity) {
  if (n.IsScalar())
    if (std::optional<Numbers> scaled = read_scaled_tuple(n.Scalar(), budget)) return *scaled;
  Numbers out;
  std::vector<std::string> items;
  if (n.IsSequence()) {
    for (std::size_t i = 0; i < n.size(); ++i) {
      if (!n[i].IsScalar()) {
        out.error = say(kItemNotNumber, i + 1);
        return out;
      }
      items.push_back(n[i].Scalar());
    }
  } else if (n.IsScalar()) {
    items = split_list(n.Scalar());
  } else {
    out.error = say(kExpectedNumbers);
    return out;
  }
  for (const std::string& item : items) {
    out.values.push_back(parse_one(item, out.error, budget, infinity));
    if (!out.error.empty()) return out;
  }
  return out;
}

Rows read_rows(const YAML::Node& node, bool vertices, WorkBudget& budget, double infinity) {
  Rows out;
  std::vector<YAML::Node> rows;
  if (node.IsSequence() && node.size() > 0) {
    for (std::size_t r = 0; r < node.size(); ++r) rows.push_back(node[r]);
  } else if (node.IsScalar()) {
    for (const std::string& r : split_rows(node.Scalar())) rows.emplace_back(r);
  }
  if (rows.empty()) {
    out.error =
        say(vertices ? kExpectedVertices : kExpectedRows, "[[0, 4], [8, 8]]", "\"(0, 4), (8, 8)\"");
    return out;
  }
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Numbers n = read_numbers(rows[r], budget, infinity);
    if (!n.error.empty()) {
      out.error = say(vertices ? kInVertex : kInRow, r + 1, n.error);
      return out;
    }
    if (!out.values.empty() && n.values.size() != out.values[0].size()) {
      out.error = vertices ? say(kVertexWrongCoordinates, r + 1) : say(kRowsDifferentLengths);
      return out;
    }
    out.values.push_back(n.values);
  }
  return out;
}

Said read_number(const YAML::Node& node, WorkBudget& budget, Exact& value) {
  if (!node.IsScalar()) return say(kExpectedOneNumber);
  Said error;
  value = parse_one(node.Scalar(), error, budget);
  return error;
}

Said read_word_list(const YAML::Node& node, bool unordered_pairs, std::vector<std::string>& words) {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      // A pair written as a list of its two ends: [0, 3] is the edge 0-3.
      const YAML::Node& item = node[i];
      if (unordered_pairs && item.IsSequence() && item.size() == 2 && item[0].IsScalar() &&
          item[1].IsScalar()) {
        words.push_back(trimmed(item[0].Scalar()) + "-" + trimmed(item[1].Scalar()));
        continue;
      }
      if (!node[i].IsScalar()) return say(kItemNotWord, i + 1);
      words.push_back(trimmed(node[i].Scalar()));  // labels keep their case ("A.B")
    }
  } else if (node.IsScalar()) {
    // Pairs written as bracketed tuples: "(0, 3), (1, 2)".
    const std::vector<std::string> rows =
        unordered_pairs ? split_rows(node.Scalar()) : std::vector<std::string>{};
    for (std::string w : rows.empty() ? split_list(node.Scalar()) : rows) {
      w = trimmed(w);
      if (!w.empty()) words.push_back(w);
    }
  } else {
    return say(kExpectedList);
  }
  return {};
}

}  // namespace reading

namespace {

// Appends the node's text until `out` is longer than `limit` (aliases can make a small file
// expand to a huge tree, so the walk stops early instead of visiting it all).
// A text inside a list (a row written "1/2, 0, 0, 0") keeps its quotes when it holds a
// separator: shown bare, ["1/2, 0", "0, 1"] would read as one flat list of four numbers.
void append_raw(const YAML::Node& node, std::string& out, std::size_t limit, bool nested = false) {
  if (out.size() > limit) return;
  if (node.IsScalar()) {
    const std::string& text = node.Scalar();
    const bool quote =
        nested && node.Tag() == "!" && text.find_first_of(",;[]{}") != std::string::npos;
    out += quote ? "\"" + text + "\"" : text;
  } else if (node.IsSequence()) {
    out += "[";
    for (std::size_t i = 0; i < node.size() && out.size() <= limit; ++i) {
      if (i) out += ", ";
      append_raw(node[i], out, limit, true);
    }
    out += "]";
  } else if (node.IsMap()) {
    out += "{";
    bool first = true;
    for (auto it = node.begin(); it != node.end() && out.size() <= limit; ++it) {
      if (!first) out += ", ";
      append_raw(it->first, out, limit, true);
      out += ": ";
      append_raw(it->second, out, limit, true);
      first = false;
    }
    out += "}";
  }
}

}  // namespace

std::string raw_text(const YAML::Node& node) {
  std::string s;
  append_raw(node, s, kMaxExpressionLength * 4);
  return s;
}

namespace {

// A name as compared: without case, spaces, `_`, braces and backslashes, Unicode subscripts,
// primes and superscripts spelled in ASCII (D_f, Df, D_{f}; M⁻¹, M^-1, M^{-1}; P′, P').
std::string symbol_key(const std::string& written) {
  static const std::pair<std::string_view, std::string_view> kSpellings[] = {
      {"₀", "0"}, {"₁", "1"}, {"₂", "2"}, {"₃", "3"}, {"₄", "4"},    {"₅", "5"}, {"₆", "6"},
      {"₇", "7"}, {"₈", "8"}, {"₉", "9"}, {"′", "'"}, {"⁻¹", "^-1"}, {"⋅", "·"}, {"−", "-"}};
  std::string out;
  for (std::size_t i = 0; i < written.size();) {
    bool spelled = false;
    for (const auto& [from, to] : kSpellings)
      if (written.compare(i, from.size(), from) == 0) {
        out += to;
        i += from.size();
        spelled = true;
        break;
      }
    if (spelled) continue;
    const char c = written[i++];
    if (c != ' ' && c != '\t' && c != '_' && c != '{' && c != '}' && c != '\\') out += c;
  }
  return ascii_lower(out);
}

// What follows "NAME =" when a text answer starts with the answer's name, or a symbol the
// derivation uses for it (AnswerSpec::symbols: "D_f = 27", "s = −415.7"), and holds one '='.
std::optional<std::string> value_after_own_name(const YAML::Node& node, const AnswerSpec& spec) {
  if (!node.IsScalar() || answer_type(spec.kind).own_equals) return std::nullopt;
  const std::string& text = node.Scalar();
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || text.find('=', eq + 1) != std::string::npos) return std::nullopt;
  const std::string left = symbol_key(text.substr(0, eq));
  if (left.empty() ||
      (left != symbol_key(spec.name) &&
       std::none_of(spec.symbols.begin(), spec.symbols.end(),
                    [&](const std::string& sym) { return symbol_key(sym) == left; })))
    return std::nullopt;
  const std::string rest = reading::trimmed(text.substr(eq + 1));
  if (rest.empty()) return std::nullopt;
  return rest;
}

}  // namespace

ParsedAnswer parse_answer(const YAML::Node& node, const AnswerSpec& spec, AngleUnit angles) {
  ParsedAnswer p;
  WorkBudget budget;  // one for the whole answer, shared by its numbers
  p.raw = raw_text(node);
  if (p.raw.size() > kMaxExpressionLength * 4) {
    p.error = say(reading::kAnswerTooLong, kMaxExpressionLength * 4);
    // Reports show the start only.
    std::size_t cut = 64;
    while (cut > 0 && (static_cast<unsigned char>(p.raw[cut]) & 0xC0) == 0x80) --cut;
    p.raw = p.raw.substr(0, cut) + "...";
    return p;
  }
  if (!node.IsDefined() || node.IsNull()) {
    p.error = say(reading::kEmptyAnswer);
    return p;
  }
  // "none": the answer has no value (a segment clipped away, no unit normal of parallel vectors).
  if (node.IsScalar() && (trim_lower(node.Scalar()) == "none" || node.Scalar() == "なし")) {
    p.value = Value::null();
    p.ok = true;
    return p;
  }
  // "z = 8" for the answer z: the answer's own name on the left of one '=' is dropped (not
  // for a plane, which may be an equation such as "z = 8 - x - y").
  const std::optional<std::string> rest = value_after_own_name(node, spec);
  AnswerReading reading{angles, budget};
  const Said error = answer_type(spec.kind).read(rest ? YAML::Node(*rest) : node, spec, reading, p);
  if (!error.empty()) {
    p.error = error;
    p.value = Value();
    return p;
  }
  if (budget.exceeded()) {
    p.value.exact.clear();
    p.note = say(reading::kReadNumerically, reading::kNumericFallbackDigits);
  }
  p.ok = true;
  return p;
}

}  // namespace frustum
