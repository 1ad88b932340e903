// Exported quizzes accept what `frustum grade` accepts: every number of every Canvas/Moodle
// field, moved to 0.9 of its window, is still graded correct by the grader, and moved to 1.5
// windows is not; every choice and text field's right word is graded correct.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "export/export_gradebook.hpp"
#include "export/export_moodle.hpp"
#include "export/export_prairielearn.hpp"
#include "export/export_qti.hpp"
#include "export/quiz_items.hpp"
#include "export/xml_text.hpp"
#include "grader/grade.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/problem_figure.hpp"
#include "solver/problem/variants.hpp"
#include "solver/util/base64.hpp"
#include "solver/visibility/pictures.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// One answer written from quiz fields, the field `moved` shifted by `shift` windows.
std::string answer_yaml(const QuizAnswer& a, std::size_t moved, double shift) {
  std::vector<std::string> items;
  std::size_t cols = 0;
  for (std::size_t i = 0; i < a.fields.size(); ++i) {
    const QuizField& f = a.fields[i];
    if (f.type != QuizField::Type::Number) return "\"" + f.correct + "\"";
    items.push_back(fmt::format("{}", f.value + (i == moved ? shift * f.window : 0)));
    if (f.label.rfind("row 1,", 0) == 0) ++cols;
  }
  if (items.size() == 1 && a.fields[0].label.empty()) return items[0];
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    const bool row_start = cols && i % cols == 0;
    out += (i && row_start ? "], [" : i ? ", " : "") + items[i];
  }
  return cols ? "[" + out + "]]" : out + "]";
}

Verdict verdict_of(const ProblemSet& set, const SolvedSet& solved, const std::string& id,
                   const std::string& name, const std::string& value) {
  const Submission s = load_submission_from_string(
      fmt::format("student: t\nanswers:\n  {}:\n    {}: {}\n", id, name, value), "answers.yaml");
  const GradeReport r = grade(set, s, &solved);
  for (const ProblemGrade& p : r.problems)
    if (p.id == id)
      for (const AnswerGrade& a : p.answers)
        if (a.name == name) return a.verdict;
  return Verdict::Missing;
}

// The sets whose every quiz field the tests below try (the seeds and the pipeline example).
constexpr const char* kQuizSets[] = {"problems/seeds/001_zbuffer_plane_method.yaml",
                                     "problems/seeds/002_transforms_and_view_volume.yaml",
                                     "problems/seeds/003_polygons_backface.yaml",
                                     "problems/seeds/004_placing_and_projecting.yaml",
                                     "problems/examples/pipeline.yaml"};

TEST(Export, QuizWindowsAreTheGradersWindows) {
  int inside = 0, outside = 0;
  for (const char* file : kQuizSets) {
    const ProblemSet source = load_problem_set(test::source_path(file));
    ASSERT_TRUE(source.all_errors().empty()) << file;
    std::vector<ProblemSet> sets = variants_from_seed(source, 11, 3, !set_varies(source));
    sets.push_back(source);
    for (const ProblemSet& set : sets) {
      const SolvedSet solved = solve_for_grading(set);
      for (const QuizQuestion& q : quiz_questions(set))
        for (const QuizAnswer& a : q.answers) {
          EXPECT_EQ(verdict_of(set, solved, q.id, a.name, answer_yaml(a, 0, 0)), Verdict::Correct)
              << file << " " << q.id << "." << a.name;
          for (std::size_t i = 0; i < a.fields.size(); ++i) {
            if (a.fields[i].type != QuizField::Type::Number) continue;
            // A zero window is the grader's too (a transform's fixed bottom row): only the
            // exact value is right, which the first check above has shown.
            ASSERT_GE(a.fields[i].window, 0) << q.id << "." << a.name;
            if (a.fields[i].window == 0) continue;
            EXPECT_EQ(verdict_of(set, solved, q.id, a.name, answer_yaml(a, i, 0.9)),
                      Verdict::Correct)
                << file << " " << q.id << "." << a.name << " " << a.fields[i].label << ": "
                << answer_yaml(a, i, 0.9);
            ++inside;
            // Directions are right up to a positive factor: moving one component changes the
            // direction, which the grader judges on the whole vector, not per field.
            if (a.prompt.find("length 1") != std::string::npos) continue;
            EXPECT_NE(verdict_of(set, solved, q.id, a.name, answer_yaml(a, i, 1.5)),
                      Verdict::Correct)
                << file << " " << q.id << "." << a.name << " " << a.fields[i].label << ": "
                << answer_yaml(a, i, 1.5);
            ++outside;
          }
        }
    }
  }
  EXPECT_GT(inside, 200);
  EXPECT_GT(outside, 150);
}

