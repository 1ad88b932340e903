#include <fmt/format.h>

#include "solver/derivation/formats.hpp"
#include "solver/derivation/labels.hpp"

namespace frustum {

std::string render_steps_markdown(const std::vector<Step>& steps, Lang lang) {
  std::string out;
  int number = 0;
  for (const Step& s : steps) {
    const std::string title = s.title.in(lang), note = s.note.in(lang);
    if (s.level == Step::Level::Warning)
      out += fmt::format("> **{} — {}.** {}\n\n", labels::in(labels::kWarning, lang), title, note);
    else if (s.level == Step::Level::Note)
      out += fmt::format("> **{}.** {}\n\n", title, note);
    else
      out += fmt::format("{}. **{}**\n\n", ++number, title);
    if (!s.formula.empty()) out += "   $$" + tr(s.formula, lang).latex + "$$\n\n";
    if (!s.substitution.empty()) out += "   $$" + tr(s.substitution, lang).latex + "$$\n\n";
    if (!s.result.empty()) out += "   $$\\Rightarrow\\; " + tr(s.result, lang).latex + "$$\n\n";
    if (!s.note.empty() && s.level == Step::Level::Info) out += "   " + note + "\n\n";
  }
  return out;
}

std::string render_problem_markdown(const ProblemResult& p, Lang lang) {
  std::string out = fmt::format("## {} (`{}`)\n\n", p.id, p.kind);
  if (!p.text.empty()) out += p.text.in(lang) + "\n\n";
  if (p.error)
    return out +
           fmt::format("**{}:** `{}`\n\n", labels::in(labels::kError, lang), p.error->format());
  out += render_steps_markdown(p.derivation.steps(), lang);
  out += fmt::format("**{}**\n\n| {} | {} |\n| --- | --- |\n", labels::in(labels::kAnswers, lang),
                     labels::in(labels::kAnswer, lang), labels::in(labels::kValue, lang));
  for (const std::string& name : p.ask)
    if (const Value* v = p.answers.find(name))
      out += fmt::format("| `{}` | ${}$ |\n", name, tr(v->shown(), lang).latex);
  return out + "\n";
}

std::string render_markdown(const SetResult& set, Lang lang) {
  std::string out = fmt::format("# {}\n\n", set.title.empty() ? set.file : set.title.in(lang));
  if (!set.source.empty())
    out += fmt::format("*{}: {}*\n\n", labels::in(labels::kSource, lang), set.source);
  for (const Diagnostic& d : set.errors)
    out += fmt::format("**{}:** `{}`\n\n", labels::in(labels::kError, lang), d.format());
  for (const ProblemResult& p : set.problems) out += render_problem_markdown(p, lang);
  return out;
}

}  // namespace frustum
