// The instructors' side of `frustum serve`, handler by handler, without sockets: instructors'
// links and sessions (and every /instructor/ route refused to a student), the class at a glance
// (the gradebook as `grade -o` writes it and in Canvas's and Moodle's formats, per problem and
// per answer counts and median attempts, the frequent named mistakes, one student's
// submissions), live events, a regrade's dry run and apply after a key changes (with the grades'
// history), CSRF refusals, and copy signals.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include "serve_test_sets.hpp"
#include "server/class_view.hpp"
#include "server/grade_job.hpp"
#include "server/instructor_phrases.hpp"
#include "server/instructors.hpp"
#include "server/session.hpp"
#include "server/student_app.hpp"
#include "server/tokens.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum::server {
namespace {

namespace fs = std::filesystem;
using namespace frustum::server::test;  // NOLINT: the shared sets and helpers

constexpr Millis kNow = 1'800'000'000'000;
constexpr const char* kProf = "00000000000000000000000000000001";
constexpr const char* kAlice = "0123456789abcdef0123456789abcdef";
constexpr const char* kBob = "fedcba9876543210fedcba9876543210";
constexpr const char* kCarol = "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa";

// How a student writes a key's value.
std::string written(const Value& v) {
  char buffer[40];
  switch (v.shape) {
    case Value::Shape::Scalar:
      std::snprintf(buffer, sizeof buffer, "%.17g", v.numbers.at(0));
      return buffer;
    case Value::Shape::Word:
      return v.word;
    case Value::Shape::Bool:
      return v.flag ? "true" : "false";
    default: {
      std::string out = "(";
      for (std::size_t i = 0; i < v.numbers.size(); ++i) {
        std::snprintf(buffer, sizeof buffer, "%.17g", v.numbers[i]);
        out += (i ? ", " : "") + std::string(buffer);
      }
      return out + ")";
    }
  }
}

class InstructorPages : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("frustum-instr-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "week1.yaml") << kWeek1;
    std::ofstream(dir_ / "varied.yaml") << kVaried;
    course_ = load_course(dir_.string(), {"alice", "bob", "carol"});
    ASSERT_TRUE(course_.errors.empty()) << course_.errors.front().format();
    course_.instructors = {"prof"};
    store_ = open_store("sqlite:" + (dir_ / "serve.sqlite").string());
    options_.events_wait_ms = 0;  // no test waits
    app_ = std::make_unique<StudentApp>(course_, *store_, options_);
    store_->put_student("alice", sha256_hex(kAlice));
    store_->put_student("bob", sha256_hex(kBob));
    store_->put_student("carol", sha256_hex(kCarol));
    store_->put_instructor("prof", sha256_hex(kProf));
  }
  void TearDown() override {
    app_.reset();
    store_.reset();
    fs::remove_all(dir_);
  }

  Request request(const std::string& method, const std::string& target, const std::string& cookie,
                  const std::string& body = "") {
    Request r{method, target, {{"host", "127.0.0.1:8080"}}, body, "127.0.0.1"};
    if (!cookie.empty())
      r.headers.emplace_back("cookie", std::string(kSessionCookie) + "=" + cookie);
    if (method == "POST") r.headers.emplace_back("origin", "http://127.0.0.1:8080");
    return r;
  }
  Response get(const std::string& target, const std::string& cookie = "") {
    return handle_student(*app_, request("GET", target, cookie), kNow);
  }
  Response post(const std::string& target, const std::string& cookie, const std::string& body) {
    return handle_student(*app_, request("POST", target, cookie, body), kNow);
  }
  std::string sign_in(const std::string& token) {
    return session_cookie(get("/start?token=" + token));
  }
  std::string csrf_of(const std::string& page) { return csrf_in(page); }
  // A student's submission of `answers` ("a.z=8&…") to `problem` of `set`.
  void submit(const std::string& token, const std::string& set, const std::string& problem,
              const std::string& answers) {
    const std::string session = sign_in(token);
    const std::string csrf = csrf_of(get("/set/" + set, session).body);
    ASSERT_EQ(post("/set/" + set + "/submit", session,
                   "csrf=" + csrf + "&problem=" + problem + "&" + answers)
                  .status,
              303);
  }
  void grade_pending() {
    SolvedCache cache;
    while (const auto s = store_->claim("worker", kNow, 60000))
      ASSERT_TRUE(
          store_->record_grade(grade_submission(course_, cache, *s, "worker", kNow), "worker"));
  }
  static std::string right_week1() {
    return "a.normal=" + url_encode("(1, 1, -1)") + "&a.plane=" + url_encode("x + y - z = -6") +
           "&a.z=8";
  }
  static std::string mistaken_week1() {
    return "a.normal=" + url_encode("(1, 1, -1)") + "&a.plane=" + url_encode("x + y - z = 6") +
           "&a.z=-4";
  }

