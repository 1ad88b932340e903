// The student side of `frustum serve`, handler by handler, without sockets: links and sessions,
// each student's own variant, previews that read but never judge, submissions committed before
// they are acknowledged, grading with the named mistake and carried credit, the set's feedback
// policy, and every refusal (another student's pages, CSRF, Origin, rate limits, escaping).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include "serve_test_sets.hpp"
#include "server/clock.hpp"
#include "server/given_tex.hpp"
#include "server/grade_job.hpp"
#include "server/phrases.hpp"
#include "server/session.hpp"
#include "server/student_app.hpp"
#include "server/tokens.hpp"
#include "solver/problem/serve_policy.hpp"
#include "solver/problem/variants.hpp"

namespace frustum::server {
namespace {

namespace fs = std::filesystem;
using namespace frustum::server::test;  // NOLINT: the shared sets and helpers
using Json = nlohmann::json;

// A problem with a figure.
constexpr const char* kSort = R"(problems:
  - id: sort
    kind: depth_sort
    given:
      polygons:
        - [[-2, -1, -6], [2, -1, -6], [2, 1, -6], [-2, 1, -6]]
        - [[-1, -2, -8], [1, -2, -8], [1, 2, -4], [-1, 2, -4]]
      eye: [0, 0, 0]
)";

constexpr Millis kNow = 1'800'000'000'000;

class StudentPages : public ::testing::Test {
 protected:
  void SetUp() override { make_course({{"week1", kWeek1}, {"varied", kVaried}, {"sort", kSort}}); }

