// What an instructor writes for students — a problem's text, a set's title, a statement and its
// reason — in the languages the set gives it: always in the set's own language (`lang:`, English
// by default), and in others where the file writes a mapping {en: …, ja: …, ru: …}. A reader
// asking for a language the set does not give reads the set's own text.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "solver/derivation/derivation.hpp"
#include "solver/derivation/i18n.hpp"

namespace frustum {

struct LocalText {
  Lang lang = Lang::En;                      // the set's own language: `text` is written in it
  std::string text;                          // in `lang`
  std::map<Lang, std::string> translations;  // the other languages the set gives

  bool empty() const { return text.empty(); }
  // The text in `reader`'s language, or the set's own.
  const std::string& in(Lang reader) const;
  // Every language given, the set's own first (even when empty): (language, text).
  std::vector<std::pair<Lang, std::string>> all() const;
  // The same languages with each text transformed (placeholders filled).
  template <typename F>
  LocalText map(F f) const {
    LocalText out{lang, f(text), {}};
    for (const auto& [l, t] : translations) out.translations.emplace(l, f(t));
    return out;
  }
};

// The text in every language: each as the set gives it, else the set's own.
Said said(const LocalText& text);

}  // namespace frustum