  fs::path dir_;
  StudentAppOptions options_;
  Course course_;
  std::unique_ptr<Store> store_;
  std::unique_ptr<StudentApp> app_;
};

TEST_F(InstructorPages, AnInstructorsLinkOpensTheInstructorsPagesOnly) {
  const Response start = get(std::string("/start?token=") + kProf);
  EXPECT_EQ(start.status, 303);
  EXPECT_EQ(start.header("Location"), "/instructor/");
  const std::string prof = sign_in(kProf);
  EXPECT_EQ(get("/instructor/", prof).status, 200);
  EXPECT_NE(get("/instructor/", prof).body.find("/instructor/set/week1"), std::string::npos);
  EXPECT_NE(get("/instructor/", prof).body.find("href=\"/instructor/author/week1\""),
            std::string::npos);  // each set's authoring page
  // The set's policy as students meet it (week1 states none: everything once graded).
  const std::string page = get("/instructor/set/week1", prof).body;
  EXPECT_NE(page.find("<dt>right answers</dt><dd>once graded</dd>"), std::string::npos) << page;
  EXPECT_NE(page.find("<dt>Attempts</dt><dd>unlimited</dd>"), std::string::npos);
  EXPECT_EQ(get("/", prof).status, 303);  // to /instructor/
  EXPECT_EQ(get("/", prof).header("Location"), "/instructor/");
  EXPECT_EQ(get("/set/week1", prof).status, 403);  // no variant, no submitting
  EXPECT_EQ(post("/api/draft", prof, "").status, 403);
  EXPECT_EQ(get("/favicon.ico", prof).status, 404);
  // An instructor no longer in instructors.csv (read at start) is signed out.
  course_.instructors.clear();
  app_ = std::make_unique<StudentApp>(course_, *store_, options_);
  EXPECT_EQ(get("/instructor/", prof).status, 403);
}

TEST_F(InstructorPages, EveryInstructorRouteRefusesAStudent) {
  const std::string alice = sign_in(kAlice);
  for (const char* target :
       {"/instructor", "/instructor/", "/instructor/set/week1", "/instructor/author/week1",
        "/instructor/set/week1/gradebook.csv", "/instructor/set/week1/canvas.csv",
        "/instructor/set/week1/student/bob", "/instructor/set/varied/copies",
        "/instructor/events?set=week1", "/instructor/nothere"})
    EXPECT_EQ(get(target, alice).status, 403) << target;
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  EXPECT_EQ(post("/instructor/set/week1/regrade", alice, "csrf=" + csrf).status, 403);
  EXPECT_EQ(get("/instructor/", "").status, 403);  // nobody signed in
  // The student's own pages work as before.
  EXPECT_EQ(get("/", alice).status, 200);
  EXPECT_EQ(get("/set/week1", alice).status, 200);
}

