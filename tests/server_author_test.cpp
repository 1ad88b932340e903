// The authoring page of `frustum serve`, handler by handler: instructors only, the file and its
// version, previews made by a child process of the built binary (errors at their line and
// column, statements in every language, key, derivation, figure, a student's variant), saving
// atomically with the previous version kept, 409 when the file changed, 422 when check fails
// (unless saved with errors), CSRF and Origin.
#include <gtest/gtest.h>
#include <openssl/evp.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "server/author_phrases.hpp"
#include "server/given_tex.hpp"
#include "server/session.hpp"
#include "server/student_app.hpp"
#include "server/tokens.hpp"
#include "test_util.hpp"

namespace frustum::server {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr const char* kWeek1 = R"(title: {en: "Depth", ja: "奥行き", ru: "Глубина"}
problems:
  - id: zbuf
    kind: depth_at_pixel
    text:
      en: "Find the z value of pixel {pixel}."
      ja: "画素 {pixel} の z 値を求めよ。"
      ru: "Найдите z пикселя {pixel}."
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    ask: [plane, z]
    samples:
      - {answers: {z: 8}, expect: right}
)";

// Every student their own polygon.
constexpr const char* kVaried = R"(title: "Facing"
variants: per_student
problems:
  - id: face
    kind: backface
    given: {points: [[2, 0, 0], [2, 1, 1], [0, 1, 3]], eye: [0, 2, 0]}
    ask: [facing]
)";

// A kind with a figure: the cube's hidden lines.
constexpr const char* kCube = R"(problems:
  - id: cube
    kind: edge_visibility
    given: {solid: cube, eye: [3, 4, 5]}
    ask: [faces]
)";

constexpr Millis kNow = 1'800'000'000'000;

class AuthorPage : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("frustum-author-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
             {"week1", kWeek1}, {"varied", kVaried}, {"cube", kCube}})
      std::ofstream(dir_ / (name + ".yaml")) << text;
    std::ofstream(dir_ / "roster.csv") << "student\nalice\nbob\n";
    course_ = load_course(dir_.string(), {"alice", "bob"});
    course_.instructors = {"carol"};
    ASSERT_TRUE(course_.errors.empty()) << course_.errors.front().format();
    store_ = open_store("sqlite:" + (dir_ / "serve.sqlite").string());
    options_.self_binary = FRUSTUM_BINARY;
    app_ = std::make_unique<StudentApp>(course_, *store_, options_);
    store_->put_student("alice", sha256_hex(kAlice));
    store_->put_instructor("carol", sha256_hex(kCarol));
    carol_ = sign_in(kCarol);
    alice_ = sign_in(kAlice);
    const Response page = get("/instructor/author/week1", carol_);
    ASSERT_EQ(page.status, 200);
    csrf_ = csrf_of(page.body);
  }
  void TearDown() override { fs::remove_all(dir_); }

  Response get(const std::string& target, const std::string& cookie) {
    Request r{"GET", target, {{"host", "127.0.0.1:8080"}}, "", "127.0.0.1"};
    if (!cookie.empty())
      r.headers.emplace_back("cookie", std::string(kSessionCookie) + "=" + cookie);
    return handle_student(*app_, r, kNow);
  }
  Response post(const std::string& target, const std::string& cookie, const std::string& body,
                const std::string& origin = "http://127.0.0.1:8080") {
    Request r{"POST", target, {{"host", "127.0.0.1:8080"}}, body, "127.0.0.1"};
    r.headers.emplace_back("cookie", std::string(kSessionCookie) + "=" + cookie);
    r.headers.emplace_back("accept", "application/json");
    if (!origin.empty()) r.headers.emplace_back("origin", origin);
    return handle_student(*app_, r, kNow);
  }
  Json preview(const std::string& set, const std::string& yaml, const std::string& student = "") {
    const Response r =
        post("/instructor/author/" + set + "/preview", carol_,
             "csrf=" + csrf_ + "&yaml=" + url_encode(yaml) + "&student=" + url_encode(student));
    EXPECT_EQ(r.status, 200) << r.body;
    return Json::parse(r.body, nullptr, false);
  }
  Response save(const std::string& set, const std::string& yaml, const std::string& base,
                bool force = false) {
    return post("/instructor/author/" + set + "/save", carol_,
                "csrf=" + csrf_ + "&yaml=" + url_encode(yaml) + "&base=" + base +
                    (force ? "&force=1" : ""));
  }
  std::string sign_in(const std::string& token) {
    const Response r = get("/start?token=" + token, "");
    EXPECT_EQ(r.status, 303);
    std::smatch m;
    const std::string cookie = r.header("Set-Cookie").value_or("");
    EXPECT_TRUE(std::regex_search(cookie, m, std::regex("frustum_session=([0-9a-f]{32})")));
    return m[1].str();
  }
  static std::string csrf_of(const std::string& page) {
    std::smatch m;
    EXPECT_TRUE(std::regex_search(page, m, std::regex("name=\"csrf\" content=\"([0-9a-f]+)\"")));
    return m[1].str();
  }
  std::string file(const std::string& set) { return test::read_file(dir_ / (set + ".yaml")); }

  static constexpr const char* kAlice = "0123456789abcdef0123456789abcdef";
  static constexpr const char* kCarol = "c0ffeec0ffeec0ffeec0ffeec0ffee00";
  fs::path dir_;
  StudentAppOptions options_;
  Course course_;
  std::unique_ptr<Store> store_;
  std::unique_ptr<StudentApp> app_;
  std::string carol_, alice_, csrf_;
};

