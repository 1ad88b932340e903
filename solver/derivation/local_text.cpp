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

namespace {

std::string quoted_in(const std::string& own, const std::map<Lang, std::string>& given, Lang lang) {
  const auto it = given.find(lang);
  return tr(it == given.end() ? own : it->second, lang);
}

}  // namespace

std::string title_in(const Step& step, Lang lang) {
  return quoted_in(step.title, step.titles, lang);
}
std::string note_in(const Step& step, Lang lang) { return quoted_in(step.note, step.notes, lang); }

}  // namespace frustum