TEST_F(InstructorPages, TheClassAtAGlanceCountsVerdictsMediansAndMistakes) {
  submit(kAlice, "week1", "zbuf", mistaken_week1());
  submit(kAlice, "week1", "zbuf", right_week1());
  submit(kBob, "week1", "zbuf", mistaken_week1());
  submit(kCarol, "week1", "zbuf", "a.z=" + url_encode("x+"));  // cannot be read
  grade_pending();
  const ClassView view = read_class(*store_, *course_.find("week1"));
  const std::vector<AnswerCount> counts = answer_counts(view);
  ASSERT_EQ(counts.size(), 4u);  // the problem, then normal, plane, z
  EXPECT_EQ(counts[0].answer, "");
  EXPECT_EQ(counts[0].submitted, 3);
  EXPECT_EQ(counts[0].right, 1);       // alice's second attempt
  EXPECT_EQ(counts[0].partly, 1);      // bob: the normal, z carried
  EXPECT_EQ(counts[0].unreadable, 1);  // carol
  EXPECT_EQ(counts[0].wrong, 0);
  EXPECT_DOUBLE_EQ(counts[0].median_attempts, 1);  // 2, 1, 1
  EXPECT_EQ(counts[2].answer, "plane");
  EXPECT_EQ(counts[2].submitted, 2);
  EXPECT_EQ(counts[2].right, 1);
  EXPECT_EQ(counts[2].wrong, 1);
  EXPECT_DOUBLE_EQ(counts[2].median_attempts, 1.5);
  EXPECT_EQ(counts[3].answer, "z");
  EXPECT_EQ(counts[3].submitted, 3);
  EXPECT_EQ(counts[3].partly, 1);
  EXPECT_EQ(counts[3].unreadable, 1);
  // The named mistake: bob's only (alice corrected hers), on the plane and on the z it gives.
  const std::vector<MistakeRow> mistakes = frequent_mistakes(view, 10);
  ASSERT_EQ(mistakes.size(), 2u);
  EXPECT_EQ(mistakes[0].answer, "plane");
  EXPECT_EQ(mistakes[1].answer, "z");
  for (const MistakeRow& m : mistakes) {
    EXPECT_EQ(m.mistake, "constant on the wrong side");
    EXPECT_EQ(m.students, std::vector<std::string>{"bob"});
  }
  EXPECT_EQ(frequent_mistakes(view, 1).size(), 1u);
  // The page shows them; sorted by score, highest first.
  const std::string prof = sign_in(kProf);
  const std::string page = get("/instructor/set/week1?sort=score&desc=1", prof).body;
  EXPECT_NE(page.find("constant on the wrong side"), std::string::npos);
  EXPECT_NE(page.find("data-events=\"/instructor/events?set=week1"), std::string::npos);
  EXPECT_NE(page.find("/static/instructor.js"), std::string::npos);
  const auto at = [&](const std::string& s) { return page.find("data-student=\"" + s + "\""); };
  EXPECT_LT(at("alice"), at("bob"));
  EXPECT_LT(at("bob"), at("carol"));
}

TEST_F(InstructorPages, TheGradebookIsGradesCsvAndImportsIntoCanvasAndMoodle) {
  submit(kAlice, "week1", "zbuf", right_week1());
  submit(kBob, "week1", "zbuf", mistaken_week1());
  grade_pending();
  const std::string prof = sign_in(kProf);
  const Response csv = get("/instructor/set/week1/gradebook.csv", prof);
  EXPECT_EQ(csv.status, 200);
  EXPECT_EQ(csv.header("Content-Type"), "text/csv; charset=utf-8");
  EXPECT_EQ(csv.body,
            "student,score,max_score,percent,status,zbuf,source,message,file\n"
            "alice,3,3,100.0,graded,3,,,\n"
            "bob,1.5,3,50.0,graded,1.5,,,\n"
            "carol,0,3,0.0,error,,,no submission,\n");
  const std::string canvas = get("/instructor/set/week1/canvas.csv", prof).body;
  EXPECT_NE(canvas.find("Points Possible"), std::string::npos);
  EXPECT_NE(canvas.find("alice"), std::string::npos);
  const std::string moodle = get("/instructor/set/week1/moodle.csv", prof).body;
  EXPECT_EQ(moodle.rfind("ID number,", 0), 0u) << moodle;
  EXPECT_NE(moodle.find("bob,1.5"), std::string::npos) << moodle;
}

