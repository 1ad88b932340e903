#include "solver/derivation/local_text.hpp"

namespace frustum {

const std::string& LocalText::in(Lang reader) const {
  const auto it = translations.find(reader);
  return it == translations.end() ? text : it->second;
}

std::vector<std::pair<Lang, std::string>> LocalText::all() const {
  std::vector<std::pair<Lang, std::string>> out;
  out.emplace_back(lang, text);
  for (const auto& [l, t] : translations) out.emplace_back(l, t);
  return out;
}

Said said(const LocalText& text) {
  return Said(text.in(Lang::En), text.in(Lang::Ja), text.in(Lang::Ru));
}

}  // namespace frustum