TEST(Export, AnswersNoFieldCanCheckAreNamedNotDropped) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  const std::vector<QuizQuestion> qs = quiz_questions(set);
  ASSERT_EQ(qs.size(), 3u);
  EXPECT_EQ(qs[1].left_out, std::vector<std::string>{
                                "plane: a plane's equation is right up to any non-zero factor"});
  const std::string moodle = export_moodle({{"", qs}}, "Seed 1");
  EXPECT_NE(moodle.find("Not asked here: plane:"), std::string::npos);
  // z = 8, rel 1e-3, 1 point; the normal's 1 point is three fields of 1/3: weights 1, 1, 1, 3.
  EXPECT_NE(moodle.find("{3:NUMERICAL:=8:0.008}"), std::string::npos) << moodle;
  const auto qti = export_qti({{"", qs}}, "Seed 1", "seed1");
  ASSERT_TRUE(qti.count("seed1.xml"));
  // Canvas: the normal and z are blanks of one item, z asked by its symbol z_S (the depth at
  // the pixel S, as the derivation writes it); z = 8 ± 0.008 asks for 2 decimals.
  EXPECT_NE(qti.at("seed1.xml").find("z_S: [b3_1] (to 2 decimal places)"), std::string::npos)
      << qti.at("seed1.xml");
  EXPECT_NE(qti.at("seed1.xml").find("texttype=\"text/plain\">8.00</mattext>"), std::string::npos);
}

// Canvas's fill-in-multiple-blanks grading (canvas-lms, Quizzes::QuizQuestion::
// FillInMultipleBlanksQuestion): a blank is right when the response, trimmed and
// lower-cased, equals one of its answers' texts the same way; the item's score is the share of
// its blanks that are right. The blanks and their texts are read back from the exported XML.
std::string xml_unescaped(std::string s) {
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}})
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
      s.replace(at, from.size(), to);
  return s;
}
std::string trimmed_lower(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t\n"), e = s.find_last_not_of(" \t\n");
  std::string t = b == std::string::npos ? "" : s.substr(b, e - b + 1);
  for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return t;
}
std::map<std::string, std::vector<std::string>> canvas_blanks(const std::string& item) {
  std::map<std::string, std::vector<std::string>> out;
  const std::string open = "<response_lid ident=\"response_";
  for (std::size_t at = item.find(open); at != std::string::npos; at = item.find(open, at + 1)) {
    const std::size_t id_start = at + open.size();
    const std::string id = item.substr(id_start, item.find('"', id_start) - id_start);
    const std::size_t end = item.find("</response_lid>", at);
    const std::string text_open = "<mattext texttype=\"text/plain\">";
    for (std::size_t t = item.find(text_open, at); t != std::string::npos && t < end;
         t = item.find(text_open, t + 1)) {
      const std::size_t s = t + text_open.size();
      out[id].push_back(xml_unescaped(item.substr(s, item.find("</mattext>", s) - s)));
    }
  }
  return out;
}
double canvas_score(const std::map<std::string, std::vector<std::string>>& blanks,
                    const std::map<std::string, std::string>& responses) {
  int right = 0;
  for (const auto& [id, texts] : blanks) {
    const auto r = responses.find(id);
    if (r == responses.end()) continue;
    for (const std::string& t : texts)
      if (trimmed_lower(t) == trimmed_lower(r->second)) {
        ++right;
        break;
      }
  }
  return blanks.empty() ? 0 : static_cast<double>(right) / static_cast<double>(blanks.size());
}
std::size_t items_in(const std::string& xml) {
  std::size_t n = 0;
  for (std::size_t at = xml.find("<item ident="); at != std::string::npos;
       at = xml.find("<item ident=", at + 1))
    ++n;
  return n;
}
std::string item_xml(const std::string& xml, const std::string& ident) {
  const std::size_t at = xml.find("<item ident=\"" + ident + "\"");
  return at == std::string::npos ? "" : xml.substr(at, xml.find("</item>", at) - at);
}

