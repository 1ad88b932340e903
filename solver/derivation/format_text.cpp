#include <fmt/format.h>

#include "solver/derivation/formats.hpp"
#include "solver/derivation/labels.hpp"
#include "solver/derivation/problem_result.hpp"

namespace frustum {

namespace {

struct Ansi {
  bool on;
  std::string bold() const { return on ? "\033[1m" : ""; }
  std::string dim() const { return on ? "\033[2m" : ""; }
  std::string yellow() const { return on ? "\033[33m" : ""; }
  std::string red() const { return on ? "\033[31m" : ""; }
  std::string cyan() const { return on ? "\033[36m" : ""; }
  std::string reset() const { return on ? "\033[0m" : ""; }
};

// A note's further lines under its first: a line that brings its own indentation (a trace
// under its heading) keeps it; any other is indented as the first.
std::string indent_lines(const std::string& text, const std::string& indent) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '\n' && i + 1 < text.size() && text[i + 1] != ' ' && text[i + 1] != '\n')
      out += indent;
  }
  return out;
}

}  // namespace

std::string render_steps_text(const std::vector<Step>& steps, const TextStyle& style,
                              const std::string& indent) {
  const Ansi a{style.color};
  std::string out;
  int number = 0;
  for (const Step& s : steps) {
    const std::string body = indent + "    ";
    const std::string title = s.title.in(style.lang), note = s.note.in(style.lang);
    if (s.level == Step::Level::Warning) {
      out += fmt::format("{}{}⚠ {}{}\n", indent, a.yellow(), title, a.reset());
    } else if (s.level == Step::Level::Note) {
      out += fmt::format("{}{}• {}{}\n", indent, a.cyan(), title, a.reset());
    } else {
      out += fmt::format("{}{}{:>2}. {}{}\n", indent, a.bold(), ++number, title, a.reset());
    }
    if (!s.formula.empty()) out += body + tr(s.formula, style.lang).unicode + "\n";
    if (!s.substitution.empty()) out += body + tr(s.substitution, style.lang).unicode + "\n";
    if (!s.result.empty())
      out += indent + "  ⇒ " + a.bold() + tr(s.result, style.lang).unicode + a.reset() + "\n";
    if (!s.note.empty()) out += body + a.dim() + indent_lines(note, body) + a.reset() + "\n";
  }
  return out;
}

std::string render_problem_text(const ProblemResult& p, const TextStyle& style) {
  const Ansi a{style.color};
  std::string out = fmt::format("{}━━ {} · {} ━━{}\n", a.bold(), p.id, p.kind, a.reset());
  if (!p.text.empty()) out += p.text.in(style.lang) + "\n";
  if (p.error) {
    out += fmt::format("  {}{}:{} {}\n", a.red(), labels::in(labels::kErrorLower, style.lang),
                       a.reset(), p.error->format());
    return out;
  }
  out += render_steps_text(p.derivation.steps(), style);
  out += fmt::format("  {}{}{}\n", a.bold(), labels::in(labels::kAnswers, style.lang), a.reset());
  for (const std::string& name : p.ask) {
    if (const Value* v = p.answers.find(name))
      out += fmt::format("    {} = {}\n", name, tr(v->shown(), style.lang).unicode);
  }
  return out;
}

std::string render_text(const SetResult& set, const TextStyle& style) {
  const Ansi a{style.color};
  std::string out;
  if (!set.title.empty())
    out += fmt::format("{}{}{}\n", a.bold(), set.title.in(style.lang), a.reset());
  if (!set.source.empty())
    out += fmt::format("{}: {}\n", labels::in(labels::kSource, style.lang), set.source);
  if (!set.title.empty() || !set.source.empty()) out += "\n";
  for (const Diagnostic& d : set.errors)
    out += fmt::format("{}error:{} {}\n", a.red(), a.reset(), d.format());
  for (const ProblemResult& p : set.problems) out += render_problem_text(p, style) + "\n";
  return out;
}

}  // namespace frustum
