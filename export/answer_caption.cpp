#include "export/answer_caption.hpp"

namespace frustum {

std::string answer_caption(const ProblemSpec& p, const std::string& name, Lang lang) {
  const AnswerSpec* spec = p.info ? p.info->answer(name) : nullptr;
  if (spec && !spec->symbols.empty()) return spec->symbols.front();
  if (spec && !spec->label.empty()) return spec->label.in(lang);
  return name;
}

}  // namespace frustum