// A problem with several numbers is one Canvas item (blanks): the key written as each blank
// asks (rounded to its decimals) scores full marks in Canvas and is right for `frustum grade`;
// every text Canvas accepts for a number lies in the grader's window; a number two windows off
// is refused; words and bit strings are their own texts.
TEST(Export, CanvasBlanksAcceptWhatTheGraderAccepts) {
  int items = 0, numbers = 0;
  for (const char* file : kQuizSets) {
    const ProblemSet source = load_problem_set(test::source_path(file));
    const std::vector<ProblemSet> sets = variants_from_seed(source, 5, 2, !set_varies(source));
    std::vector<QuizVariant> variants;
    for (std::size_t v = 0; v < sets.size(); ++v)
      variants.push_back({fmt::format("v{}", v), quiz_questions(sets[v])});
    const std::string xml = export_qti(variants, "t", "t").at("t.xml");
    for (std::size_t v = 0; v < sets.size(); ++v) {
      const SolvedSet solved = solve_for_grading(sets[v]);
      for (std::size_t i = 0; i < variants[v].questions.size(); ++i) {
        const QuizQuestion& q = variants[v].questions[i];
        const std::size_t fields = field_count(q);
        if (fields < 2) continue;
        const std::string item = item_xml(xml, fmt::format("t_q{}_v{}", i + 1, v + 1));
        ASSERT_NE(item.find("fill_in_multiple_blanks_question"), std::string::npos) << q.id;
        const auto blanks = canvas_blanks(item);
        ASSERT_EQ(blanks.size(), fields) << file << " " << q.id;
        ++items;
        std::map<std::string, std::string> key;
        for (std::size_t k = 0; k < q.answers.size(); ++k) {
          const QuizAnswer& a = q.answers[k];
          QuizAnswer rounded = a;  // the answer as a student following the hints writes it
          for (std::size_t j = 0; j < a.fields.size(); ++j) {
            const QuizField& f = a.fields[j];
            const std::string id = fmt::format("b{}_{}", k + 1, j + 1);
            const CanvasBlank b = canvas_blank(f);
            EXPECT_EQ(blanks.at(id), b.texts) << q.id << " " << id;
            if (f.type != QuizField::Type::Number) {
              key[id] = f.type == QuizField::Type::Checkboxes ? b.texts.front() : f.correct;
              continue;
            }
            if (f.value == kQuizInfinity) {
              key[id] = "inf";
              continue;
            }
            ++numbers;
            key[id] = fmt::format("{:.{}f}", f.value, b.places);
            rounded.fields[j].value = std::stod(key[id]);
            for (const std::string& t : b.texts)
              EXPECT_LE(std::abs(std::stod(t) - f.value), f.window * (1 + 1e-9) + 1e-300)
                  << q.id << " " << id << ": Canvas accepts " << t << " for " << f.value << " ± "
                  << f.window;
            if (f.window > 0) {
              const std::string wrong =
                  fmt::format("{:.{}f}", f.value + 2 * f.window, b.places + 2);
              EXPECT_LT(canvas_score(blanks, {{id, wrong}}), 1.0 / static_cast<double>(fields))
                  << q.id << " " << id << " accepts " << wrong;
            }
          }
          EXPECT_EQ(verdict_of(sets[v], solved, q.id, a.name, answer_yaml(rounded, 0, 0)),
                    Verdict::Correct)
              << file << " " << q.id << "." << a.name << ": " << answer_yaml(rounded, 0, 0);
        }
        EXPECT_EQ(canvas_score(blanks, key), 1.0) << file << " " << q.id;
        // Upper case and spaces around a response are Canvas's to ignore.
        std::map<std::string, std::string> spaced;
        for (const auto& [id, text] : key) spaced[id] = "  " + text + " ";
        EXPECT_EQ(canvas_score(blanks, spaced), 1.0) << q.id;
      }
    }
  }
  EXPECT_GE(items, 10);
  EXPECT_GE(numbers, 60);
}