TEST_F(AuthorPage, OnlyInstructorsMayAuthor) {
  EXPECT_EQ(get("/instructor/author/week1", alice_).status, 403);
  EXPECT_EQ(get("/instructor/author/week1", "").status, 403);
  const std::string alice_csrf = csrf_of(get("/set/week1", alice_).body);
  const Response r = post("/instructor/author/week1/save", alice_,
                          "csrf=" + alice_csrf + "&yaml=x&base=" + sha256_hex(file("week1")));
  EXPECT_EQ(r.status, 403);
  EXPECT_EQ(file("week1"), kWeek1);
  EXPECT_EQ(get("/instructor/author/nosuchset", carol_).status, 404);
  EXPECT_EQ(get("/instructor/author/..%2Froster", carol_).status, 404);
}

TEST_F(AuthorPage, ThePageHoldsTheFileItsVersionAndTheEditor) {
  const Response r = get("/instructor/author/week1", carol_);
  EXPECT_NE(r.body.find("<textarea name=\"yaml\""), std::string::npos);
  EXPECT_NE(r.body.find(html_escape(kWeek1)), std::string::npos) << "the file as written";
  EXPECT_NE(r.body.find("name=\"base\" value=\"" + sha256_hex(kWeek1) + "\""), std::string::npos);
  EXPECT_NE(r.body.find("/static/codemirror/mode/yaml/yaml.js"), std::string::npos);
  EXPECT_NE(r.body.find("<option value=\"bob\">"), std::string::npos) << "the roster to preview";
  EXPECT_EQ(get("/static/author.js", carol_).status, 200);
  if (fs::exists("/usr/share/javascript/codemirror/lib/codemirror.js")) {
    const Response cm = get("/static/codemirror/lib/codemirror.js", carol_);
    EXPECT_EQ(cm.status, 200);
    EXPECT_NE(cm.body.find("CodeMirror"), std::string::npos);
  }
}

TEST_F(AuthorPage, ErrorsComeAtTheirLineAndColumn) {
  std::string yaml = kWeek1;
  yaml.replace(yaml.find("pixel: [1, 1]"), 13, "pixel: [1, 1], colour: red");
  const Json j = preview("week1", yaml);
  ASSERT_TRUE(j.is_object());
  EXPECT_FALSE(j["ok"].get<bool>());
  ASSERT_EQ(j["errors"].size(), 1u) << j.dump();
  EXPECT_EQ(j["errors"][0]["line"], 9);
  EXPECT_EQ(j["errors"][0]["column"], 73);
  EXPECT_EQ(j["errors"][0]["field"], "problems[0].given.colour");
  // A sample graded otherwise than expected is reported at its own line.
  std::string wrong = kWeek1;
  wrong.replace(wrong.find("{z: 8}"), 6, "{z: 9}");
  const Json k = preview("week1", wrong);
  EXPECT_FALSE(k["ok"].get<bool>());
  EXPECT_TRUE(k["errors"].empty());
  ASSERT_EQ(k["samples"].size(), 1u);
  EXPECT_FALSE(k["samples"][0]["ok"].get<bool>());
  EXPECT_EQ(k["samples"][0]["line"], 12);
  EXPECT_EQ(k["samples"][0]["verdict"], "wrong");
}

