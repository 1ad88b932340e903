// A derivation recorded as data: a list of steps a student can follow, each with its title,
// the formula, the formula with the numbers substituted, and the result. Formatters
// (formats.hpp: render_text, render_markdown, render_json, …) decide how it looks.
#pragma once

#include <string>
#include <vector>

#include "solver/derivation/i18n.hpp"
#include "solver/derivation/math_text.hpp"
#include "solver/util/said.hpp"

namespace frustum {

struct Step {
  enum class Level { Info, Note, Warning };

  Said title;             // "Plane through A", in each language
  MathText formula;       // n·(p − A) = 0
  MathText substitution;  // (1/√3, 1/√3, −1/√3)·(x, y, z − 6) = 0
  MathText result;        // x + y − z = −6
  Said note;              // prose: a convention, a seed's slip, a warning
  Level level = Level::Info;
  std::vector<std::string> answers;  // the answers this step produces ("plane")

  // Marks this step as producing the named answer and returns it, so a kind adds a step and
  // says what it yields in one statement: `steps->add(...).yields("plane");`.
  Step& yields(std::string answer);
};

class Derivation {
 public:
  Step& add(Said title, MathText formula = {}, MathText substitution = {}, MathText result = {});
  Step& note(Said title, Said text);
  Step& warn(Said title, Said text);
  // Marks the most recent step, whoever added it (a helper, possibly ending on its warning;
  // a loop), as producing the named answer. A step a kind adds itself says it with Step::yields.
  void yields(const std::string& answer);

  const std::vector<Step>& steps() const { return steps_; }
  bool empty() const { return steps_.empty(); }
  // Steps up to and including the one that yields `answer` (all steps if none does), so a
  // wrong answer can be shown with the derivation that leads to it.
  std::vector<Step> steps_for(const std::string& answer) const;
  bool has_warnings() const;

 private:
  std::vector<Step> steps_;
};

}  // namespace frustum
