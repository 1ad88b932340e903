// Problems in the students' languages: a problem's `text`, a set's `title` and a
// statement's text and reason may be a mapping by language; `--lang` picks one, falling back to
// the set's own (`lang:`); `check` refuses unknown languages and checks every language's
// placeholders; every writer shows the chosen language, and generated variants keep them all.
#include <yaml-cpp/yaml.h>

#include "export/export_moodle.hpp"
#include "export/paper.hpp"
#include "export/quiz_items.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/problem/variants.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

constexpr const char* kTwoLanguages = R"(title: {en: Viewing, ja: 視点と投影, ru: Наблюдение}
problems:
  - id: eye
    kind: look_at
    text:
      en: "The eye at {eye} looks at {center}. Find the view matrix."
      ja: "視点 {eye} から {center} を見る。ビュー変換行列を求めよ。"
      ru: "Глаз в точке {eye} смотрит на {center}. Найдите матрицу вида."
    given: {eye: [0, 0, 5], center: [0, 0, 0], up: [0, 1, 0]}
    vary:
      eye: {choices: [[0, 0, 5], [0, 0, 7], [0, 0, 9]]}
  - id: plain
    kind: vectors
    text: "Find a · b."
    given: {a: [1, 2, 3], b: [4, 5, 6]}
    ask: [dot]
)";

std::string error_of(const std::string& yaml) {
  const ProblemSet set = load_problem_set_from_string(yaml, "t.yaml");
  for (const Diagnostic& d : set.all_errors()) return d.format();
  for (const ProblemSpec& p : set.problems)
    if (const ProblemResult r = solve_problem(p, set.file, false); r.error)
      return r.error->format();
  return "";
}

TEST(ProblemTexts, MappingIsLoadedInEveryLanguage) {
  const ProblemSet set = load_problem_set_from_string(kTwoLanguages, "t.yaml");
  ASSERT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
  EXPECT_EQ(set.lang, Lang::En);
  EXPECT_EQ(set.title.text, "Viewing");
  EXPECT_EQ(set.title.in(Lang::Ru), "Наблюдение");
  const LocalText& t = set.problems[0].text;
  EXPECT_EQ(t.lang, Lang::En);
  EXPECT_EQ(t.text, "The eye at {eye} looks at {center}. Find the view matrix.");
  EXPECT_EQ(t.in(Lang::Ja), "視点 {eye} から {center} を見る。ビュー変換行列を求めよ。");
  EXPECT_EQ(t.all().size(), 3u);
  // A plain string is the set's own language and nothing else.
  EXPECT_EQ(set.problems[1].text.in(Lang::Ja), "Find a · b.");
  EXPECT_TRUE(set.problems[1].text.translations.empty());
}

TEST(ProblemTexts, CheckNamesFileLineAndField) {
  const std::string head =
      "problems:\n  - id: p\n    kind: vectors\n    given: {a: [1, 0, 0], b: [0, 1, 0]}\n";
  EXPECT_EQ(error_of(head + "    text: {en: a, de: b}\n"),
            "t.yaml:5:19: problems[0].text.de: 'de' is not a language of Frustum (en, ja, ru)");
  EXPECT_EQ(error_of(head + "    text: {ja: あ, ru: б}\n"),
            "t.yaml:5:11: problems[0].text.en: missing: the text in the set's own language (lang: "
            "en), which readers of other languages fall back to");
  EXPECT_EQ(error_of(head + "    text: {en: a, ja: [1, 2]}\n"),
            "t.yaml:5:23: problems[0].text.ja: expected text");
  EXPECT_EQ(error_of(head + "    text: [a, b]\n"),
            "t.yaml:5:11: problems[0].text: expected text, or a mapping by language like {en: …, "
            "ja: …, ru: …}");
  EXPECT_EQ(error_of("lang: jp\n" + head),
            "t.yaml:1:7: lang: 'jp' is not one of en, ja, ru (did you mean 'ja'?)");
  EXPECT_EQ(error_of("title: {en: T, fr: U}\n" + head),
            "t.yaml:1:16: title.fr: 'fr' is not a language of Frustum (en, ja, ru)");
  // Placeholders are checked in every language, each where it is written.
  EXPECT_EQ(error_of(head + "    text:\n      en: \"a = {a}\"\n      ru: \"a = {a}, c = {c}\"\n"),
            "t.yaml:7:11: problems[0].text.ru: the placeholder {c} names no field of the given");
  // A set written in Japanese needs its Japanese text; English is then a translation.
  EXPECT_EQ(error_of("lang: ja\n" + head + "    text: {en: a}\n"),
            "t.yaml:6:11: problems[0].text.ja: missing: the text in the set's own language (lang: "
            "ja), which readers of other languages fall back to");
  EXPECT_EQ(error_of("lang: ja\n" + head + "    text: {ja: あ, en: a}\n"), "");
}