// With variants, each problem is a Canvas question group drawing one item for each student
// (selection_number 1, the problem's points per item) from its item in every variant, each
// item with that variant's own givens: per-student variants through Canvas's randomisation, in
// one quiz.
TEST(Export, CanvasDrawsEachStudentsVariantFromAQuestionGroup) {
  const ProblemSet source =
      load_problem_set(test::source_path("problems/seeds/003_polygons_backface.yaml"));
  const std::vector<ProblemSet> sets = variants_from_seed(source, 9, 3, !set_varies(source));
  std::vector<QuizVariant> variants;
  for (std::size_t v = 0; v < sets.size(); ++v)
    variants.push_back({fmt::format("seed9-{}", v), quiz_questions(sets[v])});
  const auto files = export_qti(variants, "Seed 3", "seed3");
  ASSERT_EQ(files.size(), 2u);  // the manifest and one assessment
  const std::string& xml = files.at("seed3.xml");
  EXPECT_NE(files.at("imsmanifest.xml").find("href=\"seed3.xml\""), std::string::npos);
  int groups = 0;
  for (std::size_t i = 0; i < variants[0].questions.size(); ++i) {
    const QuizQuestion& q = variants[0].questions[i];
    if (q.answers.empty()) continue;
    const std::string open = fmt::format("<section ident=\"seed3_g{}\"", i + 1);
    const std::size_t at = xml.find(open);
    ASSERT_NE(at, std::string::npos) << q.id;
    const std::string section = xml.substr(at, xml.find("</section>", at) - at);
    double points = 0;
    for (const QuizAnswer& a : q.answers) points += a.points;
    EXPECT_NE(section.find(fmt::format("<selection_number>1</selection_number><selection_extension>"
                                       "<points_per_item>{}</points_per_item>",
                                       points)),
              std::string::npos)
        << section;
    EXPECT_EQ(items_in(section), 3u) << q.id;
    for (std::size_t v = 0; v < 3; ++v) {
      const std::string item = item_xml(section, fmt::format("seed3_q{}_v{}", i + 1, v + 1));
      ASSERT_FALSE(item.empty()) << q.id << " v" << v;
      for (const std::string& g : variants[v].questions[i].given)
        EXPECT_NE(item.find(xml_escape(xml_escape(g))), std::string::npos) << q.id << " " << g;
    }
    ++groups;
  }
  EXPECT_GE(groups, 3);
}

// A word asked in a Japanese or Russian quiz is that language's word (front → 表, лицевая), as
// `frustum grade` prints it in the key and reads it back; the set's own English word stays a
// right spelling where a platform compares texts (Canvas's blanks).
TEST(Export, ChoicesAreWordsInTheStudentsLanguageAndReadBack) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/003_polygons_backface.yaml"));
  const SolvedSet solved = solve_for_grading(set);
  int words = 0;
  for (const Lang lang : {Lang::Ja, Lang::Ru})
    for (const QuizQuestion& q : quiz_questions(set, lang))
      for (const QuizAnswer& a : q.answers)
        for (const QuizField& f : a.fields) {
          if (f.type != QuizField::Type::Choice) continue;
          ++words;
          EXPECT_TRUE(std::any_of(f.correct.begin(), f.correct.end(),
                                  [](char c) { return static_cast<unsigned char>(c) >= 0x80; }))
              << q.id << "." << a.name << ": " << f.correct;
          EXPECT_NE(std::find(f.choices.begin(), f.choices.end(), f.correct), f.choices.end());
          for (const std::string& word : std::vector<std::string>{f.correct, f.also.at(0)})
            EXPECT_EQ(verdict_of(set, solved, q.id, a.name, "\"" + word + "\""), Verdict::Correct)
                << q.id << "." << a.name << ": " << word;
          const CanvasBlank b = canvas_blank(f, lang);
          EXPECT_NE(std::find(b.texts.begin(), b.texts.end(), f.also.at(0)), b.texts.end());
          EXPECT_NE(b.hint.find(f.correct), std::string::npos) << b.hint;
        }
  EXPECT_GE(words, 2);
}

