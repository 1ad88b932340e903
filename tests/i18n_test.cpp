// Derivations and feedback in Japanese and Russian: no English word reaches a
// student reading them in another language, only formulas and names. The corpus is every
// student-facing text of every bundled set, of generated variants of every kind in every API
// convention, and of the grader's feedback (student_text.hpp).
#include "solver/derivation/i18n.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>

#include "export/paper.hpp"
#include "export/quiz_items.hpp"
#include "grader/answer_parser.hpp"
#include "report/feedback.hpp"
#include "report/report.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/problem/conventions_note.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/solve_set.hpp"
#include "student_text.hpp"

namespace frustum {
namespace {

// Names that stay as they are in every language: APIs and their functions and parameters,
// algorithms named after people, and the operators written in formulas.
const std::set<std::string>& names() {
  static const std::set<std::string> n = {
      "OpenGL", "DirectX", "Processing", "Newell", "Cohen", "Sutherland", "Hodgman", "Rodrigues",
      "NDC", "perspective", "frustum", "ortho", "camera", "lookAt", "gluLookAt", "glOrtho",
      "glFrustum", "fovy", "fovx", "aspect", "near", "far", "eye", "center", "up", "width",
      "height", "screenY", "tan", "sin", "sign", "cos", "atan", "arctan", "sqrt", "diag", "min",
      "max", "OR", "AND", "xy", "yz", "xz", "ny", "nx", "nz", "xmin", "xmax", "ymin", "ymax",
      "zmin", "zmax", "inf", "float", "double", "long", "lights", "screenY", "GPU", "true", "false",
      "Direct3D", "FrontCounterClockwise", "XMMatrixTranslation", "OrthoOffCenterLH",
      "PerspectiveOffCenterLH", "translate", "size", "cameraZ",
      // Names of functions and quantities inside formulas.
      "acos", "arccos", "exp", "log", "rad", "outcode", "ndc", "clip", "dist", "depth", "fov", "nf",
      // A scene object's name (the paper plane of the paper-plane seed): names stay as written.
      "plane"};
  return n;
}

// The English words of a translated text: runs of Latin letters of two or more that are not a
// name; identifiers (with a digit or _) and `code` are names too.
std::vector<std::string> english_words(const std::string& text) {
  std::vector<std::string> out;
  bool code = false;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '`') {
      code = !code;
      ++i;
      continue;
    }
    const auto ident = [](char ch) {
      return (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') ||
             ch == '_';
    };
    if (!ident(c)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && ident(text[j])) ++j;
    const std::string token = text.substr(i, j - i);
    i = j;
    // Identifiers (a digit, _, an index [i]) and short capitals (vertex names AB, ABC) are names.
    if (code || token.size() < 2 || token.find_first_of("0123456789_") != std::string::npos)
      continue;
    if (j < text.size() && text[j] == '[') continue;
    if (token.size() <= 3 &&
        token.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ") == std::string::npos)
      continue;
    // Products of coordinates and of c = cos θ, s = sin θ in a formula (xy, zs).
    if (token.size() <= 3 && token.find_first_not_of("xyzcs") == std::string::npos) continue;
    if (!names().count(token)) out.push_back(token);
  }
  return out;
}

// How many of `texts` (text → where it was seen) keep an English word in Japanese or Russian;
// the first 40 are reported, and all are written to $FRUSTUM_UNTRANSLATED when it is set.
// Texts in every language (keyed by all three, so one English said two ways is checked twice),
// each with where it was first seen.
int untranslated(const std::map<std::array<std::string, 3>, std::string>& texts) {
  std::ofstream dump;
  if (const char* path = std::getenv("FRUSTUM_UNTRANSLATED")) dump.open(path);
  int failures = 0;
  for (const Lang lang : {Lang::Ja, Lang::Ru})
    for (const auto& [said, where] : texts) {
      const std::string& text = said[0];
      const std::string& shown = said[static_cast<std::size_t>(lang)];
      const std::vector<std::string> words = english_words(shown);
      if (words.empty()) continue;
      if (dump.is_open()) dump << to_string(lang) << "\t" << where << "\t" << text << "\n";
      if (++failures <= 40)
        ADD_FAILURE() << to_string(lang) << " " << where << ": \"" << words[0] << "\" in\n    "
                      << shown << "\n    (from: " << text << ")";
    }
  return failures;
}

TEST(Language, EnglishWordsAreFoundAndNamesAreNot) {
  EXPECT_EQ(english_words("法線 (n = e₀ × e₁)"), std::vector<std::string>{});
  EXPECT_EQ(english_words("perspective(fovy, aspect, near, far) の視体積"),
            std::vector<std::string>{});
  EXPECT_EQ(english_words("so the eye sees the 裏"),
            (std::vector<std::string>{"so", "the", "sees", "the"}));
  EXPECT_EQ(english_words("`camera.eye` из условия, p_eye, x₀"), std::vector<std::string>{});
}

TEST(Language, NoEnglishWordReachesAJapaneseOrRussianStudent) {
  std::map<std::array<std::string, 3>, std::string> texts;  // text → where first seen
  for (const test::StudentText& t : test::student_texts())
    texts.emplace(std::array{t.text.en(), t.text.in(Lang::Ja), t.text.in(Lang::Ru)}, t.where);
  EXPECT_GT(texts.size(), 300u);
  EXPECT_EQ(untranslated(texts), 0);
}

// Why an answer could not be read, in the student's language: every answer of every kind, given
// texts that fail in every way the readers know (syntax, names, limits, undefined values, lists,
// planes, words, bit strings), gives a reason with no English word in Japanese and Russian.
TEST(Language, ReadingErrorsAreInTheStudentsLanguage) {
  const std::vector<std::string> scalars = {"",
                                            "1 +",
                                            "(1",
                                            "1)",
                                            "()",
                                            "2 3",
                                            "x y",
                                            "1/0",
                                            "0^0",
                                            "0^-1",
                                            "(-1)^(1/2)",
                                            "(-1)^sqrt(2)",
                                            "2^x",
                                            "sin(1e9)",
                                            "exp(1000)",
                                            "log(0)",
                                            "log(-1)",
                                            "asin(2)",
                                            "acos(3)",
                                            "1e99999",
                                            "1,5",
                                            "[1",
                                            "{1}",
                                            "30°",
                                            "sin 3",
                                            "inf",
                                            "nan",
                                            "foo",
                                            "xy",
                                            "e",
                                            "= 3",
                                            "1 = 2 = 3",
                                            "9^9^9^9",
                                            std::string(300, '(') + "1" + std::string(300, ')'),
                                            "2^(2^40)",
                                            "10^400000",
                                            "(2^1000)^1000",
                                            "tan(pi/2)",
                                            "\xff",
                                            "\xc3\x28",
                                            "\xef\xbf\xbd",
                                            "2\xe2\x81\xbb",
                                            "x^(1/100000)",
                                            "sqrt",
                                            "1 * * 2",
                                            "∞",
                                            "\x01",
                                            "x = 1",
                                            "(1+x)^200*(1+y)^200*(1+z)^200",
                                            "1 2 3 4",
                                            "yes",
                                            "0102",
                                            "true false",
                                            "visible visible",
                                            "-"};
  const std::vector<std::string> structured = {
      "[1, 2, foo]", "[[1, 2], [1]]",      "[]",
      "{a: 1}",      "[[1, 2], [3, foo]]", "[1, [2]]",
      "{0: [1]}",    "{0-1: 3}",           "[[1, 2, 3, 4], [1, 2]]",
      "[a, [b]]",    "{visible: [1]}",     "[true]",
      "[1, 2, 3]",   "[[x, 1]]",           "x + y + z",
      "x*y = 1",     "x^2 + y = 1",        "[0, 0, 0, 1/0]"};
  std::vector<YAML::Node> inputs;
  for (const std::string& text : scalars) inputs.emplace_back(text);
  for (const std::string& text : structured) inputs.push_back(YAML::Load(text));
  // error → the input and answer that gave it
  std::map<std::array<std::string, 3>, std::string> errors;
  for (const KindInfo& kind : builtin_kinds().all())
    for (const AnswerSpec& answer : kind.answers)
      for (const YAML::Node& input : inputs) {
        const ParsedAnswer p = parse_answer(input, answer, AngleUnit::Degrees);
        if (!p.ok && !p.error.empty())
          errors.emplace(std::array{p.error.en(), p.error.in(Lang::Ja), p.error.in(Lang::Ru)},
                         kind.name + "." + answer.name + " ← " + YAML::Dump(input));
      }
  EXPECT_GT(errors.size(), 60u);
  EXPECT_EQ(untranslated(errors), 0);
}

bool cites_lecture_file(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return text.find("seed 0") != std::string::npos || text.find("seed's") != std::string::npos;
}

// What students read never cites this project's own lecture files ("seed 003"), in any language:
// not the steps or the feedback, nor a bundled set's title, source or problem texts.
TEST(Language, StudentTextCitesNoLectureFile) {
  for (const test::StudentText& t : test::student_texts())
    for (const Lang lang : {Lang::En, Lang::Ja, Lang::Ru})
      EXPECT_FALSE(cites_lecture_file(t.text.in(lang))) << t.where << ": " << t.text.in(lang);
  for (const std::string& file : test::bundled_sets()) {
    const ProblemSet set = load_problem_set(file);
    for (const auto& [lang, title] : set.title.all())
      EXPECT_FALSE(cites_lecture_file(title + " " + set.source)) << file << ": " << title;
    for (const ProblemSpec& p : set.problems)
      for (const auto& [lang, text] : p.text.all())
        EXPECT_FALSE(cites_lecture_file(text)) << file << ": " << p.id;
  }
}

// A set's `source:` is cited under its title in every format, in the reader's language.
TEST(Language, SourceIsCitedUnderTheTitle) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/004_placing_and_projecting.yaml"));
  ASSERT_NE(set.source.find("Рябинин"), std::string::npos);
  const SetResult solved = solve_set(set, true, std::nullopt);
  EXPECT_NE(render_text(solved, TextStyle{false, Lang::Ru}).find("Источник: К. В. Рябинин"),
            std::string::npos);
  EXPECT_NE(render_markdown(solved, Lang::Ja).find("*出典: К. В. Рябинин"), std::string::npos);
  EXPECT_NE(render_html(solved, Lang::En).find("<p class=\"source\">Source: К. В. Рябинин"),
            std::string::npos);
  EXPECT_EQ(render_json(solved)["source"], set.source);
}

// Course conventions and boolean keys in the student's language.

// The conventions line of a course that declares every course convention reads in Japanese and
// Russian under every API, whatever the kind states (with or without the angle unit).
TEST(Language, CourseConventionsLineIsTranslated) {
  for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX})
    for (const bool api_used : {false, true})
      for (const bool angles : {false, true}) {
        const Said line =
            conventions_note(test::course_conventions(api),
                             ConventionUse{.api = api_used, .angles = angles, .handedness = true});
        if (line.empty()) continue;
        for (const Lang lang : {Lang::Ja, Lang::Ru})
          EXPECT_EQ(english_words(line.in(lang)), std::vector<std::string>{})
              << to_string(lang) << ": " << line.in(lang);
      }
}