TEST_F(InstructorPages, ADrillDownShowsTheAnswersAsWrittenAndTheFeedbackSeen) {
  submit(kBob, "week1", "zbuf", mistaken_week1());
  grade_pending();
  const std::string prof = sign_in(kProf);
  const Response r = get("/instructor/set/week1/student/bob", prof);
  EXPECT_EQ(r.status, 200);
  EXPECT_NE(r.body.find("x + y - z = 6"), std::string::npos);               // as written
  EXPECT_NE(r.body.find("constant on the wrong side"), std::string::npos);  // the feedback
  EXPECT_NE(r.body.find(course_.find("week1")->version.substr(0, 12)), std::string::npos);
  EXPECT_NE(r.body.find("worker"), std::string::npos);  // who graded it
  EXPECT_EQ(get("/instructor/set/week1/student/nobody", prof).status, 404);
}

TEST_F(InstructorPages, EventsSayWhenTheClassChanged) {
  const std::string prof = sign_in(kProf);
  const std::int64_t mark = store_->change_mark();
  const Response idle = get("/instructor/events?set=week1&mark=" + std::to_string(mark), prof);
  EXPECT_EQ(idle.status, 200);
  EXPECT_EQ(idle.header("Content-Type"), "text/event-stream; charset=utf-8");
  EXPECT_EQ(idle.body.find("event: change"), std::string::npos);
  EXPECT_NE(idle.body.find("id: " + std::to_string(mark) + "\n"), std::string::npos);
  submit(kAlice, "week1", "zbuf", "a.z=8");
  Request r = request("GET", "/instructor/events?set=week1", prof);
  r.headers.emplace_back("last-event-id", std::to_string(mark));  // the browser's reconnect
  const Response moved = handle_student(*app_, r, kNow);
  EXPECT_NE(moved.body.find("event: change"), std::string::npos);
  EXPECT_NE(moved.body.find("id: " + std::to_string(store_->change_mark())), std::string::npos);
}

TEST_F(InstructorPages, ARegradeShowsWhatChangesThenAppliesItKeepingHistory) {
  submit(kAlice, "week1", "zbuf", right_week1());
  submit(kBob, "week1", "zbuf", "a.z=7");
  grade_pending();
  const std::string prof = sign_in(kProf);
  const std::string csrf = csrf_of(get("/instructor/set/week1", prof).body);
  // Without the token, or from another site: refused.
  EXPECT_EQ(post("/instructor/set/week1/regrade", prof, "problem=zbuf").status, 403);
  {
    Request r = request("POST", "/instructor/set/week1/regrade", prof, "csrf=" + csrf);
    r.headers.back().second = "http://evil.example";
    EXPECT_EQ(handle_student(*app_, r, kNow).status, 403);
  }
  // Nothing changed yet: a dry run lists no one.
  const Response same = post("/instructor/set/week1/regrade", prof, "csrf=" + csrf);
  EXPECT_EQ(same.status, 200);
  EXPECT_NE(same.body.find(kNoChanges.in(Lang::En)), std::string::npos);
  // The key moves: pixel (1, 0) has z = 7.
  std::string text = kWeek1;
  text.replace(text.find("pixel: [1, 1]"), 13, "pixel: [1, 0]");
  std::ofstream(dir_ / "week1.yaml") << text;
  const Response dry =
      post("/instructor/set/week1/regrade", prof, "csrf=" + csrf + "&problem=zbuf");
  EXPECT_EQ(dry.status, 200);
  std::smatch row;
  ASSERT_TRUE(std::regex_search(
      dry.body, row,
      std::regex("data-student=\"alice\" data-problem=\"zbuf\">.*?class=\"before\">3</td>"
                 "<td class=\"after\">2</td>")));
  ASSERT_TRUE(std::regex_search(
      dry.body, row,
      std::regex("data-student=\"bob\" data-problem=\"zbuf\">.*?class=\"before\">0</td>"
                 "<td class=\"after\">1</td>")));
  EXPECT_NE(dry.body.find("<code>z</code>: Correct → Incorrect"), std::string::npos);
  // A dry run writes nothing.
  const auto alices = store_->submissions("alice", "week1").at(0).id;
  EXPECT_EQ(store_->grade_history(alices).size(), 1u);
  std::smatch version;
  ASSERT_TRUE(std::regex_search(dry.body, version,
                                std::regex("name=\"version\" value=\"([0-9a-f]{64})\"")));
  // Apply against another version than the dry run's: refused, nothing written.
  EXPECT_EQ(post("/instructor/set/week1/regrade", prof,
                 "csrf=" + csrf + "&problem=zbuf&apply=1&version=" + std::string(64, '0'))
                .status,
            409);
  EXPECT_EQ(store_->grade_history(alices).size(), 1u);
  const Response applied =
      post("/instructor/set/week1/regrade", prof,
           "csrf=" + csrf + "&problem=zbuf&apply=1&version=" + version[1].str());
  EXPECT_EQ(applied.status, 200);
  const std::vector<GradeRecord> history = store_->grade_history(alices);
  ASSERT_EQ(history.size(), 2u);
  EXPECT_DOUBLE_EQ(history[0].score, 3);
  EXPECT_DOUBLE_EQ(history[1].score, 2);
  EXPECT_EQ(history[0].set_version, course_.find("week1")->version);
  EXPECT_EQ(history[1].set_version, version[1].str());
  EXPECT_EQ(history[1].graded_by, "instructor:prof");
  EXPECT_EQ(history[1].graded, kNow);
  const auto bobs = store_->submissions("bob", "week1").at(0).id;
  EXPECT_DOUBLE_EQ(store_->latest_grade(bobs)->score, 1);
  // A broken set file: nothing regraded, its error located.
  std::ofstream(dir_ / "week1.yaml") << "problems: [";
  const Response broken = post("/instructor/set/week1/regrade", prof, "csrf=" + csrf);
  EXPECT_EQ(broken.status, 409);
  EXPECT_NE(broken.body.find("week1.yaml"), std::string::npos);
}