// A text field (an outcode) is right on a platform for exactly the spellings the grader calls
// right: every bit string up to the field's length is tried against both.
TEST(Export, TextFieldsAcceptExactlyWhatTheGraderAccepts) {
  const ProblemSet set = load_problem_set(test::source_path("problems/hard/decisions.yaml"));
  ASSERT_TRUE(set.all_errors().empty());
  const SolvedSet solved = solve_for_grading(set);
  const std::vector<QuizQuestion> qs = quiz_questions(set);
  int fields = 0, dropped = 0;
  for (const QuizQuestion& q : qs)
    for (const QuizAnswer& a : q.answers)
      for (const QuizField& f : a.fields) {
        if (f.type != QuizField::Type::Text) continue;
        ++fields;
        std::vector<std::string> platform{f.correct};
        platform.insert(platform.end(), f.also.begin(), f.also.end());
        dropped += static_cast<int>(f.also.size());
        for (std::size_t n = 1; n <= f.correct.size(); ++n)
          for (unsigned bits = 0; bits < (1u << n); ++bits) {
            std::string s;
            for (std::size_t i = n; i-- > 0;) s += (bits >> i & 1u) ? '1' : '0';
            const bool graded =
                verdict_of(set, solved, q.id, a.name, "\"" + s + "\"") == Verdict::Correct;
            const bool listed = std::find(platform.begin(), platform.end(), s) != platform.end();
            EXPECT_EQ(graded, listed) << q.id << "." << a.name << " " << s;
          }
        QuizQuestion only = q;  // this field alone
        only.answers = {a};
        only.answers[0].fields = {f};
        const std::string moodle = export_moodle({{"", {only}}}, "t");
        std::string cloze = "SHORTANSWER:=" + f.correct;
        for (const std::string& also : f.also) cloze += "~=" + also;
        EXPECT_NE(moodle.find(cloze + "}"), std::string::npos) << moodle;
        const std::string qti = export_qti({{"", {only}}}, "t", "t").at("t.xml");
        for (const std::string& s : platform)
          EXPECT_NE(qti.find("<varequal respident=\"response1\">" + s + "</varequal>"),
                    std::string::npos)
              << s;
        EXPECT_EQ(qti.find("<or>") != std::string::npos, !f.also.empty());
      }
  EXPECT_GE(fields, 4);
  EXPECT_GT(dropped, 0);  // some outcode has a leading zero
}

// Moodle's Cloze grading (question/type/multianswer): the question's mark is the sum of its
// subquestions' weights (<defaultgrade> is ignored) and a student earns Σ wᵢ·fractionᵢ of it.
// So each answer's share of the weights must be its share of the problem's points, and a
// problem whose points split into whole weights is marked out of its own points.
TEST(Export, MoodleClozeWeightsAddUpToTheProblemsPoints) {
  int whole = 0, scaled = 0;
  for (const char* file : kQuizSets) {
    const ProblemSet set = load_problem_set(test::source_path(file));
    for (const QuizQuestion& q : quiz_questions(set)) {
      if (q.answers.empty()) continue;
      const std::string xml = export_moodle({{"", {q}}}, "t");
      if (xml.find("type=\"cloze\"") == std::string::npos) continue;
      // The weights as Moodle reads them: {WEIGHT:TYPE:...} in the question text.
      std::vector<long long> read;
      for (std::size_t at = xml.find("{"); at != std::string::npos; at = xml.find("{", at + 1)) {
        const std::size_t colon = xml.find(':', at);
        const std::string w = xml.substr(at + 1, colon - at - 1);
        if (!w.empty() && w.find_first_not_of("0123456789") == std::string::npos)
          read.push_back(std::stoll(w));
      }
      double total = 0;
      std::size_t fields = 0;
      for (const QuizAnswer& a : q.answers) total += a.points, fields += a.fields.size();
      ASSERT_EQ(read.size(), fields) << file << " " << q.id;
      long long sum = 0;
      for (const long long w : read) sum += w;
      std::size_t k = 0;
      bool whole_points = true;
      for (const QuizAnswer& a : q.answers) {
        long long share = 0;
        for (std::size_t i = 0; i < a.fields.size(); ++i) share += read[k++];
        EXPECT_NEAR(double(share) / double(sum), a.points / total, 1e-9) << q.id << "." << a.name;
        const double per = a.points / double(a.fields.size());
        whole_points = whole_points && per == std::floor(per);
      }
      EXPECT_NE(xml.find(fmt::format("<defaultgrade>{}</defaultgrade>", sum)), std::string::npos);
      if (whole_points) {
        EXPECT_EQ(double(sum), total) << q.id;
        ++whole;
      } else {
        // Not whole: the smallest whole weights, and the comment says which mark to set.
        EXPECT_NE(xml.find(fmt::format("maximum mark in the quiz to {}", total)), std::string::npos)
            << xml;
        ++scaled;
      }
    }
  }
  EXPECT_GE(whole, 1);   // a clipped segment's outcodes and truths: one field each
  EXPECT_GT(scaled, 3);  // a vector's point split over its numbers
}

