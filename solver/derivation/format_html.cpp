// Typeset HTML: every formula is an element carrying its LaTeX (data-tex) with the Unicode form
// inside as the fallback; the page's script typesets them with KaTeX, inlined from Debian's
// libjs-katex (script, style and fonts as data: URLs) so the page loads nothing from anywhere.
#include <fmt/format.h>

#include <fstream>
#include <sstream>

#include "solver/derivation/formats.hpp"
#include "solver/derivation/labels.hpp"
#include "solver/derivation/line_breaks.hpp"
#include "solver/derivation/svg.hpp"
#include "solver/util/base64.hpp"

namespace frustum {

namespace {

constexpr const char* kKatexDir = "/usr/share/javascript/katex/";

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// KaTeX's stylesheet with each font's woff2 only (every browser that runs KaTeX reads woff2), the
// other formats dropped; `font_url` gives the URL of a font file named in it.
template <typename FontUrl>
std::string katex_css(FontUrl font_url) {
  const std::string css = read_file(std::string(kKatexDir) + "katex.min.css");
  std::string out;
  std::size_t i = 0;
  while (true) {
    const std::size_t src = css.find("src:url(fonts/", i);
    if (src == std::string::npos) break;
    const std::size_t name_start = src + 14, name_end = css.find(')', name_start);
    const std::size_t decl_end = css.find_first_of(";}", name_end);
    if (name_end == std::string::npos || decl_end == std::string::npos) break;
    out += css.substr(i, src - i) + "src:url(" +
           font_url(css.substr(name_start, name_end - name_start)) + ") format('woff2')";
    i = decl_end;
  }
  return out + css.substr(i);
}

// A script element ends at the first "</script"; KaTeX's source has none, but be sure.
std::string katex_script() {
  std::string script = read_file(std::string(kKatexDir) + "katex.min.js");
  for (std::size_t at = 0; (at = script.find("</script", at)) != std::string::npos;)
    script.replace(at, 2, "<\\/");
  return script;
}

}  // namespace

std::string html_math_head() {
  const std::string js = katex_script();
  if (js.empty()) return {};  // no KaTeX here: the Unicode forms stay, still readable
  const std::string css = katex_css([](const std::string& font) {
    return "data:font/woff2;base64," + base64(read_file(std::string(kKatexDir) + "fonts/" + font));
  });
  return "<style>" + css + "</style>\n<script>" + js + "</script>\n";
}

std::vector<std::pair<std::string, std::string>> katex_files() {
  std::vector<std::pair<std::string, std::string>> files{
      {"katex.min.js", read_file(std::string(kKatexDir) + "katex.min.js")}};
  if (files[0].second.empty()) return {};
  std::vector<std::string> fonts;
  const std::string css = katex_css([&](const std::string& font) {
    fonts.push_back(font);
    return "fonts/" + font;
  });
  files.emplace_back("katex.min.css", css);
  for (const std::string& font : fonts)
    files.emplace_back("fonts/" + font, read_file(std::string(kKatexDir) + "fonts/" + font));
  return files;
}

std::string html_math_head_linked(const std::string& prefix) {
  return fmt::format(
      "<link rel=\"stylesheet\" href=\"{0}katex.min.css\">\n<script "
      "src=\"{0}katex.min.js\"></script>\n",
      svg_escape(prefix));
}

std::string html_math_script() {
  return R"JS(
(function () {
  if (typeof katex === 'undefined') return;
  document.querySelectorAll('[data-tex]').forEach(function (e) {
    try {
      katex.render(e.getAttribute('data-tex'), e, {displayMode: e.classList.contains('display'), throwOnError: true});
      e.setAttribute('data-typeset', 'yes');
    } catch (err) { e.setAttribute('data-typeset', 'error'); }
  });
  document.body.setAttribute('data-math', 'yes');
})();
)JS";
}

std::string html_math(const MathText& m, Lang lang, bool display, MathMarkup markup) {
  const MathText t = tr(m, lang);
  if (markup == MathMarkup::Delimited)
    return fmt::format("<span class=\"tex\" title=\"{}\">{}{}{}</span>", svg_escape(t.unicode),
                       display ? "\\[" : "\\(", svg_escape(t.latex), display ? "\\]" : "\\)");
  return fmt::format("<span class=\"tex{}\" data-tex=\"{}\" title=\"{}\">{}</span>",
                     display ? " display" : "", svg_escape(t.latex), svg_escape(t.unicode),
                     svg_escape(t.unicode));
}

