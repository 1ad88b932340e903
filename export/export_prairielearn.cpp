#include "export/export_prairielearn.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "batch/file_names.hpp"
#include "export/answer_caption.hpp"
#include "export/export_tolerance.hpp"
#include "export/quiz_items.hpp"
#include "export/xml_text.hpp"
#include "grader/answer_type.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/problem_figure.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/variants.hpp"

namespace frustum {

using json = nlohmann::ordered_json;
using namespace quiz_phrases;

namespace {

// What to type, for an answer entered as text.
// Under a text input: exact forms, and the window of each decimal.
constexpr Phrase kInfinityWrittenInf{
    "+∞, the depth of a pixel no polygon covers, is written inf (or 1e30)",
    "+∞ (どの多角形にも覆われない画素の奥行き) は inf (または 1e30) と書く",
    "+∞ — глубину пикселя, не покрытого ни одним многоугольником, — пишут inf (или 1e30)"};
constexpr Phrase kExactFormsOneWindow{
    "Exact forms such as 15/2 or sqrt(3)/2 are accepted; a decimal is right within {0} of the "
    "exact value.",
    "15/2 や sqrt(3)/2 のような厳密な形で答えてよい. 小数は厳密な値との差が {0} 以内なら正解.",
    "Можно писать точные значения, например 15/2 или sqrt(3)/2; десятичная дробь верна, если "
    "отличается от точного значения не более чем на {0}."};
constexpr Phrase kExactFormsWindows{
    "Exact forms such as 15/2 or sqrt(3)/2 are accepted; decimals are right within {0} of the "
    "exact values, in order.",
    "15/2 や sqrt(3)/2 のような厳密な形で答えてよい. 小数は厳密な値との差が順に {0} "
    "以内なら正解.",
    "Можно писать точные значения, например 15/2 или sqrt(3)/2; десятичные дроби верны, если "
    "отличаются от точных значений не более чем на {0} (по порядку)."};

std::uint64_t fnv1a(const std::string& s, std::uint64_t h = 1469598103934665603ull) {
  for (const unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

// A UUID (version 4 layout) that depends only on the set's title and the problem id, so a
// re-export keeps each question's identity (and its students' data) in PrairieLearn.
std::string stable_uuid(const std::string& title, const std::string& id) {
  const std::uint64_t a = fnv1a("frustum-prairielearn/1\x1f" + title + "\x1f" + id);
  const std::uint64_t b = fnv1a(id + "\x1f" + title, a);
  const std::string hex = fmt::format("{:016x}{:016x}", a, b);
  return fmt::format("{}-{}-4{}-{:x}{}-{}", hex.substr(0, 8), hex.substr(8, 4), hex.substr(13, 3),
                     8 | (std::stoi(hex.substr(16, 1), nullptr, 16) & 3), hex.substr(17, 3),
                     hex.substr(20, 12));
}

// Which statements are true, as checkboxes in the set's order, each numbered as in the set
// (frustum-pl-grade reads the ticked ones back by these numbers), and a last, unnumbered one
// for "none is true": pl-checkbox refuses to render without a right option (and min-correct
// must be at least 1), so a set whose statements are all false still has one to tick.
std::string checkbox_html(const std::string& name, const ProblemSpec& p, Lang lang) {
  const ProblemResult solved = solve_problem(p, "", false);
  const Value* key = solved.error ? nullptr : solved.answers.find(name);
  const QuizField f = key ? statement_checkboxes(p, *key, lang) : QuizField{};
  const bool none_true = std::find(f.right.begin(), f.right.end(), true) == f.right.end();
  std::string s = fmt::format(
      "<p>{}:</p>\n<pl-checkbox answers-name=\"{}\" fixed-order=\"true\" "
      "hide-letter-keys=\"true\">\n",
      xml_escape(answer_caption(p, name, lang)), name);
  for (std::size_t i = 0; i < f.choices.size(); ++i)
    s += fmt::format("  <pl-answer correct=\"{}\">{}. {}</pl-answer>\n",
                     f.right[i] ? "true" : "false", i + 1, xml_escape(f.choices[i]));
  s += fmt::format("  <pl-answer correct=\"{}\">{}</pl-answer>\n", none_true ? "true" : "false",
                   xml_escape(kNoStatementIsTrue.in(lang)));
  return s + "</pl-checkbox>";
}

// Numbers, vectors, matrices and point lists are typed as text that Frustum reads, so exact
// forms (15/2, sqrt(14)/14) and `none` are accepted, which pl-number-input and pl-matrix-input
// refuse; the window a decimal must fall in is stated under the input (params.help), the same
// the grader uses. The answer panel shows the key (correct_answers, set by server.py).
// The student reads each input by its caption (answer_caption.hpp) and each word in their
// language (the grader reads 表 as back); answers-name and params stay keyed by the name.
std::string input_html(const AnswerSpec& spec, const ProblemSpec& p, Lang lang) {
  const std::string name = xml_escape(spec.name);
  const std::string caption = xml_escape(answer_caption(p, spec.name, lang));
  const std::string input = prairielearn_input(spec);
  if (input == "checkbox") return checkbox_html(name, p, lang);
  if (input == "choice") {
    std::string s = fmt::format(
        "<p>{}:</p>\n<pl-multiple-choice answers-name=\"{}\" inline=\"true\">\n", caption, name);
    for (const std::string& w : answer_type(spec.kind).choices(spec))
      s += fmt::format("  <pl-answer correct=\"{{{{params.correct.{}.{}}}}}\">{}</pl-answer>\n",
                       name, w, xml_escape(words::vocabulary_word(w).in(lang)));
    return s + "</pl-multiple-choice>";
  }
  return fmt::format(
      "<pl-string-input answers-name=\"{0}\" label=\"{2} =\" placeholder=\"{1}\" size=\"40\" "
      "remove-leading-trailing=\"true\" show-help-text=\"false\"></pl-string-input>\n"
      "<pl-question-panel>{{{{#params.help.{0}}}}}<p class=\"small\">{{{{params.help.{0}}}}}</p>"
      "{{{{/params.help.{0}}}}}</pl-question-panel>",
      name, xml_escape(answer_type(spec.kind).typed_hint->in(lang)), caption);
}

// The key as a student types it (`[1, 1, -1]`, `sqrt(14)/14`, `none`), for the answer panel.
std::string typed_key(const Value& v) {
  std::string text = emit_flow(answer_node(v));
  if (text.size() >= 2 && text.front() == '"' && text.back() == '"')
    text = text.substr(1, text.size() - 2);
  return text;
}

// What the statement under a text input says: exact forms, and the window of each decimal.
std::string help_text(const ProblemSpec& p, const Answers& key, const AnswerSpec& spec,
                      const Value& expected, Lang lang) {
  if (expected.numbers.empty() || !answer_type(spec.kind).componentwise) return {};
  // A z-buffer's background depth is +∞ (1e30 in the key), which Frustum, grading this input,
  // reads written inf: said under the input.
  const bool infinity =
      spec.infinity != 0 && std::find(expected.numbers.begin(), expected.numbers.end(),
                                      spec.infinity) != expected.numbers.end();
  const std::string why = infinity ? fmt::format(" {}.", kInfinityWrittenInf.in(lang)) : "";
  const std::vector<double> windows = accepted_windows(p, key, spec.name, expected);
  std::vector<std::string> items;
  for (const double w : windows) items.push_back(fmt::format("±{:.3g}", w));
  bool same = true;
  for (const std::string& i : items) same = same && i == items.front();
  if (same) return say(kExactFormsOneWindow, items.front()).in(lang) + why;
  std::string list;
  for (const std::string& i : items) list += (list.empty() ? "" : ", ") + i;
  return say(kExactFormsWindows, list).in(lang) + why;
}

// One problem of a variant as a complete one-problem set (the set's other fields kept).
std::string one_problem_set(const YAML::Node& root, const ProblemSet& variant, std::size_t index) {
  YAML::Node copy = YAML::Clone(root);
  YAML::Node only(YAML::NodeType::Sequence);
  only.push_back(YAML::Clone(root["problems"][index]));
  copy["problems"] = only;
  ProblemSet one = variant;
  one.problems = {variant.problems[index]};
  return emit_variant_set(copy, one, "");
}

}  // namespace

std::string prairielearn_input(const AnswerSpec& spec) {
  switch (answer_type(spec.kind).input) {
    case TypedInput::Choice:
      return "choice";
    case TypedInput::Checkboxes:
      return "checkbox";
    case TypedInput::Text:
      break;
  }
  return "string";
}

std::map<std::string, std::map<std::string, std::string>> export_prairielearn(
    const YAML::Node& root, const ProblemSet& set, const std::vector<ProblemSet>& variants,
    const std::string& stem, const PrairieLearnOptions& options) {
  std::map<std::string, std::map<std::string, std::string>> out;
  // The uuid keeps to the set's own title, so a question keeps its id in every language.
  const std::string title = set.title.empty() ? stem : set.title.text;
  const std::string shown = set.title.empty() ? stem : set.title.in(options.lang);
  // One directory per question, never shared: the batch's injective encoding of names (ids
  // "q 1", "q/1", "q_1" and "Q_1" are four questions, also on a file system blind to case).
  std::vector<std::string> wanted;
  for (const ProblemSpec& p : set.problems) wanted.push_back(stem + "-" + p.id);
  const std::vector<std::string> dirs = unique_file_names(wanted);
  for (std::size_t i = 0; i < set.problems.size(); ++i) {
    const ProblemSpec& p = set.problems[i];
    if (!p.info) continue;
    json info;
    info["uuid"] = stable_uuid(title, p.id);
    info["title"] = shown + ": " + p.id;
    info["topic"] = shown;
    info["tags"] = json::array({"frustum", p.kind});
    info["type"] = "v3";
    info["singleVariant"] = variants.size() == 1;
    info["gradingMethod"] = "External";
    info["externalGradingOptions"] = json{{"enabled", true},
                                          {"image", options.image},
                                          {"entrypoint", options.entrypoint},
                                          {"timeout", options.timeout}};
    // The variants Frustum drew: what the page shows, the set the grader grades against (in
    // the export's language), which words are right (pl-multiple-choice) and the key with its
    // derivation for the answer panel (correct_answers: shown when the assessment allows).
    json drawn = json::array();
    bool question_figure = false, answer_figure = false;  // where the variants' pictures go
    for (const ProblemSet& v : variants) {
      if (i >= v.problems.size() || v.problems[i].error) continue;
      const ProblemSpec& vp = v.problems[i];
      const ProblemResult r = solve_problem(vp, v.file, true);
      if (r.error) continue;
      json params;
      params["problem"] = vp.id;
      params["lang"] = std::string(to_string(options.lang));
      params["text"] = question_text(v, vp, options.lang);
      std::string given;
      for (const std::string& line : given_lines(vp)) given += line + "\n";
      params["given"] = given;
      params["set"] = one_problem_set(root, v, i);
      json inputs, correct, help = json::object(), key = json::object();
      for (const std::string& name : vp.ask) {
        const AnswerSpec* spec = vp.info->answer(name);
        const Value* expected = r.answers.find(name);
        if (!spec || !expected) continue;
        inputs[name] = prairielearn_input(*spec);
        if (inputs[name] == "string") {
          key[name] = typed_key(*expected);
          const std::string h = help_text(vp, r.answers, *spec, *expected, options.lang);
          if (!h.empty()) help[name] = h;
        }
        if (inputs[name] != "choice") continue;
        const AnswerType& type = answer_type(spec->kind);
        const std::string right = type.chosen(*expected);
        for (const std::string& w : type.choices(*spec))
          correct[name][w] = w == right ? "true" : "false";
      }
      params["inputs"] = inputs;
      params["correct"] = correct.is_null() ? json::object() : correct;
      params["help"] = help;
      key["frustum_solution"] =
          html_steps(r.derivation.steps(), options.lang, MathMarkup::Delimited);
      // The variant's picture, as an image of its own SVG (not a pl-figure: a question's files
      // can be fetched before the answer panel is shown). One that shows answers (the painter's
      // order, the hidden edges) goes with the key into the answer panel; one of the givens only
      // (the window and segment, the triangle and pixel) into the question.
      if (const std::optional<Figure> f = problem_figure(vp, options.lang)) {
        (f->shows_answers ? key : params)["frustum_figure"] = html_figure(*f, options.lang);
        (f->shows_answers ? answer_figure : question_figure) = true;
      }
      drawn.push_back(json{{"params", params}, {"correct_answers", key}});
    }
    if (drawn.empty()) continue;
    std::string html =
        "<pl-question-panel>\n  <p>{{params.text}}</p>\n  "
        "<pre>{{params.given}}</pre>\n" +
        std::string(question_figure ? "  {{{params.frustum_figure}}}\n" : "") +
        "</pl-question-panel>\n\n";
    for (const std::string& name : p.ask)
      if (const AnswerSpec* spec = p.info->answer(name))
        html += input_html(*spec, p, options.lang) + "\n\n";
    // Frustum's feedback as HTML (pl-external-grader-results shows the score; its own fields
    // are plain text in <pre>), and the derivation once the answer panel is shown.
    html +=
        "<pl-submission-panel>\n  "
        "<pl-external-grader-results></pl-external-grader-results>\n"
        "  <div class=\"frustum-feedback\">{{{feedback.results.frustum_html}}}</div>\n"
        "</pl-submission-panel>\n\n"
        "<pl-answer-panel>\n  <div class=\"frustum-solution\">"
        "{{{correct_answers.frustum_solution}}}</div>\n" +
        std::string(answer_figure ? "  {{{correct_answers.frustum_figure}}}\n" : "") +
        "</pl-answer-panel>\n";
    std::string server =
        "# Generated by `frustum export prairielearn`: the variants below were drawn and solved "
        "by\n"
        "# Frustum; grading runs Frustum itself in the external grader (frustum-pl-grade).\n"
        "import json\nimport random\n\n"
        "VARIANTS = json.loads(" +
        json(drawn.dump()).dump() +  // a JSON string literal is a Python string literal
        ")\n\n\n"
        "def generate(data):\n"
        "    # PrairieLearn seeds `random` with the variant's seed, so a variant keeps its "
        "problem.\n"
        "    variant = VARIANTS[random.randrange(len(VARIANTS))]\n"
        "    data[\"params\"].update(variant[\"params\"])\n"
        "    # The key, for the answer panel: shown when the assessment's policy allows.\n"
        "    data[\"correct_answers\"].update(variant[\"correct_answers\"])\n";
    auto& files = out[dirs[i]];
    files["info.json"] = info.dump(2) + "\n";
    files["question.html"] = html;
    files["server.py"] = server;
  }
  return out;
}

}  // namespace frustum
