#include "solver/util/said.hpp"

#include <utility>

namespace frustum {

namespace {

// Joins two texts of one language as consecutive sentences: one space between (none at a line
// break).
void join(std::string& left, const std::string& right, bool spaced) {
  if (right.empty()) return;
  if (spaced && !left.empty() && left.back() != '\n' && left.back() != ' ' &&
      right.front() != '\n' && right.front() != ' ')
    left += ' ';
  left += right;
}

}  // namespace

Said& Said::operator+=(const Said& next) {
  for (std::size_t i = 0; i < text_.size(); ++i) join(text_[i], next.text_[i], true);
  return *this;
}

Said& Said::append(const Said& next) {
  for (std::size_t i = 0; i < text_.size(); ++i) join(text_[i], next.text_[i], false);
  return *this;
}

Said said_detail::fill(const Phrase& p, const Said* args, std::size_t n) {
  std::array<std::string, 3> out;
  for (const Lang lang : kLangs) {
    const std::string_view to = p.in(lang);
    std::string& text = out[static_cast<std::size_t>(lang)];
    for (std::size_t i = 0; i < to.size(); ++i) {
      const std::size_t slot = i + 2 < to.size() && to[i] == '{' && to[i + 2] == '}'
                                   ? static_cast<std::size_t>(to[i + 1] - '0')
                                   : n;
      if (slot < n) {
        text += args[slot].in(lang);
        i += 2;
      } else {
        text += to[i];
      }
    }
  }
  return Said(std::move(out[0]), std::move(out[1]), std::move(out[2]));
}

}  // namespace frustum