TEST_F(AuthorPage, ThePreviewShowsWhatStudentsReadTheKeyAndTheDerivation) {
  const Json j = preview("week1", kWeek1);
  ASSERT_TRUE(j.is_object());
  EXPECT_TRUE(j["ok"].get<bool>()) << j.dump();
  EXPECT_EQ(j["langs"], Json::parse(R"(["en","ja","ru"])"));
  ASSERT_EQ(j["problems"].size(), 1u);
  const Json& p = j["problems"][0];
  ASSERT_EQ(p["texts"].size(), 3u);
  EXPECT_EQ(p["texts"][0]["text"], "Find the z value of pixel (1, 1).");
  EXPECT_EQ(p["texts"][1]["text"], "画素 (1, 1) の z 値を求めよ。");
  ASSERT_EQ(p["key"].size(), 2u);
  EXPECT_EQ(p["key"][1]["name"], "z");
  EXPECT_NE(p["key"][1]["html"].get<std::string>().find("data-tex=\"8\""), std::string::npos)
      << p["key"][1]["html"];
  EXPECT_NE(p["derivation_html"].get<std::string>().find("data-tex="), std::string::npos);
  EXPECT_TRUE(j["samples"][0]["ok"].get<bool>());
  // A kind with a figure: draw's SVG.
  const Json s = preview("cube", kCube);
  EXPECT_NE(s["problems"][0]["figure_svg"].get<std::string>().find("<svg"), std::string::npos);
}