// The PrairieLearn questions of a set `t` written in YAML (each variant the set itself), in `lang`.
std::map<std::string, std::map<std::string, std::string>> prairielearn_questions(const char* yaml,
                                                                                 Lang lang) {
  const YamlDocument doc = parse_yaml(yaml, "t.yaml");
  const ProblemSet set = load_problem_set(doc, "t.yaml");
  EXPECT_TRUE(set.all_errors().empty());
  PrairieLearnOptions options;
  options.image = "course/frustum-grader:1";
  options.lang = lang;
  return export_prairielearn(doc.root, set, {set}, "t", options);
}

// PrairieLearn's element rules (pl-checkbox.py: "At least one option must be true", min-correct
// at least 1; pl-number-input and pl-matrix-input refuse `none` and sqrt(…)): a set whose
// statements are all false, and a polygon clipped away, export questions that render and take
// their key as typed.
TEST(Export, PrairieLearnQuestionsRenderAndTakeTheirKey) {
  const char* kSet = R"(title: t
problems:
  - id: gone
    kind: clip_polygon
    given:
      points: [[5, 5], [8, 5], [5, 8]]
      window: {xmin: 0, xmax: 1, ymin: 0, ymax: 1}
  - id: none-true
    kind: statements
    text: "Which are true?"
    given:
      statements:
        - {text: "One.", truth: false}
        - {text: "Two.", truth: false}
  - id: pixel
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
)";
  const auto pl = prairielearn_questions(kSet, Lang::Ru);
  ASSERT_EQ(pl.size(), 3u);
  for (const auto& [dir, files] : pl) {
    const std::string& html = files.at("question.html");
    const std::string& server = files.at("server.py");
    EXPECT_EQ(html.find("pl-number-input"), std::string::npos) << dir;
    EXPECT_EQ(html.find("pl-matrix-input"), std::string::npos) << dir;
    EXPECT_EQ(html.find("min-correct"), std::string::npos) << dir;
    EXPECT_NE(html.find("{{{feedback.results.frustum_html}}}"), std::string::npos) << dir;
    EXPECT_NE(html.find("<pl-answer-panel>"), std::string::npos) << dir;
    EXPECT_NE(server.find("data[\"correct_answers\"].update"), std::string::npos) << dir;
    EXPECT_NE(server.find("\\\"lang\\\":\\\"ru\\\""), std::string::npos) << dir;
    EXPECT_NE(files.at("info.json").find("\"image\": \"course/frustum-grader:1\""),
              std::string::npos);
  }
  // No statement is true: the right option is "none of them" (in Russian), the only right one.
  const std::string& checkbox = pl.at("t-none-true").at("question.html");
  EXPECT_NE(checkbox.find("<pl-answer correct=\"true\">Ни одно из утверждений выше не верно"),
            std::string::npos)
      << checkbox;
  std::size_t right = 0;
  for (std::size_t at = checkbox.find("correct=\"true\""); at != std::string::npos;
       at = checkbox.find("correct=\"true\"", at + 1))
    ++right;
  EXPECT_EQ(right, 1u) << checkbox;
  // The polygon clipped away: a text input whose key is `none`.
  const std::string& gone = pl.at("t-gone").at("question.html");
  EXPECT_NE(gone.find("<pl-string-input answers-name=\"clipped\""), std::string::npos) << gone;
  EXPECT_NE(pl.at("t-gone").at("server.py").find("\\\"clipped\\\":\\\"none\\\""), std::string::npos)
      << pl.at("t-gone").at("server.py");
  // z = 8 by the plane method: its exact key, and the window of a decimal said in Russian.
  const std::string& pixel = pl.at("t-pixel").at("server.py");
  EXPECT_NE(pixel.find("\\\"z\\\":\\\"8\\\""), std::string::npos) << pixel;
  EXPECT_NE(pixel.find("±0.008"), std::string::npos) << pixel;
  EXPECT_NE(pixel.find("Можно писать точные значения"), std::string::npos) << pixel;
}

