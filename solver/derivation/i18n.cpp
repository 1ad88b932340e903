#include "solver/derivation/i18n.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "solver/derivation/vocabulary.hpp"

namespace frustum {

namespace {

bool is_word(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }

}  // namespace

std::optional<Lang> parse_lang(std::string_view code) {
  if (code == "en") return Lang::En;
  if (code == "ja") return Lang::Ja;
  if (code == "ru") return Lang::Ru;
  return std::nullopt;
}

std::string_view to_string(Lang lang) {
  switch (lang) {
    case Lang::Ja:
      return "ja";
    case Lang::Ru:
      return "ru";
    case Lang::En:
      break;
  }
  return "en";
}

namespace {

// Longer words first: "0 back faces culled" is one phrase, not "0 back"; "window triangles" is
// not "window" and a translated "triangles".
std::vector<Said> longest_first(const MathText& m) {
  std::vector<Said> words = m.words;
  std::stable_sort(words.begin(), words.end(),
                   [](const Said& a, const Said& b) { return a.en().size() > b.en().size(); });
  return words;
}

// "N word", the word agreeing with N — English 1 triangle, 2 triangles; Russian 1 треугольник,
// 2 треугольника, 5 треугольников: each counted word of `m` right after a number and a space
// (LaTeX: N\,\text{word}).
void agree_counts(MathText& m, Lang lang) {
  const auto form = [lang](const words::CountForms& c, const std::string& digits) {
    if (lang == Lang::En) return digits == "1" ? c.en_one : c.en;
    const RuForm f =
        russian_form(std::stol(digits.substr(std::max<std::size_t>(digits.size(), 2) - 2)));
    return f == RuForm::One ? c.one : f == RuForm::Few ? c.few : c.many;
  };
  const auto digits_before = [](const std::string& s, std::size_t at) {
    std::size_t i = at;
    while (i > 0 && s[i - 1] >= '0' && s[i - 1] <= '9') --i;
    return s.substr(i, at - i);
  };
  for (const Said& said : longest_first(m))
    for (const words::CountForms& c : words::count_forms()) {
      const std::string& w = said.en();
      if (c.en != w) continue;
      const std::string unicode_word = " " + w, latex_word = "\\,\\text{" + latex_text(w) + "}";
      for (std::size_t at = 0; (at = m.unicode.find(unicode_word, at)) != std::string::npos;) {
        const std::string n = digits_before(m.unicode, at);
        const std::size_t end = at + unicode_word.size();
        const bool whole = end >= m.unicode.size() || !is_word(m.unicode[end]);
        if (n.empty() || !whole) {
          at = end;
          continue;
        }
        const std::string to = " " + std::string(form(c, n));
        m.unicode.replace(at, unicode_word.size(), to);
        at += to.size();
      }
      for (std::size_t at = 0; (at = m.latex.find(latex_word, at)) != std::string::npos;) {
        const std::string n = digits_before(m.latex, at);
        if (n.empty()) {
          at += latex_word.size();
          continue;
        }
        const std::string to = "\\,\\text{" + latex_text(form(c, n)) + "}";
        m.latex.replace(at, latex_word.size(), to);
        at += to.size();
      }
    }
}

}  // namespace

RuForm russian_form(long n) {
  const long last = std::abs(n) % 10, tens = std::abs(n) % 100;
  if (tens >= 11 && tens <= 14) return RuForm::Many;
  return last == 1 ? RuForm::One : last >= 2 && last <= 4 ? RuForm::Few : RuForm::Many;
}

MathText tr(const MathText& m, Lang lang) {
  if (m.words.empty()) return m;
  MathText out = m;
  if (lang != Lang::Ja) agree_counts(out, lang);
  if (lang == Lang::En) return out;
  for (const Said& said : longest_first(m)) {
    const std::string &w = said.en(), &t = said.in(lang);
    if (t == w) continue;
    for (std::size_t at = 0; (at = out.unicode.find(w, at)) != std::string::npos;) {
      const bool whole =
          (at == 0 || !is_word(out.unicode[at - 1])) &&
          (at + w.size() >= out.unicode.size() || !is_word(out.unicode[at + w.size()]));
      if (whole) {
        out.unicode.replace(at, w.size(), t);
        at += t.size();
      } else {
        at += w.size();
      }
    }
    const std::string from = "\\text{" + latex_text(w) + "}", to = "\\text{" + latex_text(t) + "}";
    for (std::size_t at = 0; (at = out.latex.find(from, at)) != std::string::npos; at += to.size())
      out.latex.replace(at, from.size(), to);
  }
  return out;
}

}  // namespace frustum