// A true/false key is printed in the student's language (真/偽, истина/ложь) in the text and
// Markdown feedback, and a student who writes that word back gets the mark.
TEST(Language, BooleanKeyIsPrintedInTheStudentsLanguageAndAcceptedBack) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  const SolvedSet solved = solve_for_grading(set);
  const std::string id = "seed001-pixel-z";
  for (const Lang lang : {Lang::Ja, Lang::Ru}) {
    YAML::Node wrong;
    wrong[id]["inside"] = std::string(words::kFalse.in(lang));
    const GradeReport r = test::grade_answers(set, solved, wrong);
    // The key as the text report says it.
    const std::string expected = lang == Lang::Ja ? "正解: 真" : "Верный ответ: истина";
    EXPECT_NE(render_grade_text(r, TextStyle{false, lang}).find(expected), std::string::npos)
        << render_grade_text(r, TextStyle{false, lang});
    const ProblemGrade* p = nullptr;
    for (const ProblemGrade& g : r.problems)
      if (g.id == id) p = &g;
    ASSERT_NE(p, nullptr);
    const std::string md = render_problem_feedback_markdown(*p, lang);
    EXPECT_NE(md.find("| " + std::string(words::kTrue.in(lang)) + " |"), std::string::npos) << md;
    EXPECT_EQ(md.find("| true |"), std::string::npos) << md;
    // The key's own word, written back by the student, is correct.
    YAML::Node right;
    right[id]["inside"] = std::string(words::kTrue.in(lang));
    const GradeReport ok = test::grade_answers(set, solved, right);
    for (const ProblemGrade& g : ok.problems) {
      if (g.id != id) continue;
      for (const AnswerGrade& a : g.answers) {
        if (a.name == "inside") {
          EXPECT_EQ(a.verdict, Verdict::Correct) << to_string(lang);
        }
      }
    }
  }
}

