#include "solver/derivation/i18n.hpp"

#include <algorithm>
#include <cstdlib>
#include <unordered_map>
#include <utility>
#include <vector>

#include "solver/derivation/phrases.hpp"

namespace frustum {

namespace {

bool is_word(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }

// A pattern's English cut at its slots: literal₀ {slot₀} literal₁ … literalₖ.
struct Pattern {
  const Phrase* phrase;
  std::vector<std::string_view> literals;
  std::vector<int> slots;
};

Pattern cut(const Phrase& p) {
  Pattern out{&p, {}, {}};
  std::string_view en = p.en;
  std::size_t from = 0;
  for (std::size_t at; (at = en.find('{', from)) != std::string_view::npos;) {
    const std::size_t close = en.find('}', at);
    out.literals.push_back(en.substr(from, at - from));
    out.slots.push_back(en[at + 1] - '0');
    from = close + 1;
  }
  out.literals.push_back(en.substr(from));
  return out;
}

struct Catalogue {
  std::unordered_map<std::string_view, const Phrase*> whole;
  std::vector<Pattern> patterns;       // most literal text first: the most specific wins
  std::vector<const Phrase*> phrases;  // plain phrases, longest first, for inside a sentence
};

const Catalogue& catalogue() {
  static const Catalogue c = [] {
    Catalogue out;
    for (const auto part : {step_phrases(), note_phrases(), grading_phrases()})
      for (const Phrase& p : part) {
        if (p.en.find("{0}") != std::string_view::npos) {
          out.patterns.push_back(cut(p));
        } else {
          out.whole.emplace(p.en, &p);
          out.phrases.push_back(&p);
        }
      }
    const auto literal_size = [](const Pattern& p) {
      std::size_t n = 0;
      for (const auto l : p.literals) n += l.size();
      return n;
    };
    std::stable_sort(
        out.patterns.begin(), out.patterns.end(),
        [&](const Pattern& a, const Pattern& b) { return literal_size(a) > literal_size(b); });
    std::stable_sort(out.phrases.begin(), out.phrases.end(),
                     [](const Phrase* a, const Phrase* b) { return a->en.size() > b->en.size(); });
    return out;
  }();
  return c;
}

std::string_view in(const Phrase& p, Lang lang) { return lang == Lang::Ja ? p.ja : p.ru; }

// Matches text against literals[i…] with captures (each non-empty but a quoted one, shortest
// first).
bool match(const Pattern& p, std::size_t i, std::string_view text,
           std::vector<std::string_view>& caps) {
  const std::string_view lit = p.literals[i];
  if (text.substr(0, lit.size()) != lit) return false;
  text.remove_prefix(lit.size());
  if (i + 1 == p.literals.size()) return text.empty();
  const std::string_view next = p.literals[i + 1];
  if (next.empty() && i + 2 == p.literals.size()) {  // the last slot takes the rest
    if (text.empty()) return false;
    caps.push_back(text);
    return true;
  }
  // A quoted value may be empty ('' is how an empty answer is quoted); other slots may not.
  const bool quoted = !lit.empty() && lit.back() == '\'' && !next.empty() && next.front() == '\'';
  for (std::size_t end = text.find(next, quoted ? 0 : 1); end != std::string_view::npos;
       end = text.find(next, end + 1)) {
    caps.push_back(text.substr(0, end));
    if (match(p, i + 1, text.substr(end), caps)) return true;
    caps.pop_back();
  }
  return false;
}

std::optional<std::string> translate_whole(std::string_view text, Lang lang, bool patterns);

std::string fill(const Pattern& p, const std::vector<std::string_view>& caps, Lang lang) {
  std::string out;
  const std::string_view to = in(*p.phrase, lang);
  for (std::size_t i = 0; i < to.size(); ++i) {
    if (to[i] == '{' && i + 2 < to.size() && to[i + 2] == '}') {
      const int slot = to[i + 1] - '0';
      // A slot written in `code` (a field of the problem) is a name: it stays as written.
      for (std::size_t k = 0; k < p.slots.size(); ++k)
        if (p.slots[k] == slot)
          out += i > 0 && to[i - 1] == '`' ? std::string(caps[k]) : tr(caps[k], lang);
      i += 2;
    } else {
      out += to[i];
    }
  }
  return out;
}

// A whole text from the catalogue, or (`patterns`: the text is one sentence) a pattern filled.
std::optional<std::string> translate_whole(std::string_view text, Lang lang, bool patterns) {
  const Catalogue& c = catalogue();
  if (const auto it = c.whole.find(text); it != c.whole.end())
    return std::string(in(*it->second, lang));
  if (!patterns) return std::nullopt;
  std::vector<std::string_view> caps;
  for (const Pattern& p : c.patterns) {
    caps.clear();
    if (match(p, 0, text, caps)) return fill(p, caps, lang);
  }
  return std::nullopt;
}

// Known phrases inside a sentence the catalogue does not hold whole, at word boundaries so
// that "Normal" does not eat "Normalize".
std::string translate_inside(std::string_view sentence, Lang lang) {
  std::string out(sentence);
  for (const Phrase* p : catalogue().phrases) {
    if (p->en.size() < 4) continue;  // short words only as whole texts
    const std::string_view to = in(*p, lang);
    std::size_t at = 0;
    while ((at = out.find(p->en, at)) != std::string::npos) {
      const bool left = at == 0 || !is_word(out[at - 1]);
      const bool right = at + p->en.size() >= out.size() || !is_word(out[at + p->en.size()]);
      if (left && right) {
        out.replace(at, p->en.size(), to);
        at += to.size();
      } else {
        at += p->en.size();
      }
    }
  }
  return out;
}

// Sentences: a text is cut after ". " (or ".) ") before a capital letter, and at line breaks.
std::vector<std::string_view> sentences(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t from = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') {
      out.push_back(text.substr(from, i - from));
      out.push_back(text.substr(i, 1));
      from = i + 1;
    } else if (text[i] == ' ' && i > from &&
               (text[i - 1] == '.' || (text[i - 1] == ')' && i > from + 1 && text[i - 2] == '.')) &&
               i + 1 < text.size() &&
               ((text[i + 1] >= 'A' && text[i + 1] <= 'Z') || text[i + 1] == '(')) {
      out.push_back(text.substr(from, i - from));
      from = i + 1;
    }
  }
  out.push_back(text.substr(from));
  return out;
}

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

std::string tr(std::string_view english, Lang lang) {
  if (lang == Lang::En || english.empty()) return std::string(english);
  const std::vector<std::string_view> parts = sentences(english);
  if (auto whole = translate_whole(english, lang, parts.size() == 1)) return *whole;
  if (parts.size() == 1) return translate_inside(english, lang);
  std::string out;
  for (const std::string_view s : parts) {
    if (s == "\n") {
      out += '\n';
      continue;
    }
    if (!out.empty() && out.back() != '\n') out += ' ';
    // A line's indentation (a trace under its heading) stays; the text after it is translated.
    const std::size_t indent = std::min(s.find_first_not_of(' '), s.size());
    out += s.substr(0, indent);
    const std::string_view body = s.substr(indent);
    auto whole = translate_whole(body, lang, true);
    out += whole ? *whole : translate_inside(body, lang);
  }
  return out;
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
  const auto form = [lang](const CountForms& c, const std::string& digits) {
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
    for (const CountForms& c : count_forms()) {
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

Said::Said(const std::string& english)
    : text_{english, tr(english, Lang::Ja), tr(english, Lang::Ru)} {}

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