TEST(ProblemTexts, ChosenLanguageOrTheSetsOwn) {
  const ProblemSet set = load_problem_set_from_string(kTwoLanguages, "t.yaml");
  const SetResult solved = solve_set(set, true);
  const std::string ja = render_text(solved, TextStyle{false, Lang::Ja});
  EXPECT_NE(ja.find("視点と投影"), std::string::npos);
  EXPECT_NE(ja.find("視点 (0, 0, 5) から (0, 0, 0) を見る。"), std::string::npos) << ja;
  EXPECT_EQ(ja.find("The eye at"), std::string::npos);
  // No Russian text for `plain`: the set's own (English) text.
  const std::string ru = render_markdown(solved, Lang::Ru);
  EXPECT_NE(ru.find("# Наблюдение"), std::string::npos);
  EXPECT_NE(ru.find("Глаз в точке (0, 0, 5)"), std::string::npos);
  EXPECT_NE(ru.find("Find a · b."), std::string::npos);
  const std::string en = render_html(solved, Lang::En);
  EXPECT_NE(en.find("The eye at (0, 0, 5) looks at (0, 0, 0)."), std::string::npos);
  EXPECT_EQ(en.find("視点"), std::string::npos);
  EXPECT_NE(render_latex(solved, Lang::Ru).find("Найдите матрицу вида."), std::string::npos);
  // A Japanese set read in English or Russian, with no translation, is read in Japanese.
  const SetResult own =
      solve_set(load_problem_set_from_string(
                    "lang: ja\nproblems:\n  - id: p\n    kind: vectors\n    text: 内積を求めよ。\n"
                    "    given: {a: [1, 0, 0], b: [0, 1, 0]}\n    ask: [dot]\n",
                    "t.yaml"),
                true);
  EXPECT_NE(render_text(own, TextStyle{false, Lang::Ru}).find("内積を求めよ。"), std::string::npos);
}

TEST(ProblemTexts, JsonGivesTheChosenTextAndEveryLanguage) {
  const SetResult solved = solve_set(load_problem_set_from_string(kTwoLanguages, "t.yaml"), true);
  const auto j = render_json(solved, Lang::Ja);
  EXPECT_EQ(j["lang"], "en");
  EXPECT_EQ(j["title"], "視点と投影");
  EXPECT_EQ(j["titles"]["ru"], "Наблюдение");
  EXPECT_EQ(j["problems"][0]["text"],
            "視点 (0, 0, 5) から (0, 0, 0) を見る。ビュー変換行列を求めよ。");
  EXPECT_EQ(j["problems"][0]["texts"]["en"],
            "The eye at (0, 0, 5) looks at (0, 0, 0). Find the view matrix.");
  EXPECT_EQ(j["problems"][0]["texts"].size(), 3u);
  EXPECT_EQ(j["problems"][1]["text"], "Find a · b.");
  EXPECT_EQ(j["problems"][1]["texts"].size(), 1u);
  EXPECT_EQ(render_json(solved)["problems"][0]["text"], j["problems"][0]["texts"]["en"]);
}

TEST(ProblemTexts, VariantsKeepEveryLanguageWithTheValuesFilled) {
  const ProblemSet set = load_problem_set_from_string(kTwoLanguages, "t.yaml");
  const std::vector<ProblemSet> variants = variants_from_seed(set, 7, 3);
  ASSERT_EQ(variants.size(), 3u);
  for (const ProblemSet& v : variants) {
    ASSERT_TRUE(v.all_errors().empty());
    const std::string eye = "(0, 0, " + v.problems[0].given_node["eye"][2].Scalar() + ")";
    const std::string emitted = emit_variant_set(YAML::Load(kTwoLanguages), v, "");
    const ProblemSet again = load_problem_set_from_string(emitted, "v.yaml");
    ASSERT_TRUE(again.all_errors().empty()) << emitted;
    const LocalText& t = again.problems[0].text;
    EXPECT_EQ(t.text, "The eye at " + eye + " looks at (0, 0, 0). Find the view matrix.")
        << emitted;
    EXPECT_EQ(t.in(Lang::Ja), "視点 " + eye + " から (0, 0, 0) を見る。ビュー変換行列を求めよ。");
    EXPECT_EQ(t.in(Lang::Ru),
              "Глаз в точке " + eye + " смотрит на (0, 0, 0). Найдите матрицу вида.");
    EXPECT_EQ(again.title.in(Lang::Ja), "視点と投影");
  }
}