// Problems in the students' languages: the seed, example and hard sets give every text
// a student reads — titles, problem texts, statements and reasons — in Japanese and Russian, so
// no English reaches a student reading them in another language (the same check as the steps').
TEST(Language, NoEnglishProblemTextReachesAJapaneseOrRussianStudent) {
  const std::vector<test::InstructorText> texts = test::instructor_texts();
  EXPECT_GT(texts.size(), 70u);
  int failures = 0;
  for (const test::InstructorText& t : texts)
    for (const Lang lang : {Lang::Ja, Lang::Ru}) {
      const std::string& shown = t.shown.at(lang);
      const std::vector<std::string> words = english_words(shown);
      if (words.empty()) continue;
      if (++failures <= 40)
        ADD_FAILURE() << to_string(lang) << " " << t.where << ": \"" << words[0] << "\" in\n    "
                      << shown;
    }
  EXPECT_EQ(failures, 0);
  // And each language reads its own text: a Japanese text is not shown to a Russian student.
  for (const test::InstructorText& t : texts)
    EXPECT_NE(t.shown.at(Lang::Ja), t.shown.at(Lang::Ru)) << t.where;
}

// The prose of a LaTeX document a student reads, after \begin{document}: mathematics
// (\(…\), \[…\], $…$, align and tikz environments), code (\texttt{…}, `…`), commands with their
// options, environment names and comments left out.
std::string latex_prose(const std::string& tex) {
  std::string out;
  std::size_t i = tex.find("\\begin{document}");
  i = i == std::string::npos ? 0 : i + 16;
  const auto skip_to = [&](const std::string& end) {
    const std::size_t at = tex.find(end, i);
    i = at == std::string::npos ? tex.size() : at + end.size();
  };
  const auto skip_group = [&] {  // a {…} group at i, nested braces included
    if (i >= tex.size() || tex[i] != '{') return;
    int depth = 0;
    for (; i < tex.size(); ++i) {
      if (tex[i] == '\\') {
        ++i;
        continue;
      }
      depth += tex[i] == '{' ? 1 : tex[i] == '}' ? -1 : 0;
      if (depth == 0) break;
    }
    ++i;
  };
  while (i < tex.size()) {
    const char c = tex[i];
    if (c == '%') {
      skip_to("\n");
    } else if (tex.compare(i, 2, "\\(") == 0) {
      skip_to("\\)");
    } else if (tex.compare(i, 2, "\\[") == 0) {
      skip_to("\\]");
    } else if (c == '$') {
      ++i;
      skip_to("$");
    } else if (c == '`') {
      ++i;
      skip_to("`");
    } else if (c == '\\' && i + 1 < tex.size() &&
               std::isalpha(static_cast<unsigned char>(tex[i + 1]))) {
      std::size_t j = i + 1;
      while (j < tex.size() && (std::isalpha(static_cast<unsigned char>(tex[j])) || tex[j] == '*'))
        ++j;
      const std::string command = tex.substr(i + 1, j - i - 1);
      i = j;
      if (i < tex.size() && tex[i] == '[') skip_to("]");
      if (command == "texttt" || command == "includegraphics" || command == "end") {
        skip_group();
      } else if (command == "begin") {
        const std::size_t close = tex.find('}', i);
        const std::string env = tex.substr(i + 1, close - i - 1);
        skip_group();
        if (env.rfind("align", 0) == 0 || env.rfind("equation", 0) == 0 ||
            env.rfind("gather", 0) == 0 || env == "tikzpicture")
          skip_to("\\end{" + env + "}");
        else
          skip_group();  // an environment's argument ({tabular}'s columns)
      }
      out += ' ';
    } else if (c == '\\') {
      // An escaped character (\_, \%, \&) is itself; a line break (\\) or a space command is
      // a space.
      out += i + 1 < tex.size() && std::string_view("_%&#{}$").find(tex[i + 1]) != std::string::npos
                 ? tex[i + 1]
                 : ' ';
      i += 2;
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

// The line of `text` where `word` first stands.
std::string line_with(const std::string& text, const std::string& word) {
  const std::size_t at = text.find(word);
  if (at == std::string::npos) return "";
  const std::size_t from = text.rfind('\n', at), to = text.find('\n', at);
  const std::size_t begin = from == std::string::npos ? 0 : from + 1;
  return text.substr(begin, to == std::string::npos ? std::string::npos : to - begin);
}

// Exam sheets and answer keys on paper (`generate --format latex|pdf --lang ja|ru`): no English
// word in what a Japanese or Russian student reads — the headings, the answer lines, the points,
// the key's step titles — besides the instructor's problem ids.
TEST(Language, ExamSheetsAndAnswerKeysHaveNoEnglishWord) {
  int documents = 0;
  std::map<std::array<std::string, 3>, std::string> texts;
  for (const ProblemSet& set : test::student_text_sets(1)) {
    if (set.problems.empty()) continue;
    const std::vector<PaperSheet> sheets = {PaperSheet{"s1", set}};
    for (const Lang lang : {Lang::Ja, Lang::Ru})
      for (const bool key : {false, true}) {
        std::string prose = latex_prose(key ? answer_key_latex(sheets, "t", lang)
                                            : exam_sheets_latex(sheets, "t", lang));
        ++documents;
        std::vector<std::string> ids;  // the instructor's names for the problems, longest first
        for (const ProblemSpec& p : set.problems) ids.push_back(p.id);
        std::sort(ids.begin(), ids.end(),
                  [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
        for (const std::string& id : ids)
          for (std::size_t at; (at = prose.find(id)) != std::string::npos;)
            prose.replace(at, id.size(), " ");
        const std::vector<std::string> english = english_words(prose);
        EXPECT_TRUE(english.empty()) << set.file << (key ? " answer key " : " exam sheets ")
                                     << to_string(lang) << ": \"" << english[0] << "\" in\n"
                                     << line_with(prose, english[0]);
      }
  }
  EXPECT_GT(documents, 40);
  // The extraction keeps the words: the same sheets in English have them.
  const ProblemSet seed =
      load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  const std::string en = latex_prose(exam_sheets_latex({PaperSheet{"s1", seed}}, "t", Lang::En));
  EXPECT_GT(english_words(en).size(), 20u) << en;
}

// The questions the exports write (Moodle, Canvas QTI, PrairieLearn): every prompt, field label
// ("строка 1, столбец 2"), choice and hint a Japanese or Russian student reads has no English
// word; the same questions in English have them.
TEST(Language, ExportedQuestionsHaveNoEnglishWord) {
  std::size_t labels = 0;
  for (const ProblemSet& set : test::student_text_sets(1))
    for (const Lang lang : {Lang::Ja, Lang::Ru})
      for (const QuizQuestion& q : quiz_questions(set, lang))
        for (const QuizAnswer& a : q.answers) {
          // The prompt is the answer's symbol or its label in the student's language, never the
          // key it is stored under (`unit_normal`, `df`): no name is excused.
          std::vector<std::string> texts = {a.prompt};
          for (const QuizField& f : a.fields) {
            texts.push_back(f.label);
            labels += !f.label.empty();
            if (f.type != QuizField::Type::Checkboxes)  // statements are the instructor's text
              for (const std::string& c : f.choices) texts.push_back(c);
          }
          for (const std::string& l : q.left_out)  // "name: why it is not asked here"
            texts.push_back(l.substr(l.find(": ") == std::string::npos ? 0 : l.find(": ") + 2));
          for (const std::string& text : texts) {
            const std::vector<std::string> english = english_words(text);
            EXPECT_TRUE(english.empty())
                << set.file << " " << q.id << "." << a.name << " " << to_string(lang) << ": \""
                << english[0] << "\" in " << text;
          }
        }
  EXPECT_GT(labels, 100u);
  const ProblemSet seed =
      load_problem_set(test::source_path("problems/seeds/002_transforms_and_view_volume.yaml"));
  bool english_label = false;
  for (const QuizQuestion& q : quiz_questions(seed, Lang::En))
    for (const QuizAnswer& a : q.answers)
      for (const QuizField& f : a.fields) english_label |= f.label.rfind("row 1, column 1", 0) == 0;
  EXPECT_TRUE(english_label);
}

// A problem without a text is asked by its kind's summary, in the student's language too.
TEST(Language, KindSummariesAreTranslated) {
  for (const KindInfo& kind : builtin_kinds().all())
    for (const Lang lang : {Lang::Ja, Lang::Ru})
      EXPECT_EQ(english_words(kind.summary.in(lang)), std::vector<std::string>{})
          << kind.name << " " << to_string(lang) << ": " << kind.summary.in(lang);
}

}  // namespace
}  // namespace frustum

namespace frustum {
namespace {

// The formulas, substitutions and results of every derivation a Japanese or Russian student
// reads: their words are translated (MathText::words), and no English is written into the
// mathematics itself ("for every vertex v", "the camera's z axis").
TEST(Language, NoEnglishWordInTheMathematicsOfAJapaneseOrRussianDerivation) {
  std::map<std::string, std::string> failures;  // shown formula → where
  std::size_t formulas = 0;
  for (const ProblemSet& set : test::student_text_sets()) {
    const SolvedSet solved = solve_for_grading(set);
    for (std::size_t i = 0; i < set.problems.size(); ++i) {
      if (solved.results[i].error) continue;
      for (const Step& s : solved.results[i].derivation.steps())
        for (const MathText* m : {&s.formula, &s.substitution, &s.result})
          for (const Lang lang : {Lang::Ja, Lang::Ru}) {
            ++formulas;
            const std::string shown = tr(*m, lang).unicode;
            if (!english_words(shown).empty())
              failures.emplace(shown, set.problems[i].id + " (" + s.title.en() + ")");
          }
    }
  }
  EXPECT_GT(formulas, 1000u);
  int n = 0;
  for (const auto& [shown, where] : failures)
    if (++n <= 40) ADD_FAILURE() << where << ": \"" << english_words(shown)[0] << "\" in " << shown;
  EXPECT_EQ(failures.size(), 0u);
}

}  // namespace
}  // namespace frustum

namespace frustum {
namespace {

// Counted words agree with their number: Russian 1 треугольник, 2 треугольника, 5 треугольников
// (11–14 take the many form; 21 the one form), in Unicode and in LaTeX; English 1 triangle.
TEST(Language, RussianCountsAgreeWithTheirNumbers) {
  const MathText m = counts({{1, "triangles"},
                             {2, "front"},
                             {5, "hidden"},
                             {21, "back"},
                             {12, "visible"},
                             {3, "window triangles"},
                             {0, "back faces culled"}});
  EXPECT_EQ(tr(m, Lang::Ru).unicode,
            "1 треугольник, 2 лицевые, 5 невидимых, 21 обратная, 12 видимых, 3 треугольника в "
            "окне, 0 нелицевых граней отброшено");
  EXPECT_NE(tr(m, Lang::Ru).latex.find("2\\,\\text{лицевые}"), std::string::npos)
      << tr(m, Lang::Ru).latex;
  EXPECT_EQ(tr(m, Lang::En).unicode,
            "1 triangle, 2 front, 5 hidden, 21 back, 12 visible, 3 window triangles, 0 back faces "
            "culled");
  EXPECT_EQ(tr(counts({{1, "back faces culled"}, {11, "triangles"}}), Lang::En).unicode,
            "1 back face culled, 11 triangles");
}

}  // namespace
}  // namespace frustum