std::string html_steps(const std::vector<Step>& steps, Lang lang, MathMarkup markup) {
  std::string out = "<ol class=\"steps\">\n";
  int number = 0;  // notes and warnings are not numbered, as in the text rendering
  for (const Step& s : steps) {
    const std::string cls = s.level == Step::Level::Warning ? " class=\"warning\""
                            : s.level == Step::Level::Note  ? " class=\"note-step\""
                                                           : fmt::format(" value=\"{}\"", ++number);
    out += fmt::format("<li{}><b>{}</b>", cls, svg_escape(s.title.in(lang)));
    // A long line is set as breakable inline math in display style, within the page.
    const auto block = [&](const MathText& m) {
      return long_math(m) ? html_math(tex("\\displaystyle ") + m, lang, false, markup)
                          : html_math(m, lang, true, markup);
    };
    for (const MathText* m : {&s.formula, &s.substitution})
      if (!m->empty()) out += "<div class=\"math\">" + block(*m) + "</div>";
    if (!s.result.empty())
      out += "<div class=\"math result\">" + block(tex("\\Rightarrow\\;") + s.result) + "</div>";
    if (!s.note.empty())
      out += fmt::format("<div class=\"note\">{}</div>", svg_escape(s.note.in(lang)));
    out += "</li>\n";
  }
  return out + "</ol>\n";
}

std::string html_figure(const Figure& figure, Lang lang, bool with_key) {
  // The picture as an image: its styles stay its own, whatever else the page shows.
  if (figure.svg.empty()) return {};
  const bool keyed = with_key && !figure.svg_with_key.empty();
  const std::string caption = !figure.student_answer ? ""
                              : keyed ? labels::in(labels::kYourAnswerDashedWithKey, lang)
                                      : labels::in(labels::kYourAnswerDashed, lang);
  return fmt::format(
      "<figure class=\"figure\"><img alt=\"{}\" src=\"data:image/svg+xml;base64,{}\">{}</figure>\n",
      svg_escape(labels::in(labels::kFigure, lang)),
      base64(keyed ? figure.svg_with_key : figure.svg),
      caption.empty() ? "" : "<figcaption>" + svg_escape(caption) + "</figcaption>");
}

std::string render_html(const SetResult& set, Lang lang, const Figures* figures) {
  const std::string title = set.title.empty() ? set.file : set.title.in(lang);
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, "
      "initial-scale=1\">\n<title>{}</title>\n"
      "<style>body {{ font-family: system-ui, sans-serif; max-width: 60rem; margin: 2rem auto; "
      "padding: 0 1rem; "
      "color: #1d232a; }} h2 {{ border-bottom: 1px solid #ccd; margin-top: 2rem; }} ol.steps li {{ "
      "margin: .6rem 0; }} "
      ".note {{ color: #555; font-size: .95em; }} .warning b {{ color: #a35200; }} li.note-step, "
      "li.warning {{ list-style: none; }} "
      ".error {{ color: #c4262e; font-family: monospace; }} table {{ border-collapse: collapse; }} "
      "td, th {{ border: 1px solid #ccd; padding: .3rem .6rem; text-align: left; "
      "}} figure.figure {{ margin: 1rem 0; }} figure.figure img {{ max-width: 100%; "
      "}}</style>\n{}</head>\n<body>\n<h1>{}</h1>\n",
      to_string(lang), svg_escape(title), html_math_head(), svg_escape(title));
  if (!set.source.empty())
    out += fmt::format("<p class=\"source\">{}: {}</p>\n",
                       svg_escape(labels::in(labels::kSource, lang)), svg_escape(set.source));
  for (const Diagnostic& d : set.errors)
    out += fmt::format("<p class=\"error\">{}</p>\n", svg_escape(d.format()));
  for (const ProblemResult& p : set.problems) {
    out += fmt::format("<section id=\"{}\">\n<h2>{} <small>({})</small></h2>\n", svg_escape(p.id),
                       svg_escape(p.id), svg_escape(p.kind));
    if (!p.text.empty()) out += fmt::format("<p>{}</p>\n", svg_escape(p.text.in(lang)));
    if (const Figure* f = find_figure(figures, p.id)) out += html_figure(*f, lang);
    if (p.error) {
      out += fmt::format("<p class=\"error\">{}</p>\n</section>\n", svg_escape(p.error->format()));
      continue;
    }
    out += html_steps(p.derivation.steps(), lang);
    out += fmt::format("<table>\n<tr><th>{}</th><th></th></tr>\n",
                       svg_escape(labels::in(labels::kAnswers, lang)));
    for (const std::string& name : p.ask)
      if (const Value* v = p.answers.find(name))
        out += fmt::format("<tr><td><code>{}</code></td><td>{}</td></tr>\n", svg_escape(name),
                           html_math(v->shown(), lang, false));
    out += "</table>\n</section>\n";
  }
  return out + "<script>" + html_math_script() + "</script>\n</body>\n</html>\n";
}

}  // namespace frustum
