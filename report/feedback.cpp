#include "report/feedback.hpp"

#include <fmt/format.h>

#include "grader/visible_text.hpp"
#include "report/report.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/derivation/svg.hpp"
#include "solver/problem/problem_figure.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

using namespace report_phrases;

namespace {

constexpr Phrase kAnswer{"Answer", "解答", "Ответ"};
constexpr Phrase kVerdict{"Verdict", "判定", "Оценка"};
constexpr Phrase kScore{"Score", "得点", "Баллы"};
constexpr Phrase kYouWrote{"You wrote", "あなたの解答", "Ваш ответ"};
constexpr Phrase kExpected{"Expected", "正解", "Верный ответ"};
constexpr Phrase kCreditCarriedForward{"credit carried forward from your earlier answer",
                                       "前の解答からの継続点 (誤りの持ち越し)",
                                       "баллы перенесены с вашего предыдущего ответа"};

// Markdown table cells: a pipe would end the cell (markdown_escape escapes it).
std::string cell(const std::string& s) { return markdown_escape(s); }

// HTML text and attribute values: the SVG writer's escaping (&, <, >, ", ') serves both, after
// bytes that are not UTF-8 and control characters are made visible.
std::string html_escape(std::string_view s) { return svg_escape(visible_text(s, Breaks::Kept)); }

std::string verdict_word(Verdict v, Lang lang) { return std::string(verdict_phrase(v).in(lang)); }

// The answer as the student wrote it (their decimals, their form), never our exact reading of
// it: 0.948683 stays 0.948683 beside the key.
std::string got_shown(const AnswerGrade& a) {
  return a.verdict == Verdict::Missing ? "—" : a.got_text;
}

const char* kStyle = R"CSS(
body { font-family: system-ui, "Noto Sans CJK JP", sans-serif; max-width: 60rem; margin: 2rem auto; padding: 0 1rem; color: #1d232a; }
figure.figure { margin: .8rem 0; } figure.figure img { max-width: 100%; }
h1 { font-size: 1.5rem; } h2 { font-size: 1.2rem; margin-top: 2rem; border-bottom: 1px solid #ccd; }
.total { font-size: 1.2rem; font-weight: bold; }
table { border-collapse: collapse; width: 100%; margin: .5rem 0; }
th, td { border: 1px solid #ccd; padding: .3rem .5rem; text-align: left; vertical-align: top; }
.math { font-family: "STIX Two Math", "Cambria Math", "Latin Modern Math", serif; font-size: 1.05em; }
.verdict { font-weight: bold; }
tr.correct .verdict { color: #18794e; } tr.partial .verdict { color: #a35200; }
tr.incorrect .verdict, tr.unparseable .verdict { color: #c4262e; } tr.missing .verdict { color: #6b7280; }
.mistake { background: #fff4e5; border-left: 4px solid #a35200; padding: .3rem .6rem; margin: .3rem 0; }
.feedback { margin: .3rem 0; }
ol.steps li { margin: .4rem 0; } .note { color: #555; font-size: .95em; } .warning { color: #a35200; }
.error { color: #c4262e; font-family: monospace; }
)CSS";

// Counts the verdicts shown and writes the summary line in the page's language (each row's
// data-word): the page works without it, and a browser test sees that the page was rendered
// and its script ran.
const char* kScript = R"JS(
(function () {
  var rows = document.querySelectorAll('tr[data-verdict]');
  var counts = {};
  rows.forEach(function (r) { var v = r.getAttribute('data-word'); counts[v] = (counts[v] || 0) + 1; });
  var parts = Object.keys(counts).sort().map(function (k) { return k + ': ' + counts[k]; });
  document.getElementById('summary').textContent = parts.join(', ');
  document.body.setAttribute('data-rendered', 'yes');
})();
)JS";

}  // namespace

std::string markdown_escape(std::string_view raw) {
  const std::string text = visible_text(raw, Breaks::Kept);
  std::string out;
  // At the start of a line these would make a heading, a list or a quote.
  if (!text.empty() && std::string_view("#-+>").find(text[0]) != std::string_view::npos)
    out += '\\';
  out.reserve(out.size() + text.size() + text.size() / 8);
  for (const char c : text) {
    switch (c) {
      case '\n':
      case '\t':
        out += ' ';
        break;
      case '<':
      case '>':
      case '&':
        out += xml_entity(c);
        break;
      case '\\':
      case '`':
      case '*':
      case '_':
      case '[':
      case ']':
      case '|':
        out += '\\';
        out += c;
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string markdown_code(std::string_view raw) {
  std::string out;
  for (const char c : visible_text(raw, Breaks::Kept)) {
    if (c == '`')
      out += "ʼ";
    else if (c == '\n' || c == '\t')
      out += ' ';
    else
      out += c;
  }
  return out;
}

std::string render_problem_feedback_markdown(const ProblemGrade& p, Lang lang) {
  std::string out;
  if (p.error)
    return out + fmt::format("**{}:** `{}`\n\n", kError.in(lang), markdown_code(p.error->format()));
  out +=
      fmt::format("| {} | {} | {} | {} | {} |\n| --- | --- | --- | --- | --- |\n", kAnswer.in(lang),
                  kVerdict.in(lang), kScore.in(lang), kYouWrote.in(lang), kExpected.in(lang));
  for (const AnswerGrade& a : p.answers)
    out += fmt::format("| `{}` | {} | {} / {} | {} | {} |\n", markdown_code(a.name),
                       verdict_word(a.verdict, lang), score_text(a.score), score_text(a.max_score),
                       cell(got_shown(a)), cell(tr(a.expected.shown(), lang).unicode));
  out += "\n";
  for (const AnswerGrade& a : p.answers) {
    if (a.verdict == Verdict::Correct) continue;
    if (a.misconception.empty() && a.feedback.empty() && a.derivation.empty()) continue;
    out += fmt::format("**`{}`**", markdown_code(a.name));
    if (a.carried_forward) out += fmt::format(" — {}", kCreditCarriedForward.in(lang));
    out += "\n\n";
    if (!a.misconception.empty())
      out += fmt::format("> **{}:** {}\n\n", kCommonMistake.in(lang), misconception_text(a, lang));
    if (!a.feedback.empty()) out += markdown_escape(a.feedback.in(lang)) + "\n\n";
    if (!a.derivation.empty())
      out += fmt::format("*{}:*\n\n", kHowToGetIt.in(lang)) +
             render_steps_markdown(a.derivation, lang);
  }
  return out;
}

std::vector<std::string> problem_feedback_markdown(const GradeReport& r, Lang lang) {
  std::vector<std::string> out;
  for (const ProblemGrade& p : r.problems) out.push_back(render_problem_feedback_markdown(p, lang));
  return out;
}

std::string render_feedback_markdown(const GradeReport& r, Lang lang) {
  return render_feedback_markdown(r, lang, problem_feedback_markdown(r, lang));
}

std::string render_feedback_markdown(const GradeReport& r, Lang lang,
                                     const std::vector<std::string>& problem_markdown) {
  std::string out =
      fmt::format("# {} {}\n\n**{}: {} / {}**\n\n", kStudent.in(lang),
                  r.student.empty() ? std::string(kUnnamed.in(lang)) : markdown_escape(r.student),
                  kScore.in(lang), score_text(r.score), score_text(r.max_score));
  for (const Diagnostic& d : r.errors)
    out += fmt::format("- {}: `{}`\n", kWarning.in(lang), markdown_code(d.format()));
  if (!r.errors.empty()) out += "\n";
  for (std::size_t i = 0; i < r.problems.size(); ++i) {
    const ProblemGrade& p = r.problems[i];
    out += fmt::format("## {} — {} / {}\n\n", markdown_escape(p.id), score_text(p.score),
                       score_text(p.max_score));
    out += problem_markdown.at(i);
  }
  return out;
}

Figures student_figures(const ProblemSet& set, const GradeReport& r, Lang lang) {
  std::map<std::string, AnswerPair> answers;
  for (const ProblemGrade& p : r.problems)
    for (const AnswerGrade& a : p.answers) {
      AnswerPair& pair = answers[p.id];
      if (a.got) pair.student.set(a.name, *a.got);
      pair.key.set(a.name, a.expected);
    }
  return feedback_figures(set, lang, answers);
}

std::string render_problem_feedback_html(const ProblemGrade& p, Lang lang, bool with_key,
                                         MathMarkup markup, const Figure* figure) {
  std::string out = fmt::format(
      "<section class=\"problem\" id=\"problem-{}\">\n<h2>{} <small>({})</small> — {} / "
      "{}</h2>\n",
      html_escape(p.id), html_escape(p.id), html_escape(p.kind), score_text(p.score),
      score_text(p.max_score));
  if (figure && (with_key || !figure->shows_answers)) out += html_figure(*figure, lang, with_key);
  if (p.error)
    return out +
           fmt::format("<p class=\"error\">{}</p>\n</section>\n", html_escape(p.error->format()));
  out += fmt::format("<table>\n<tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th>{}</tr>\n",
                     html_escape(kAnswer.in(lang)), html_escape(kVerdict.in(lang)),
                     html_escape(kScore.in(lang)), html_escape(kYouWrote.in(lang)),
                     with_key ? "<th>" + html_escape(kExpected.in(lang)) + "</th>" : "");
  for (const AnswerGrade& a : p.answers) {
    const std::string_view v = to_string(a.verdict);
    out += fmt::format(
        "<tr class=\"{}\" data-verdict=\"{}\" data-word=\"{}\"><td><code>{}</code></td><td "
        "class=\"verdict\">{}</td><td>{} / {}</td><td class=\"math{}\">{}</td>{}</tr>\n",
        v, v, html_escape(verdict_word(a.verdict, lang)), html_escape(a.name),
        html_escape(verdict_word(a.verdict, lang)), score_text(a.score), score_text(a.max_score),
        // What a student wrote is never read as a formula by the host's MathJax.
        markup == MathMarkup::Delimited ? " mathjax_ignore" : "", html_escape(got_shown(a)),
        with_key
            ? "<td class=\"math\">" + html_math(a.expected.shown(), lang, false, markup) + "</td>"
            : "");
  }
  out += "</table>\n";
  for (const AnswerGrade& a : p.answers) {
    if (a.verdict == Verdict::Correct) continue;
    const bool steps = with_key && !a.derivation.empty();
    if (a.misconception.empty() && a.feedback.empty() && !steps) continue;
    out += fmt::format(
        "<div class=\"answer-feedback\" id=\"feedback-{}-{}\">\n<h3><code>{}</code>{}</h3>\n",
        html_escape(p.id), html_escape(a.name), html_escape(a.name),
        a.carried_forward ? " — " + html_escape(kCreditCarriedForward.in(lang)) : "");
    if (!a.misconception.empty())
      out += fmt::format("<p class=\"mistake\"><b>{}:</b> {}</p>\n",
                         html_escape(kCommonMistake.in(lang)),
                         html_escape(misconception_text(a, lang)));
    if (!a.feedback.empty())
      out += fmt::format("<p class=\"feedback\">{}</p>\n", html_escape(a.feedback.in(lang)));
    if (steps)
      out += fmt::format("<details open><summary>{}</summary>\n{}</details>\n",
                         html_escape(kHowToGetIt.in(lang)), html_steps(a.derivation, lang, markup));
    out += "</div>\n";
  }
  return out + "</section>\n";
}

std::string render_feedback_html(const GradeReport& r, Lang lang) {
  return render_feedback_html(r, lang, html_math_head());
}

std::string render_feedback_html(const GradeReport& r, Lang lang, const std::string& math_head) {
  return render_feedback_html(r, lang, math_head, nullptr);
}

std::string render_feedback_html(const GradeReport& r, Lang lang, const std::string& math_head,
                                 const Figures* figures) {
  const std::string student = r.student.empty() ? std::string(kUnnamed.in(lang)) : r.student;
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>Frustum — {}</title>\n<style>{}</style>\n{}</head>\n<body data-rendered=\"no\">\n",
      to_string(lang), html_escape(student), kStyle, math_head);
  out += fmt::format(
      "<h1>{} {}</h1>\n<p class=\"total\" id=\"total\">{}: {} / {}</p>\n<p id=\"summary\"></p>\n",
      html_escape(kStudent.in(lang)), html_escape(student), html_escape(kScore.in(lang)),
      score_text(r.score), score_text(r.max_score));
  for (const Diagnostic& d : r.errors)
    out += fmt::format("<p class=\"error\">{}: {}</p>\n", html_escape(kWarning.in(lang)),
                       html_escape(d.format()));
  for (const ProblemGrade& p : r.problems)
    out +=
        render_problem_feedback_html(p, lang, true, MathMarkup::KaTeX, find_figure(figures, p.id));
  out += fmt::format("<script>{}{}</script>\n</body>\n</html>\n", kScript, html_math_script());
  return out;
}

}  // namespace frustum