  void make_course(const std::vector<std::pair<std::string, std::string>>& sets) {
    dir_ = fs::temp_directory_path() /
           ("frustum-serve-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (const auto& [name, text] : sets) std::ofstream(dir_ / (name + ".yaml")) << text;
    course_ = load_course(dir_.string(), {"alice", "bob"});
    ASSERT_TRUE(course_.errors.empty()) << course_.errors.front().format();
    store_ = open_store("sqlite:" + (dir_ / "serve.sqlite").string());
    app_ = std::make_unique<StudentApp>(course_, *store_, options_);
    store_->put_student("alice", sha256_hex(kAlice));
    store_->put_student("bob", sha256_hex(kBob));
  }

  Response get(const std::string& target, const std::string& cookie = "", Millis now = kNow) {
    Request r{"GET", target, {{"host", "127.0.0.1:8080"}}, "", "127.0.0.1"};
    if (!cookie.empty())
      r.headers.emplace_back("cookie", std::string(kSessionCookie) + "=" + cookie);
    return handle_student(*app_, r, now);
  }
  Response post(const std::string& target, const std::string& cookie, const std::string& body,
                const std::string& origin = "http://127.0.0.1:8080", Millis now = kNow) {
    Request r{"POST", target, {{"host", "127.0.0.1:8080"}}, body, "127.0.0.1"};
    r.headers.emplace_back("cookie", std::string(kSessionCookie) + "=" + cookie);
    if (!origin.empty()) r.headers.emplace_back("origin", origin);
    return handle_student(*app_, r, now);
  }
  // Signs in with the link's token; returns the session cookie's value.
  std::string sign_in(const std::string& token) {
    return session_cookie(get("/start?token=" + token));
  }
  std::string csrf_of(const std::string& page) { return csrf_in(page); }
  void grade_pending() {
    SolvedCache cache;
    while (const auto s = store_->claim("test", kNow, 60000))
      ASSERT_TRUE(store_->record_grade(grade_submission(course_, cache, *s, "test", kNow), "test"));
  }

  static constexpr const char* kAlice = "0123456789abcdef0123456789abcdef";
  static constexpr const char* kBob = "fedcba9876543210fedcba9876543210";
  fs::path dir_;
  StudentAppOptions options_;
  Course course_;
  std::unique_ptr<Store> store_;
  std::unique_ptr<StudentApp> app_;
};

TEST_F(StudentPages, TheLinkBecomesAStrictCookieAndLeavesTheUrl) {
  const Response r = get(std::string("/start?token=") + kAlice);
  EXPECT_EQ(r.status, 303);
  EXPECT_EQ(r.header("Location"), "/");
  const std::string cookie = r.header("Set-Cookie").value_or("");
  EXPECT_NE(cookie.find("HttpOnly"), std::string::npos);
  EXPECT_NE(cookie.find("SameSite=Strict"), std::string::npos);
  EXPECT_EQ(cookie.find("Secure"), std::string::npos);
  EXPECT_EQ(cookie.find(kAlice), std::string::npos);  // the session is not the link's token
  const std::string session = sign_in(kAlice);
  EXPECT_EQ(get("/", session).status, 200);
  EXPECT_NE(get("/", session).body.find("/set/week1"), std::string::npos);
}

TEST_F(StudentPages, SecureCookiesBehindTls) {
  options_.secure_cookies = true;
  app_ = std::make_unique<StudentApp>(course_, *store_, options_);
  EXPECT_NE(get(std::string("/start?token=") + kAlice).header("Set-Cookie")->find("; Secure"),
            std::string::npos);
}

TEST_F(StudentPages, UnknownOrRotatedLinksAndNoSessionAreRefused) {
  EXPECT_EQ(get("/start?token=00000000000000000000000000000000").status, 404);
  EXPECT_EQ(get("/start?token=short").status, 404);
  store_->put_student("alice", sha256_hex("11111111111111111111111111111111"));  // rotated
  EXPECT_EQ(get(std::string("/start?token=") + kAlice).status, 404);
  EXPECT_EQ(get("/set/week1").status, 403);
  EXPECT_EQ(get("/set/week1", "0123456789abcdef0123456789abcdef").status, 403);
  EXPECT_NE(get("/").body.find(kSignInFirst.in(Lang::En)), std::string::npos);
}

TEST_F(StudentPages, EachStudentSeesTheVariantThatGenerateDraws) {
  const std::string alice = sign_in(kAlice), bob = sign_in(kBob);
  const std::vector<ProblemSet> drawn =
      variants_for_class(course_.find("varied")->set, {"alice", "bob"}, false);
  const auto points = [](const ProblemSet& v) {
    return given_plain(v.problems[0].given_node["points"]);
  };
  const std::string a = get("/set/varied", alice).body, b = get("/set/varied", bob).body;
  EXPECT_NE(a.find(points(drawn[0])), std::string::npos) << points(drawn[0]);
  EXPECT_NE(b.find(points(drawn[1])), std::string::npos) << points(drawn[1]);
  EXPECT_EQ(a.find(points(drawn[1])), std::string::npos);
  EXPECT_EQ(course_.find("varied")->variant_id("alice"), "student:alice");
}

TEST_F(StudentPages, ThePreviewReadsButNeverJudges) {
  const std::string alice = sign_in(kAlice);
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  const auto preview = [&](const std::string& answer, const std::string& text) {
    const Response r = post(
        "/api/preview", alice,
        "csrf=" + csrf + "&set=week1&problem=zbuf&answer=" + answer + "&text=" + url_encode(text));
    EXPECT_EQ(r.status, 200);
    return Json::parse(r.body);
  };
  const Json right = preview("plane", "x + y - z = -6");
  const Json wrong = preview("plane", "x + y - z = 6");
  EXPECT_TRUE(right["ok"]);
  // A plane is read back as its equation, whichever form the student wrote.
  EXPECT_EQ(right["tex"], "x + y - z = -6");
  EXPECT_EQ(wrong["tex"], "x + y - z = 6");
  EXPECT_EQ(preview("plane", "[2, 2, -2, -12]")["tex"], "2x + 2y - 2z = -12");
  std::vector<std::string> right_keys, wrong_keys;
  for (const auto& [k, v] : right.items()) right_keys.push_back(k);
  for (const auto& [k, v] : wrong.items()) wrong_keys.push_back(k);
  EXPECT_EQ(right_keys, wrong_keys);  // nothing says which is right
  const Json junk = preview("z", "8++");
  EXPECT_FALSE(junk["ok"]);
  EXPECT_NE(junk["error"].get<std::string>().find("8++"), std::string::npos);
  EXPECT_EQ(
      post("/api/preview", alice, "csrf=" + csrf + "&set=week1&problem=zbuf&answer=secret&text=1")
          .status,
      404);
}

// Handlers run on many threads and GiNaC is not thread-safe: previews (exact numbers) from
// several threads at once must neither crash nor disagree.
TEST_F(StudentPages, PreviewsFromManyThreadsAtOnce) {
  options_.preview_burst = 1e9;
  app_ = std::make_unique<StudentApp>(course_, *store_, options_);
  const std::string alice = sign_in(kAlice);
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  const auto preview = [&](int n) {
    return post("/api/preview", alice,
                "csrf=" + csrf + "&set=week1&problem=zbuf&answer=plane&text=" +
                    url_encode("x/3 + y - z = " + std::to_string(n) + "/7"))
        .body;
  };
  constexpr int kThreads = 6, kEach = 150;
  std::vector<std::string> alone;
  for (int n = 0; n < kThreads * kEach; ++n) alone.push_back(preview(n));
  EXPECT_NE(alone[1].find("\\frac{1}{7}"), std::string::npos) << alone[1];
  std::atomic<int> same{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < kEach; ++i) same += preview(t * kEach + i) == alone[t * kEach + i];
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(same.load(), kThreads * kEach);
}

TEST_F(StudentPages, PostsNeedTheSessionsCsrfTokenAndThisOrigin) {
  const std::string alice = sign_in(kAlice), bob = sign_in(kBob);
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  const std::string bob_csrf = csrf_of(get("/set/week1", bob).body);
  const std::string body = "problem=zbuf&a.z=8&csrf=";
  EXPECT_EQ(post("/set/week1/submit", alice, body).status, 403);
  EXPECT_EQ(post("/set/week1/submit", alice, body + bob_csrf).status, 403);
  EXPECT_EQ(post("/set/week1/submit", alice, body + csrf, "http://evil.example").status, 403);
  EXPECT_TRUE(store_->submissions("alice", "week1").empty());
  EXPECT_EQ(post("/set/week1/submit", alice, body + csrf).status, 303);
  EXPECT_EQ(store_->submissions("alice", "week1").size(), 1u);
}

TEST_F(StudentPages, ASubmissionIsStoredBeforeItIsAcknowledged) {
  const std::string alice = sign_in(kAlice);
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  const Response r = post("/set/week1/submit", alice,
                          "csrf=" + csrf + "&problem=zbuf&a.plane=" + url_encode("x + y - z = 6") +
                              "&a.z=-4&a.normal=");
  EXPECT_EQ(r.status, 303);
  EXPECT_EQ(r.header("Location"), "/set/week1#p-zbuf");
  const auto mine = store_->submissions("alice", "week1");
  ASSERT_EQ(mine.size(), 1u);
  EXPECT_EQ(Json::parse(mine[0].answers), (Json{{"plane", "x + y - z = 6"}, {"z", "-4"}}));
  EXPECT_EQ(mine[0].set_version, course_.find("week1")->version);
  EXPECT_EQ(mine[0].set_version.size(), 64u);
  EXPECT_EQ(mine[0].received, kNow);
  // Pending until a worker grades it: the page says so and refreshes itself.
  const std::string pending = get("/set/week1", alice).body;
  EXPECT_NE(pending.find("data-state=\"pending\""), std::string::npos);
  EXPECT_NE(pending.find("http-equiv=\"refresh\""), std::string::npos);
  // The answers stay in the inputs.
  EXPECT_NE(pending.find("value=\"x + y - z = 6\""), std::string::npos);
}

TEST_F(StudentPages, GradedFeedbackNamesTheMistakeAndTheCarriedCredit) {
  const std::string alice = sign_in(kAlice);
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  post("/set/week1/submit", alice,
       "csrf=" + csrf + "&problem=zbuf&a.normal=" + url_encode("(1, 1, -1)") +
           "&a.plane=" + url_encode("x + y - z = 6") + "&a.z=-4");
  grade_pending();
  const auto s = store_->submissions("alice", "week1").at(0);
  const Json result = Json::parse(store_->latest_grade(s.id)->result);
  const Json& plane = result["answers"][1];
  const Json& z = result["answers"][2];
  EXPECT_EQ(plane["verdict"], "incorrect");
  EXPECT_EQ(plane["mistake"], "constant on the wrong side");
  EXPECT_EQ(z["verdict"], "partial");
  EXPECT_TRUE(z["carried_forward"]);
  EXPECT_EQ(z["carried_from"][0]["name"], "plane");
  EXPECT_EQ(z["carried_from"][0]["text"], "x + y - z = 6");
  EXPECT_DOUBLE_EQ(store_->latest_grade(s.id)->score, 1.5);
  const std::string page = get("/set/week1", alice).body;
  EXPECT_NE(page.find("constant on the wrong side"), std::string::npos);
  EXPECT_NE(page.find(kCarried.in(Lang::En)), std::string::npos);
  EXPECT_NE(page.find("class=\"steps\""), std::string::npos);  // the derivation
  EXPECT_NE(page.find("1.5 / 3"), std::string::npos);
}

TEST_F(StudentPages, NoStudentReachesAnothersPages) {
  const std::string alice = sign_in(kAlice), bob = sign_in(kBob);
  const std::string csrf = csrf_of(get("/set/week1", bob).body);
  post("/set/week1/submit", bob, "csrf=" + csrf + "&problem=zbuf&a.z=8");
  const std::int64_t bobs = store_->submissions("bob", "week1").at(0).id;
  EXPECT_EQ(get("/set/week1/submission/" + std::to_string(bobs), bob).status, 200);
  EXPECT_EQ(get("/set/week1/submission/" + std::to_string(bobs), alice).status, 404);
  EXPECT_EQ(get("/set/varied/submission/" + std::to_string(bobs), bob).status, 404);
  EXPECT_EQ(get("/set/nothere", alice).status, 404);
  EXPECT_EQ(get("/set/week1/figure/nothere.svg", alice).status, 404);
  EXPECT_EQ(get("/set/week1/figure/zbuf.svg", alice).status, 404);  // nothing to draw
  // The figure shows the answers: only with the feedback, once a submission is graded.
  EXPECT_EQ(get("/set/sort/figure/sort.svg", alice).status, 404);
  EXPECT_EQ(get("/set/sort", alice).body.find("figure/sort.svg"), std::string::npos);
  const std::string sort_csrf = csrf_of(get("/set/sort", alice).body);
  post("/set/sort/submit", alice,
       "csrf=" + sort_csrf + "&problem=sort&a.order=" + url_encode("1 0"));
  grade_pending();
  const Response figure = get("/set/sort/figure/sort.svg", alice);
  EXPECT_EQ(figure.status, 200);
  EXPECT_NE(figure.body.find("<svg"), std::string::npos);
  EXPECT_EQ(figure.header("Content-Type"), "image/svg+xml");
  EXPECT_NE(get("/set/sort", alice).body.find("figure/sort.svg"), std::string::npos);
  EXPECT_EQ(get("/set/sort/figure/sort.svg", bob).status, 404);  // bob has submitted nothing
}

TEST_F(StudentPages, PreviewsAndSubmissionsAreRateLimitedPerSession) {
  const std::string alice = sign_in(kAlice), bob = sign_in(kBob);
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  const std::string body = "csrf=" + csrf + "&set=week1&problem=zbuf&answer=z&text=8";
  int refused = 0;
  for (int i = 0; i < 40; ++i) {
    const Response r = post("/api/preview", alice, body);
    if (r.status == 429) {
      ++refused;
      EXPECT_EQ(r.header("Retry-After"), "1");
    }
  }
  EXPECT_EQ(refused, 40 - static_cast<int>(options_.preview_burst));
  // Another session is not slowed; the same one is served again a second later.
  const std::string bob_csrf = csrf_of(get("/set/week1", bob).body);
  EXPECT_EQ(
      post("/api/preview", bob, "csrf=" + bob_csrf + "&set=week1&problem=zbuf&answer=z&text=8")
          .status,
      200);
  EXPECT_EQ(post("/api/preview", alice, body, "http://127.0.0.1:8080", kNow + 1000).status, 200);
}

TEST_F(StudentPages, WhatAStudentTypesIsEscapedAndTheCspIsStrict) {
  const std::string alice = sign_in(kAlice);
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  const std::string evil = "\"><script>alert(1)</script>";
  EXPECT_EQ(post("/api/draft", alice,
                 "csrf=" + csrf + "&set=week1&problem=zbuf&answer=z&text=" + url_encode(evil))
                .status,
            200);
  const Response page = get("/set/week1", alice);
  EXPECT_EQ(page.body.find("<script>alert"), std::string::npos);
  EXPECT_NE(page.body.find("&quot;&gt;&lt;script&gt;alert(1)"), std::string::npos);
  const std::string csp = page.header("Content-Security-Policy").value_or("");
  EXPECT_NE(csp.find("script-src 'self';"), std::string::npos);
  EXPECT_NE(csp.find("style-src-attr 'unsafe-inline'"), std::string::npos);
  EXPECT_EQ(csp.find("script-src 'self' 'unsafe-inline'"), std::string::npos);
  EXPECT_EQ(page.body.find("<script>"), std::string::npos);  // no inline script at all
  EXPECT_EQ(page.body.find(" style=\""), std::string::npos);
}

TEST_F(StudentPages, DraftsAreKeptAndTheLastOneShows) {
  const std::string alice = sign_in(kAlice);
  const std::string csrf = csrf_of(get("/set/week1", alice).body);
  const std::string body = "csrf=" + csrf + "&set=week1&problem=zbuf&answer=z&text=";
  post("/api/draft", alice, body + "7", "http://127.0.0.1:8080", kNow);
  post("/api/draft", alice, body + "8", "http://127.0.0.1:8080", kNow + 10);
  EXPECT_NE(get("/set/week1", alice).body.find("name=\"a.z\" value=\"8\""), std::string::npos);
  EXPECT_EQ(get("/set/week1", sign_in(kBob)).body.find("name=\"a.z\" value=\"8\""),
            std::string::npos);
}

TEST_F(StudentPages, ThePolicyLimitsAttemptsDeadlineAndFeedback) {
  make_course({{"strict", std::string("attempts: 1\nfeedback: never\n") + kWeek1},
               {"late", std::string("deadline: 2020-01-01T00:00:00+09:00\n") + kWeek1}});
  const std::string alice = sign_in(kAlice);
  const std::string csrf = csrf_of(get("/set/strict", alice).body);
  EXPECT_EQ(post("/set/strict/submit", alice, "csrf=" + csrf + "&problem=zbuf&a.z=6").status, 303);
  EXPECT_EQ(post("/set/strict/submit", alice, "csrf=" + csrf + "&problem=zbuf&a.z=8").status, 403);
  grade_pending();
  const std::string page = get("/set/strict", alice).body;
  EXPECT_NE(page.find(kFeedbackLater.in(Lang::En)), std::string::npos);
  EXPECT_EQ(page.find("verdict-incorrect"), std::string::npos);
  EXPECT_NE(page.find(kNoAttemptsLeft.in(Lang::En)), std::string::npos);
  EXPECT_EQ(post("/set/late/submit", alice, "csrf=" + csrf + "&problem=zbuf&a.z=8").status, 403);
  EXPECT_EQ(store_->submissions("alice", "late").size(), 0u);
}

// Each part of the feedback when the set says (kNow is 2027-01-15T08:00:00Z): the verdicts at
// once, the named mistakes from the second attempt, the points never, the key and the
// derivation after the student's own deadline — bob's, extended, comes two days later than
// alice's, and he may still submit when she may not.
TEST_F(StudentPages, EachPartOfTheFeedbackShowsWhenThePolicySays) {
  make_course({{"parts", std::string("deadline: 2027-01-16T08:00:00Z\n"
                                     "extensions: {bob: 2027-01-18T08:00:00Z}\n"
                                     "feedback: {mistakes: {attempts: 2}, credit: never, "
                                     "key: deadline, derivation: submit}\n"
                                     "attempts: 3\npenalty: 25%\n") +
                             kWeek1}});
  constexpr Millis kDay = 86'400'000;
  const std::string alice = sign_in(kAlice), bob = sign_in(kBob);
  const std::string csrf = csrf_of(get("/set/parts", alice).body);
  const std::string wrong =
      "csrf=" + csrf + "&problem=zbuf&a.plane=" + url_encode("x + y - z = 6") + "&a.z=-4";
  ASSERT_EQ(post("/set/parts/submit", alice, wrong).status, 303);
  grade_pending();
  std::string page = get("/set/parts", alice).body;
  EXPECT_NE(page.find("verdict-incorrect"), std::string::npos);           // verdicts: submit
  EXPECT_EQ(page.find("constant on the wrong side"), std::string::npos);  // mistakes: 2 attempts
  EXPECT_EQ(page.find("class=\"points\""), std::string::npos);            // credit: never
  EXPECT_EQ(page.find("1.5 / 3"), std::string::npos);
  EXPECT_EQ(page.find("class=\"key\""), std::string::npos);  // key: after the deadline
  // The derivation ends at the right answer: it waits for the key, whatever it says itself.
  EXPECT_EQ(page.find("class=\"steps\""), std::string::npos);
  EXPECT_NE(page.find("25%"), std::string::npos);  // the penalty is stated before submitting
  EXPECT_NE(page.find("2027-01-16T08:00:00Z"), std::string::npos);

  ASSERT_EQ(post("/set/parts/submit", alice, wrong).status, 303);
  grade_pending();
  page = get("/set/parts", alice).body;
  EXPECT_NE(page.find("constant on the wrong side"), std::string::npos);
  EXPECT_EQ(page.find("class=\"key\""), std::string::npos);

  // After alice's deadline: no more submissions; the key (the plane x + y − z = −6) and the
  // derivation show.
  const Millis later = kNow + 2 * kDay;
  EXPECT_EQ(post("/set/parts/submit", alice, wrong, "http://127.0.0.1:8080", later).status, 403);
  page = get("/set/parts", alice, later).body;
  EXPECT_NE(page.find("class=\"key\""), std::string::npos);
  EXPECT_NE(page.find("x + y − z = −6"), std::string::npos);
  EXPECT_NE(page.find("class=\"steps\""), std::string::npos);
  EXPECT_EQ(page.find("1.5 / 3"), std::string::npos);  // credit stays hidden

  // Bob's extension: his deadline on his page, his submission taken, his key not yet shown.
  const std::string bob_csrf = csrf_of(get("/set/parts", bob).body);
  EXPECT_NE(get("/set/parts", bob).body.find("2027-01-18T08:00:00Z"), std::string::npos);
  EXPECT_EQ(post("/set/parts/submit", bob, "csrf=" + bob_csrf + "&problem=zbuf&a.z=-4",
                 "http://127.0.0.1:8080", later)
                .status,
            303);
  grade_pending();
  page = get("/set/parts", bob, later).body;
  EXPECT_NE(page.find("verdict-incorrect"), std::string::npos);
  EXPECT_EQ(page.find("class=\"key\""), std::string::npos);
  EXPECT_NE(get("/set/parts", bob, kNow + 4 * kDay).body.find("class=\"key\""), std::string::npos);
}

// A further attempt is credited less by the penalty: the page says what is credited, the
// gradebook counts it.
TEST_F(StudentPages, APenaltyCreditsEachFurtherAttemptLess) {
  make_course({{"penalised", std::string("penalty: 25%\n") + kWeek1}});
  const std::string alice = sign_in(kAlice);
  const std::string csrf = csrf_of(get("/set/penalised", alice).body);
  const std::string right = "csrf=" + csrf + "&problem=zbuf&a.normal=" + url_encode("(1, 1, -1)") +
                            "&a.plane=" + url_encode("x + y - z = -6") + "&a.z=8";
  post("/set/penalised/submit", alice, "csrf=" + csrf + "&problem=zbuf&a.z=-4");
  grade_pending();
  EXPECT_EQ(get("/set/penalised", alice).body.find("class=\"credited\""), std::string::npos);
  post("/set/penalised/submit", alice, right);
  grade_pending();
  const std::string page = get("/set/penalised", alice).body;
  EXPECT_NE(page.find("3 / 3"), std::string::npos);
  EXPECT_NE(page.find(std::string(kCreditedAfterPenalty.in(Lang::En)) + " (" +
                      std::string(kAttempt.in(Lang::En)) + " 2): 2.25 / 3"),
            std::string::npos)
      << page;
}

TEST_F(StudentPages, AnExtensionForSomeoneNotOnTheRosterKeepsTheSetFromBeingServed) {
  fs::create_directories(fs::temp_directory_path() / "frustum-serve-extension");
  const fs::path dir = fs::temp_directory_path() / "frustum-serve-extension";
  std::ofstream(dir / "hw.yaml") << "deadline: 2027-01-16T08:00:00Z\n"
                                    "extensions: {alcie: 2027-01-18T08:00:00Z}\n"
                                 << kWeek1;
  const Course course = load_course(dir.string(), {"alice", "bob"});
  fs::remove_all(dir);
  EXPECT_EQ(course.find("hw"), nullptr);
  ASSERT_EQ(course.errors.size(), 1u);
  EXPECT_EQ(course.errors[0].field, "extensions.alcie");
  EXPECT_EQ(course.errors[0].where.line, 2);
}

TEST_F(StudentPages, StaticFilesComeFromTheBinary) {
  const Response js = get("/static/page.js");
  EXPECT_EQ(js.status, 200);
  EXPECT_EQ(js.header("Content-Type"), "text/javascript; charset=utf-8");
  EXPECT_NE(js.body.find("trust: false"), std::string::npos);
  EXPECT_NE(js.body.find("strict: 'error'"), std::string::npos);
  const Response katex = get("/static/katex/katex.min.js");
  EXPECT_EQ(katex.status, 200);
  EXPECT_GT(katex.body.size(), 100000u);
  EXPECT_EQ(get("/static/../../etc/passwd").status, 404);
}

TEST(ServePolicy, DatesNeedAnOffset) {
  EXPECT_EQ(parse_iso8601("1970-01-01T00:00:00Z"), 0);
  EXPECT_EQ(parse_iso8601("1970-01-01T09:00+09:00"), 0);
  EXPECT_EQ(parse_iso8601("2026-12-10T23:59:00+09:00"), 1796914740000);
  EXPECT_FALSE(parse_iso8601("2026-12-10T23:59:00"));
  EXPECT_FALSE(parse_iso8601("2026-13-10T23:59:00Z"));
  EXPECT_FALSE(parse_iso8601("tomorrow"));
}

TEST(ServePolicy, BadKeysAreLocatedErrors) {
  const ProblemSet bad = load_problem_set_from_string(
      std::string("deadline: 2026-12-10 23:59\n") + kWeek1, "bad.yaml");
  ASSERT_EQ(bad.errors.size(), 1u);
  EXPECT_EQ(bad.errors[0].field, "deadline");
  EXPECT_EQ(bad.errors[0].where.line, 1);
  const ProblemSet worse = load_problem_set_from_string(
      std::string("feedback: {after: lunch}\n") + kWeek1, "worse.yaml");
  ASSERT_EQ(worse.errors.size(), 1u);
  EXPECT_EQ(worse.errors[0].field, "feedback.after");
  const ProblemSet zero =
      load_problem_set_from_string(std::string("attempts: 0\n") + kWeek1, "zero.yaml");
  ASSERT_EQ(zero.errors.size(), 1u);
  EXPECT_EQ(zero.errors[0].field, "attempts");
  ServePolicy p = read_serve_policy(YAML::Load("feedback: {attempts: 2}"), "x");
  EXPECT_FALSE(p.shown("alice", 1, 0).any());
  EXPECT_TRUE(p.shown("alice", 2, 0).derivation);
  // Each part's own when, checked and located like the rest.
  const auto error_of = [](const std::string& yaml) {
    const ProblemSet set = load_problem_set_from_string(yaml + kWeek1, "policy.yaml");
    return set.errors.empty() ? Diagnostic{} : set.errors[0];
  };
  EXPECT_EQ(error_of("feedback: {key: deadline}\n").field, "feedback.key");  // no deadline
  EXPECT_EQ(error_of("feedback: {keys: submit}\n").field, "feedback.keys");
  EXPECT_EQ(error_of("deadline: 2027-01-16T08:00:00Z\nfeedback: {credit: soon}\n").field,
            "feedback.credit");
  EXPECT_EQ(error_of("penalty: 150%\n").field, "penalty");
  EXPECT_EQ(error_of("penalty: -0.1\n").field, "penalty");
  EXPECT_EQ(error_of("extensions: {alice: 2027-01-18T08:00:00Z}\n").field, "extensions");
  EXPECT_EQ(error_of("deadline: 2027-01-16T08:00:00Z\nextensions: {alice: soon}\n").field,
            "extensions.alice");
  EXPECT_EQ(error_of("deadline: 2027-01-16T08:00:00Z\nextensions: {alice: soon}\n").where.line, 2);
  EXPECT_EQ(error_of("penalty: 0.1\nfeedback: {after: submit}\n").field, "");
  const ServePolicy q = read_serve_policy(
      YAML::Load("penalty: 0.25\ndeadline: 2027-01-16T08:00:00Z\nfeedback: {key: deadline}"), "x");
  EXPECT_DOUBLE_EQ(q.credit_factor(1), 1.0);
  EXPECT_DOUBLE_EQ(q.credit_factor(2), 0.75);
  EXPECT_DOUBLE_EQ(q.credit_factor(9), 0.0);  // never below nothing
  EXPECT_TRUE(q.shown("alice", 1, 0).verdicts);
  EXPECT_FALSE(q.shown("alice", 1, 0).key);
  EXPECT_FALSE(q.shown("alice", 1, 0).derivation);  // it would give the key away
  EXPECT_TRUE(q.shown("alice", 1, *parse_iso8601("2027-01-16T08:00:01Z")).derivation);
}

TEST(ServePhrases, EveryPhraseHasJapaneseAndRussianWithoutEnglish) {
  expect_three_languages(kAllStudentPagePhrases);
}

}  // namespace
}  // namespace frustum::server
