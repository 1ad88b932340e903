#include "solver/derivation/derivation.hpp"

#include <algorithm>

namespace frustum {

Step& Step::yields(std::string answer) {
  answers.push_back(std::move(answer));
  return *this;
}

Step& Derivation::add(Said title, MathText formula, MathText substitution, MathText result) {
  Step s;
  s.title = std::move(title);
  s.formula = std::move(formula);
  s.substitution = std::move(substitution);
  s.result = std::move(result);
  steps_.push_back(std::move(s));
  return steps_.back();
}

Step& Derivation::note(Said title, Said text) {
  Step& s = add(std::move(title));
  s.note = std::move(text);
  s.level = Step::Level::Note;
  return s;
}

Step& Derivation::warn(Said title, Said text) {
  Step& s = add(std::move(title));
  s.note = std::move(text);
  s.level = Step::Level::Warning;
  return s;
}

void Derivation::yields(const std::string& answer) {
  if (!steps_.empty()) steps_.back().yields(answer);
}

std::vector<Step> Derivation::steps_for(const std::string& answer) const {
  std::vector<Step> out;
  for (const Step& s : steps_) {
    out.push_back(s);
    if (std::find(s.answers.begin(), s.answers.end(), answer) != s.answers.end()) return out;
  }
  return out;
}

bool Derivation::has_warnings() const {
  return std::any_of(steps_.begin(), steps_.end(),
                     [](const Step& s) { return s.level == Step::Level::Warning; });
}

}  // namespace frustum