// A kind's figure that shows its answers is, in a PrairieLearn question, the variant's own SVG in
// the answer panel (with the key), never in the question panel or a file of the question; a
// picture of the givens only is in the question panel.
TEST(Export, PrairieLearnShowsTheFigureWithTheKeyOnly) {
  const char* kSet = R"(title: t
lang: ja
problems:
  - id: sort
    kind: depth_sort
    given:
      polygons:
        - [[-2, -1, -6], [2, -1, -6], [2, 1, -6], [-2, 1, -6]]
        - [[-1, -2, -8], [1, -2, -8], [1, 2, -4], [-1, 2, -4]]
      eye: [0, 0, 0]
  - id: pixel
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
)";
  const auto pl = prairielearn_questions(kSet, Lang::Ja);
  const ProblemSet set = load_problem_set(parse_yaml(kSet, "t.yaml"), "t.yaml");
  const auto& sort = pl.at("t-sort");
  const std::string& html = sort.at("question.html");
  const std::size_t answer_panel = html.find("<pl-answer-panel>");
  ASSERT_NE(answer_panel, std::string::npos);
  EXPECT_GT(html.find("{{{correct_answers.frustum_figure}}}"), answer_panel) << html;
  EXPECT_EQ(sort.size(), 3u);  // info.json, question.html, server.py: no figure file
  // The figure is the variant's SVG, drawn as `frustum draw --lang ja` draws it, with a Japanese
  // alt text and Japanese captions.
  const std::string& server = sort.at("server.py");
  PictureOptions picture;
  picture.lang = Lang::Ja;
  const std::string svg =
      draw_picture(set.problems[0].info->drawable(set.problems[0].given), picture).svg;
  EXPECT_NE(server.find(base64(svg)), std::string::npos);
  EXPECT_NE(server.find("<img alt="), std::string::npos);
  EXPECT_NE(server.find("図"), std::string::npos);
  EXPECT_EQ(server.find("Figure"), std::string::npos);
  EXPECT_EQ(html.find("{{{params.frustum_figure}}}"), std::string::npos);
  // A picture of the givens only (the plane method's triangle and pixel) is in the question.
  const std::string& pixel = pl.at("t-pixel").at("question.html");
  EXPECT_LT(pixel.find("{{{params.frustum_figure}}}"), pixel.find("</pl-question-panel>")) << pixel;
  EXPECT_EQ(pixel.find("correct_answers.frustum_figure"), std::string::npos);
  EXPECT_NE(
      pl.at("t-pixel").at("server.py").find(base64(problem_figure(set.problems[1], Lang::Ja)->svg)),
      std::string::npos);
}

// Canvas matches SIS User ID and Moodle ID number exactly: an id the spreadsheet guard would
// change ('=cmd) is left out and named, never written as an id no student has; plain ids and
// signed numbers stay as they are.
TEST(Export, GradebookIdsAreWrittenAsTheLmsKnowsThemOrLeftOut) {
  const std::string book =
      "student,score,max_score,percent,status\n"
      "s1,3,4,75,graded\n=cmd(),4,4,100,graded\n@sum(1),2,4,50,graded\n"
      "-42,1,4,25,graded\n";
  for (const GradebookFormat format : {GradebookFormat::Canvas, GradebookFormat::Moodle}) {
    std::vector<std::string> left_out;
    const std::string csv =
        export_gradebook(book, "gradebook.csv", format, "HW", StudentKey::SisUserId, &left_out);
    EXPECT_EQ(csv.find("'="), std::string::npos) << csv;
    EXPECT_EQ(csv.find("'@"), std::string::npos) << csv;
    EXPECT_EQ(csv.find("cmd"), std::string::npos) << csv;
    EXPECT_NE(csv.find(format == GradebookFormat::Canvas ? ",,s1,,,3\n" : "s1,3\n"),
              std::string::npos)
        << csv;
    EXPECT_NE(csv.find(format == GradebookFormat::Canvas ? ",,-42,,,1\n" : "-42,1\n"),
              std::string::npos)
        << csv;
    ASSERT_EQ(left_out.size(), 2u);
    EXPECT_NE(left_out[0].find("enter the grade (4) by hand"), std::string::npos) << left_out[0];
    EXPECT_NE(left_out[1].find("@sum(1)"), std::string::npos) << left_out[1];
  }
}

}  // namespace
}  // namespace frustum