// The render kind's figure is the image `frustum render` writes of the same scene, byte for byte.
TEST_F(AuthorPage, ARenderProblemShowsTheImageTheRenderCommandDraws) {
  const fs::path seed = fs::path(FRUSTUM_SOURCE_DIR) / "problems/seeds/paperplane.yaml";
  const std::string plane = test::read_file(seed);
  test::write_file(dir_ / "plane.yaml", plane);
  const Json j = preview("plane", plane);
  ASSERT_EQ(j["problems"].size(), 1u) << j.dump().substr(0, 400);
  const Json& p = j["problems"][0];
  EXPECT_EQ(p["kind"], "render");
  const std::string url = p.value("figure_png", "");
  const std::string prefix = "data:image/png;base64,";
  ASSERT_EQ(url.rfind(prefix, 0), 0u) << p.value("figure_error", "") << url.substr(0, 80);
  const std::string b64 = url.substr(prefix.size());
  std::string png(b64.size() / 4 * 3, '\0');
  const int n = EVP_DecodeBlock(reinterpret_cast<unsigned char*>(png.data()),
                                reinterpret_cast<const unsigned char*>(b64.data()),
                                static_cast<int>(b64.size()));
  ASSERT_GT(n, 0);
  png.resize(static_cast<std::size_t>(n) - std::count(b64.end() - 2, b64.end(), '='));
  const fs::path drawn = dir_ / "drawn.png";
  const ProgramRun run =
      run_program({FRUSTUM_BINARY, "render", seed.string(), "-o", drawn.string(), "--id", p["id"]});
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_EQ(png, test::read_file(drawn));
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST_F(AuthorPage, AStudentsVariantIsTheOneTheyAreServed) {
  const ProblemSpec* bob = course_.find("varied")->for_student("bob")->find("face");
  const Json j = preview("varied", kVaried, "bob");
  ASSERT_EQ(j["problems"].size(), 1u);
  // The given `points` as the preview shows it.
  const auto points = [](const Json& preview) {
    for (const Json& g : preview["problems"][0]["given"])
      if (g["name"] == "points") return g["plain"].get<std::string>();
    return std::string("(none)");
  };
  EXPECT_EQ(points(j), given_plain(bob->given_node["points"]));
  EXPECT_NE(points(preview("varied", kVaried)), points(j)) << "bob's drawn points";
  EXPECT_EQ(preview("varied", kVaried, "mallory")["student_error"], "not on the roster");
}

TEST_F(AuthorPage, SavingKeepsThePreviousVersion) {
  std::string edited = kWeek1;
  edited.replace(edited.find("pixel: [1, 1]"), 13, "pixel: [1, 2]");
  edited.replace(edited.find("{z: 8}"), 6, "{z: 7}");  // z at (1, 2) is 9: a wrong sample
  edited.replace(edited.find("expect: right"), 13, "expect: wrong");
  const Response r = save("week1", edited, sha256_hex(kWeek1));
  ASSERT_EQ(r.status, 200) << r.body;
  const Json j = Json::parse(r.body);
  EXPECT_TRUE(j["saved"].get<bool>());
  EXPECT_EQ(j["version"], sha256_hex(edited));
  EXPECT_EQ(file("week1"), edited);
  const fs::path history = dir_ / ".frustum" / "history" / "week1";
  ASSERT_TRUE(fs::is_directory(history));
  std::vector<fs::path> kept;
  for (const auto& e : fs::directory_iterator(history)) kept.push_back(e.path());
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(test::read_file(kept[0]), kWeek1);
  EXPECT_EQ(kept[0].filename().string(), "20270115T080000.000Z.yaml");
  EXPECT_EQ((dir_ / j["history"].get<std::string>()).string(), kept[0].string());
  // The server serves what was saved from the next request on: the student's page asks for
  // pixel (1, 2) and the set's version is the saved file's.
  const std::string page = get("/set/week1", alice_).body;
  EXPECT_NE(page.find("Find the z value of pixel (1, 2)."), std::string::npos) << page;
  EXPECT_EQ(app_->live.current()->find("week1")->version, sha256_hex(edited));
}

TEST_F(AuthorPage, AFileChangedOnDiskIsNotOverwritten) {
  const std::string base = sha256_hex(kWeek1);
  std::string theirs = kWeek1;
  theirs += "# edited in another editor\n";
  test::write_file(dir_ / "week1.yaml", theirs);
  const Response r = save("week1", kWeek1, base);
  EXPECT_EQ(r.status, 409);
  EXPECT_EQ(Json::parse(r.body)["version"], sha256_hex(theirs));
  EXPECT_EQ(file("week1"), theirs);
  EXPECT_FALSE(fs::exists(dir_ / ".frustum" / "history"));
}

TEST_F(AuthorPage, ASetWithErrorsIsSavedOnlyWhenAskedTo) {
  const std::string broken = std::string(kWeek1) + "  - id: zbuf\n    kind: vectors\n";
  const Response r = save("week1", broken, sha256_hex(kWeek1));
  EXPECT_EQ(r.status, 422);
  const Json j = Json::parse(r.body);
  EXPECT_FALSE(j["saved"].get<bool>());
  EXPECT_FALSE(j["check"]["errors"].empty());
  EXPECT_EQ(file("week1"), kWeek1);
  const Response forced = save("week1", broken, sha256_hex(kWeek1), true);
  EXPECT_EQ(forced.status, 200) << forced.body;
  EXPECT_FALSE(Json::parse(forced.body)["ok"].get<bool>());
  EXPECT_EQ(file("week1"), broken);
}

TEST_F(AuthorPage, CsrfAndOriginAreChecked) {
  const std::string body = "yaml=" + url_encode(kCube) + "&base=" + sha256_hex(file("cube"));
  EXPECT_EQ(post("/instructor/author/cube/save", carol_, body).status, 403);
  EXPECT_EQ(post("/instructor/author/cube/save", carol_, "csrf=" + csrf_ + "&" + body,
                 "https://evil.example")
                .status,
            403);
  EXPECT_EQ(post("/instructor/author/cube/preview", carol_, body).status, 403);
  EXPECT_EQ(file("cube"), kCube);
}

TEST_F(AuthorPage, APreviewThatFailsIsAnAnswerNotACrash) {
  options_.self_binary = "/nonexistent/frustum";
  app_ = std::make_unique<StudentApp>(course_, *store_, options_);
  const Response r = post("/instructor/author/week1/preview", carol_,
                          "csrf=" + csrf_ + "&yaml=" + url_encode(kWeek1));
  EXPECT_EQ(r.status, 503);
  const Response s = save("week1", kWeek1 + std::string("# x\n"), sha256_hex(kWeek1));
  EXPECT_EQ(s.status, 422);
  EXPECT_EQ(file("week1"), kWeek1);
}

TEST(AuthorPhrases, PhrasesInEveryLanguage) {
  for (std::size_t i = 0; i < std::size(kAllAuthorPagePhrases); ++i) {
    const Phrase& phrase = *kAllAuthorPagePhrases[i];
    const std::string en(phrase.in(Lang::En)), ja(phrase.in(Lang::Ja)), ru(phrase.in(Lang::Ru));
    EXPECT_FALSE(en.empty()) << i;
    EXPECT_NE(ja, en) << i;
    EXPECT_NE(ru, en) << i;
  }
}

}  // namespace
}  // namespace frustum::server
