#include "grader/statement_choice.hpp"

#include <string_view>
#include <vector>

#include "solver/kinds/statements.hpp"
#include "solver/util/expression.hpp"
#include "solver/util/scripts.hpp"
#include "solver/util/words.hpp"

namespace frustum {

namespace {

// Statement numbers longer than this are out of range whatever the problem.
constexpr std::size_t kMaxNumberDigits = 4;

// Why an answer cannot be read.
constexpr Phrase kNoStatementZero{"there is no statement 0: the statements are numbered from 1",
                                  "記述 0 はない. 記述の番号は 1 から始まる",
                                  "утверждения 0 нет: утверждения нумеруются с 1"};
constexpr Phrase kNeitherNumberNorTruth{
    "'{0}' is neither the number of a statement nor true or false",
    "`{0}` は記述の番号でも真偽の値でもない", "`{0}` — не номер утверждения и не верно/неверно"};
constexpr Phrase kMixesNumbersAndTruths{
    "the answer mixes statement numbers and true/false: write the numbers of the true statements, "
    "like [1, 3], or one true/false per statement, like [true, false, true]",
    "記述の番号と真偽の値が混ざっている. 正しい記述の番号 (例: [1, 3]) か, 記述ごとの真偽 (例: [○, "
    "×, ○]) のどちらかで書くこと",
    "в ответе смешаны номера утверждений и верно/неверно: укажите номера верных утверждений, "
    "например [1, 3], или по одному верно/неверно на утверждение, например [да, нет, да]"};
constexpr Phrase kNoSuchStatement{"there is no statement {0}: the statements are numbered 1 to {1}",
                                  "記述 {0} はない. 記述の番号は 1 から {1} まで",
                                  "утверждения {0} нет: утверждения пронумерованы от 1 до {1}"};
constexpr Phrase kItemNotNumberOrTruth{"item {0} is not a statement number or true/false",
                                       "{0} 番目の項目は記述の番号でも真偽の値でもない",
                                       "элемент {0} — не номер утверждения и не верно/неверно"};
constexpr Phrase kItemEmpty{"item {0} is empty", "{0} 番目の項目が空", "элемент {0} пуст"};
constexpr Phrase kMappingKeysAreNumbers{
    "a mapping's keys are statement numbers 1, 2, …, like {1: true, 2: false}",
    "対応表のキーは記述の番号 1, 2, … (例: {1: ○, 2: ×})",
    "ключи соответствия — номера утверждений 1, 2, …, например {1: да, 2: нет}"};
constexpr Phrase kStatementExpectsTruth{"statement {0}: expected true or false",
                                        "記述 {0}: 真偽 (○ か ×) を書くこと",
                                        "утверждение {0}: ожидается верно или неверно"};
constexpr Phrase kExpectedTrueStatementNumbers{"expected the numbers of the true statements",
                                               "正しい記述の番号を書くこと",
                                               "ожидаются номера верных утверждений"};
constexpr Phrase kEmptyAnswer{"empty answer: write the numbers of the true statements, or none",
                              "解答が空. 正しい記述の番号を書くか, なければ「なし」と書くこと",
                              "пустой ответ: укажите номера верных утверждений или «ни одного»"};
constexpr Phrase kStatementGivenTwice{"statement {0} is given twice",
                                      "記述 {0} が 2 回書かれている",
                                      "утверждение {0} указано дважды"};
constexpr Phrase kStatementsButTruths{
    "{0} statements, but {1} true/false values: give one per statement, or the numbers of the true "
    "ones",
    "記述は {0} 個だが, 真偽の値は {1} 個. 記述ごとに 1 つ書くか, 正しい記述の番号を書くこと",
    "утверждений {0}, а значений верно/неверно {1}: укажите по одному на утверждение или номера "
    "верных"};
// How it is judged.
constexpr Phrase kStatementTrueNotFalse{
    "Statement {0} is true, not false (see step {1}).",
    "記述 {0} は正しい (○). 誤り (×) ではない (ステップ {1} 参照).",
    "Утверждение {0} верно, а не неверно (см. шаг {1})."};
constexpr Phrase kStatementFalseNotTrue{
    "Statement {0} is false, not true (see step {1}).",
    "記述 {0} は誤り (×). 正しい (○) ではない (ステップ {1} 参照).",
    "Утверждение {0} неверно, а не верно (см. шаг {1})."};
constexpr Phrase kYouChose{
    "You chose {0} of the {1} true statements and {2} of the {3} false ones.",
    "{1} 個の正しい記述のうち {0} 個と, {3} 個の誤った記述のうち {2} 個を選んだ.",
    "Выбрано верных утверждений: {0} из {1}, неверных: {2} из {3}."};
constexpr Phrase kEachChosenEarns{
    "Each true statement chosen earns 1/{0} of the points; each false one chosen takes 1/{1} away.",
    "正しい記述を 1 つ選ぶごとに配点の 1/{0} を得て, 誤った記述を 1 つ選ぶごとに 1/{1} を失う.",
    "Каждое выбранное верное утверждение даёт 1/{0} баллов, каждое выбранное неверное отнимает "
    "1/{1}."};

// Full-width digits (１２) as ASCII; empty when the token is not all digits. Leading zeros go.
std::string digits_of(std::string_view token) {
  std::string out;
  for (const std::string_view c : characters_of(token)) {
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
  for (const std::string_view c : characters_of(text)) {
    if (c == "," || c == ";" || c == " " || c == "\t" || c == "\n" || c == "、" || c == "，" ||
        c == "[" || c == "]" || c == "(" || c == ")" || c == "　")
      flush();
    else
      cur += c;
  }
  flush();
  if (out.size() == 1 && !truth_word(out[0])) {
    const std::vector<std::string_view> marks = characters_of(out[0]);
    bool all_marks = marks.size() > 1;
    for (const std::string_view m : marks) all_marks = all_marks && truth_word(m) && m.size() > 1;
    if (all_marks) return {marks.begin(), marks.end()};
  }
  return out;
}

StatementChoice failed(Said why) { return {Value::null(), std::move(why)}; }

// A list of tokens as numbers or as truths, never both.
StatementChoice from_tokens(const std::vector<std::string>& tokens) {
  std::vector<std::string> numbers;
  std::vector<std::pair<std::string, std::string>> truths;
  for (const std::string& t : tokens) {
    if (const std::string d = digits_of(t); !d.empty()) {
      if (d == "0") return failed(say(kNoStatementZero));
      numbers.push_back(d);
    } else if (const std::optional<bool> b = truth_word(t)) {
      truths.emplace_back(std::to_string(truths.size() + 1), *b ? "true" : "false");
    } else {
      // quote_excerpt's text without its quotes: the phrase quotes it in each language's way.
      const std::string quoted = quote_excerpt(t);
      return failed(say(kNeitherNumberNorTruth, quoted.substr(1, quoted.size() - 2)));
    }
  }
  if (!numbers.empty() && !truths.empty()) return failed(say(kMixesNumbersAndTruths));
  if (!truths.empty()) return {Value::word_map(std::move(truths)), {}};
  return {Value::word_list(std::move(numbers)), {}};
}

Comparison judged(Verdict v, double credit, Said why) {
  return {v, credit, std::move(why), {}, false, {}};
}

// The index of statement `number` (as read) among n, or nothing when there is no such statement.
std::optional<std::size_t> index_of(const std::string& number, std::size_t n) {
  if (number.empty() || number.size() > kMaxNumberDigits) return std::nullopt;
  const std::size_t k = std::stoul(number);
  if (k < 1 || k > n) return std::nullopt;
  return k - 1;
}

Said no_such(const std::string& number, std::size_t n) {
  const std::string shown = number.size() > 8 ? number.substr(0, 8) + "…" : number;
  return say(kNoSuchStatement, shown, n);
}

}  // namespace

StatementChoice read_statement_choice(const YAML::Node& node) {
  if (node.IsSequence()) {
    std::vector<std::string> tokens;
    for (std::size_t i = 0; i < node.size(); ++i) {
      if (!node[i].IsScalar()) return failed(say(kItemNotNumberOrTruth, i + 1));
      tokens.push_back(trim_lower(node[i].Scalar()));
      if (tokens.back().empty()) return failed(say(kItemEmpty, i + 1));
    }
    return from_tokens(tokens);
  }
  if (node.IsMap()) {
    std::vector<std::pair<std::string, std::string>> entries;
    for (auto it = node.begin(); it != node.end(); ++it) {
      const std::string key = it->first.IsScalar() ? digits_of(trim_lower(it->first.Scalar())) : "";
      if (key.empty() || key == "0") return failed(say(kMappingKeysAreNumbers));
      const std::optional<bool> b =
          it->second.IsScalar() ? truth_word(it->second.Scalar()) : std::nullopt;
      if (!b)
        return failed(say(kStatementExpectsTruth, key.size() > 8 ? key.substr(0, 8) + "…" : key));
      entries.emplace_back(key, *b ? "true" : "false");
    }
    return {Value::word_map(std::move(entries)), {}};
  }
  if (!node.IsScalar()) return failed(say(kExpectedTrueStatementNumbers));
  const std::string text = trim_lower(node.Scalar());
  // "none" and なし are read before any answer type; these say it in words of their own.
  for (const char* none : {"ни одного", "нет верных", "ない", "正しいものはない"})
    if (text == none) return {Value::null(), {}};
  const std::vector<std::string> tokens = tokens_of(text);
  if (tokens.empty()) return failed(say(kEmptyAnswer));
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
      if (seen[*i]) return judged(Verdict::Unparseable, 0, say(kStatementGivenTwice, k));
      seen[*i] = true;
      chosen[*i] = w == "true";
    }
    if (got.entries.size() != n)
      return judged(Verdict::Unparseable, 0, say(kStatementsButTruths, n, got.entries.size()));
  } else if (got.shape != Value::Shape::Null) {
    return judged(Verdict::Unparseable, 0, say(kExpectedTrueStatementNumbers));
  }
  const std::size_t falses = n - trues;
  std::size_t right_chosen = 0, wrong_chosen = 0;
  Said why;
  for (std::size_t i = 0; i < n; ++i) {
    right_chosen += chosen[i] && truth[i];
    wrong_chosen += chosen[i] && !truth[i];
    if (chosen[i] != truth[i])
      // The kind derives statement k in step k (it states no conventions before them).
      why += say(truth[i] ? kStatementTrueNotFalse : kStatementFalseNotTrue, i + 1, i + 1);
  }
  if (why.empty()) return judged(Verdict::Correct, 1, {});
  // Each true statement chosen earns 1/T, each false one chosen costs 1/F.
  const double earned =
      trues ? static_cast<double>(right_chosen) / static_cast<double>(trues) : 1.0;
  const double lost =
      falses ? static_cast<double>(wrong_chosen) / static_cast<double>(falses) : 0.0;
  const double credit = std::max(0.0, earned - lost);
  if (trues && falses)
    why += say(kYouChose, right_chosen, trues, wrong_chosen, falses) +
           say(kEachChosenEarns, trues, falses);
  return judged(credit > 0 ? Verdict::Partial : Verdict::Incorrect, credit, why);
}

}  // namespace frustum