TEST_F(InstructorPages, AnswersThatFitAnotherStudentsVariantAreFlagged) {
  // bob's key, written by alice; bob's own right answers; carol's own wrong ones.
  const ProblemSet& bobs = *course_.find("varied")->for_student("bob");
  const SolvedSet solved = solve_for_grading(bobs);
  std::string copied;
  for (const auto& [name, value] : solved.results.at(0).answers.items())
    copied += (copied.empty() ? "" : "&") + ("a." + name + "=" + url_encode(written(value)));
  submit(kAlice, "varied", "bf", copied);
  submit(kBob, "varied", "bf", copied);
  submit(kCarol, "varied", "bf", "a.df=123456&a.facing=edge_on");
  grade_pending();
  const std::string prof = sign_in(kProf);
  const Response r = get("/instructor/set/varied/copies", prof);
  EXPECT_EQ(r.status, 200);
  EXPECT_NE(r.body.find("data-student=\"alice\" data-fits=\"bob\""), std::string::npos) << r.body;
  EXPECT_EQ(r.body.find("data-student=\"bob\""), std::string::npos);
  EXPECT_EQ(r.body.find("data-student=\"carol\""), std::string::npos);
  // Never in a student's view.
  EXPECT_EQ(get("/set/varied", sign_in(kAlice)).body.find("bob"), std::string::npos);
}

TEST_F(InstructorPages, InstructorsCsvIsReadWithItsErrorsLocated) {
  std::ofstream(dir_ / "instructors.csv") << "name,instructor\nDr X,prof\n,\nDr Y,ta1\n";
  EXPECT_EQ(read_instructors((dir_ / "instructors.csv").string()),
            (std::vector<std::string>{"prof", "ta1"}));
  std::ofstream(dir_ / "twice.csv") << "instructor\nprof\nPROF\n";
  try {
    read_instructors((dir_ / "twice.csv").string());
    FAIL() << "a repeated instructor was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.diagnostic().where.line, 3);
  }
  std::ofstream(dir_ / "none.csv") << "student\nprof\n";
  EXPECT_THROW(read_instructors((dir_ / "none.csv").string()), InputError);
}

TEST(InstructorPhrases, EveryPhraseHasJapaneseAndRussianWithoutEnglish) {
  expect_three_languages(kAllInstructorPagePhrases);
}

}  // namespace
}  // namespace frustum::server