constexpr const char* kStatements = R"(title: {en: Back faces, ja: 背面除去}
problems:
  - id: q
    kind: statements
    text: {en: "Which are true?", ja: 正しいものを選べ。}
    given:
      statements:
        - text: {en: A back face is never drawn., ja: 裏面は描かれない。}
          truth: true
          reason: {en: It faces away., ja: 視点から見えない。}
        - {text: Culling needs a z-buffer., truth: false}
)";

TEST(ProblemTexts, QuizExportAndPaperInJapanese) {
  const ProblemSet set = load_problem_set_from_string(kStatements, "t.yaml");
  ASSERT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
  const std::vector<QuizQuestion> qs = quiz_questions(set, Lang::Ja);
  ASSERT_EQ(qs.size(), 1u);
  EXPECT_EQ(qs[0].text, "正しいものを選べ。");
  ASSERT_EQ(qs[0].answers.size(), 1u);
  const QuizField& f = qs[0].answers[0].fields.at(0);
  EXPECT_EQ(f.choices,
            (std::vector<std::string>{"裏面は描かれない。", "Culling needs a z-buffer."}));
  EXPECT_EQ(f.reasons[0], "視点から見えない。");
  const std::string xml = export_moodle({{"", qs}}, set.title.in(Lang::Ja));
  EXPECT_NE(xml.find("正しいものを選べ。"), std::string::npos);
  EXPECT_NE(xml.find("裏面は描かれない。"), std::string::npos);
  EXPECT_EQ(xml.find("Which are true?"), std::string::npos);
  EXPECT_EQ(quiz_questions(set)[0].text, "Which are true?");
  const std::string paper = exam_sheets_latex({{"s1", set}}, set.title.in(Lang::Ja), Lang::Ja);
  EXPECT_NE(paper.find("裏面は描かれない。"), std::string::npos);
  EXPECT_EQ(paper.find("A back face"), std::string::npos);
}

TEST(ProblemTexts, StatementsAndReasonsInTheDerivation) {
  const SetResult solved = solve_set(load_problem_set_from_string(kStatements, "t.yaml"), true);
  ASSERT_FALSE(solved.problems[0].error);
  const std::string ja = render_markdown(solved, Lang::Ja);
  EXPECT_NE(ja.find("記述 1: 裏面は描かれない。"), std::string::npos) << ja;
  EXPECT_NE(ja.find("視点から見えない。"), std::string::npos);
  EXPECT_EQ(ja.find("A back face"), std::string::npos);
  const std::string en = render_text(solved, TextStyle{false, Lang::En});
  EXPECT_NE(en.find("Statement 1: A back face is never drawn."), std::string::npos);
  EXPECT_NE(en.find("Reason: It faces away."), std::string::npos);
  // An unknown language inside a statement is named with its path.
  EXPECT_EQ(error_of("problems:\n  - id: q\n    kind: statements\n    given:\n      statements:\n"
                     "        - {text: {en: a, ja: b, es: c}, truth: true}\n"),
            "t.yaml:6:33: problems[0].given.statements[0].text.es: 'es' is not a language of "
            "Frustum (en, ja, ru)");
}

TEST(ProblemTexts, AProblemWithoutTextIsAskedByItsKindInTheChosenLanguage) {
  const ProblemSet set = load_problem_set_from_string(
      "problems:\n  - id: p\n    kind: normal\n    given: {points: [[0, 0, 0], [1, 0, 0], [0, 1, "
      "0]]}\n",
      "t.yaml");
  EXPECT_EQ(quiz_questions(set, Lang::Ja).at(0).text, "多角形の法線ベクトルと単位法線ベクトル");
  EXPECT_EQ(quiz_questions(set, Lang::Ru).at(0).text, "нормаль и единичная нормаль многоугольника");
  EXPECT_EQ(quiz_questions(set).at(0).text, "the normal and unit normal of a polygon");
}

}  // namespace
}  // namespace frustum
