// The store's conformance suite: every backend (SQLite here; PostgreSQL when FRUSTUM_TEST_PG
// names a database) passes the same cases — students by token hash, sessions that expire,
// drafts where the last write wins, durable numbered submissions, claims that grade each
// submission exactly once, and every read scoped by the student.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <set>
#include <thread>

#include "server/store.hpp"

namespace frustum::server {
namespace {

namespace fs = std::filesystem;

// A backend: a fresh, empty database's URL per test ("" = skipped, with `why`).
struct Backend {
  std::string name;
  std::function<std::string(const std::string& test)> fresh_url;
  std::string why_skipped;
};

void PrintTo(const Backend& b, std::ostream* os) { *os << b.name; }

std::string fresh_sqlite(std::string test) {
  std::replace(test.begin(), test.end(), '/', '_');  // parameterized names: Case/SQLite
  const fs::path dir = fs::temp_directory_path() / ("frustum-store-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / (test + ".sqlite");
  for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(file.string() + suffix);
  return "sqlite:" + file.string();
}

std::vector<Backend> backends() {
  std::vector<Backend> out{{"SQLite", fresh_sqlite, ""}};
  return out;
}

class StoreConformance : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override {
    if (!GetParam().why_skipped.empty()) GTEST_SKIP() << GetParam().why_skipped;
    url_ = GetParam().fresh_url(::testing::UnitTest::GetInstance()->current_test_info()->name());
    store_ = open_store(url_);
  }
  NewSubmission sub(const std::string& student, const std::string& problem, Millis t) {
    return NewSubmission{student, "week1", "v1", "seed", problem, R"({"z":"8"})", t};
  }
  std::string url_;
  std::unique_ptr<Store> store_;
};

TEST_P(StoreConformance, FreshDatabaseHasTheLatestSchemaAndReopens) {
  EXPECT_EQ(store_->schema_version(), latest_schema_version());
  EXPECT_GE(latest_schema_version(), 1);
  store_.reset();
  EXPECT_EQ(open_store(url_)->schema_version(), latest_schema_version());
}

TEST_P(StoreConformance, StudentsAreFoundByTokenHashAndRotate) {
  store_->put_student("bob", "hash-b1");
  store_->put_student("alice", "hash-a1");
  EXPECT_EQ(store_->student_by_token("hash-a1"), "alice");
  EXPECT_EQ(store_->student_by_token("hash-b1"), "bob");
  EXPECT_EQ(store_->student_by_token("nope"), std::nullopt);
  store_->put_student("alice", "hash-a2");  // a new link: the old one stops working
  EXPECT_EQ(store_->student_by_token("hash-a1"), std::nullopt);
  EXPECT_EQ(store_->student_by_token("hash-a2"), "alice");
  EXPECT_EQ(store_->students(), (std::vector<std::string>{"alice", "bob"}));
}

TEST_P(StoreConformance, SessionsExpire) {
  store_->put_student("alice", "h");
  store_->put_session("s1", SessionRecord{"alice", "csrf1", 1000});
  const auto s = store_->session("s1", 999);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->student, "alice");
  EXPECT_EQ(s->csrf, "csrf1");
  EXPECT_EQ(s->expires, 1000);
  EXPECT_FALSE(store_->session("s1", 1000));
  EXPECT_FALSE(store_->session("s2", 0));
}

TEST_P(StoreConformance, DraftsKeepTheLastWriteOfEachStudent) {
  store_->save_draft("alice", Draft{"week1", "p1", "z", "8", 20});
  store_->save_draft("alice", Draft{"week1", "p1", "z", "7", 10});  // older: ignored
  store_->save_draft("alice", Draft{"week1", "p1", "normal", "(0,0,1)", 5});
  store_->save_draft("bob", Draft{"week1", "p1", "z", "9", 30});
  store_->save_draft("alice", Draft{"week2", "p1", "z", "1", 30});
  const std::vector<Draft> d = store_->drafts("alice", "week1");
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].answer, "normal");
  EXPECT_EQ(d[1].answer, "z");
  EXPECT_EQ(d[1].text, "8");
  EXPECT_EQ(d[1].saved, 20);
  store_->save_draft("alice", Draft{"week1", "p1", "z", "8.0", 21});
  EXPECT_EQ(store_->drafts("alice", "week1")[1].text, "8.0");
  EXPECT_TRUE(store_->drafts("carol", "week1").empty());
}

TEST_P(StoreConformance, SubmissionsAreNumberedPerProblemAndScopedByStudent) {
  const SubmissionRecord a1 = store_->submit(sub("alice", "p1", 1));
  const SubmissionRecord a2 = store_->submit(sub("alice", "p1", 2));
  const SubmissionRecord a3 = store_->submit(sub("alice", "p2", 3));
  const SubmissionRecord b1 = store_->submit(sub("bob", "p1", 4));
  EXPECT_EQ(a1.attempt, 1);
  EXPECT_EQ(a2.attempt, 2);
  EXPECT_EQ(a3.attempt, 1);
  EXPECT_EQ(b1.attempt, 1);
  EXPECT_NE(a1.id, a2.id);
  EXPECT_EQ(a1.state, SubmissionState::Pending);
  const auto mine = store_->submissions("alice", "week1");
  ASSERT_EQ(mine.size(), 3u);
  EXPECT_EQ(mine[1].id, a2.id);
  EXPECT_EQ(mine[1].answers, R"({"z":"8"})");
  EXPECT_EQ(mine[1].variant, "seed");
  EXPECT_EQ(mine[1].set_version, "v1");
  EXPECT_EQ(mine[1].received, 2);
  EXPECT_TRUE(store_->submission("alice", a1.id));
  EXPECT_FALSE(store_->submission("alice", b1.id));  // bob's, asked for by alice
  EXPECT_FALSE(store_->submission("bob", a1.id));
  EXPECT_EQ(store_->pending_count(), 4);
}

TEST_P(StoreConformance, SubmissionsSurviveReopening) {
  const SubmissionRecord a = store_->submit(sub("alice", "p1", 1));
  store_.reset();
  store_ = open_store(url_);
  const auto again = store_->submission("alice", a.id);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->answers, a.answers);
  EXPECT_EQ(store_->pending_count(), 1);
}

TEST_P(StoreConformance, AClaimedSubmissionIsGradedOnce) {
  const SubmissionRecord a = store_->submit(sub("alice", "p1", 1));
  const SubmissionRecord b = store_->submit(sub("bob", "p1", 2));
  const auto c1 = store_->claim("w1", 100, 1000);
  const auto c2 = store_->claim("w2", 100, 1000);
  ASSERT_TRUE(c1 && c2);
  EXPECT_EQ(c1->id, a.id);  // oldest first
  EXPECT_EQ(c2->id, b.id);
  EXPECT_FALSE(store_->claim("w3", 100, 1000));  // both held
  GradeRecord g{a.id, R"({"ok":true})", 1, 2, "v1", "w1", 150};
  EXPECT_FALSE(store_->record_grade(g, "w2"));  // not w2's claim
  EXPECT_TRUE(store_->record_grade(g, "w1"));
  EXPECT_FALSE(store_->record_grade(g, "w1"));  // already graded
  const auto latest = store_->latest_grade(a.id);
  ASSERT_TRUE(latest);
  EXPECT_EQ(latest->result, R"({"ok":true})");
  EXPECT_DOUBLE_EQ(latest->score, 1);
  EXPECT_DOUBLE_EQ(latest->max_score, 2);
  EXPECT_EQ(latest->graded_by, "w1");
  EXPECT_EQ(store_->submission("alice", a.id)->state, SubmissionState::Graded);
  EXPECT_FALSE(store_->latest_grade(b.id));
  EXPECT_EQ(store_->pending_count(), 1);
}

TEST_P(StoreConformance, AnExpiredClaimIsTakenAgainAndTheFirstWorkerLosesIt) {
  const SubmissionRecord a = store_->submit(sub("alice", "p1", 1));
  ASSERT_TRUE(store_->claim("dead", 100, 1000));
  EXPECT_FALSE(store_->claim("w2", 1099, 1000));
  const auto again = store_->claim("w2", 1100, 1000);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->id, a.id);
  EXPECT_EQ(again->claims, 2);
  GradeRecord g{a.id, "{}", 0, 1, "v1", "dead", 1200};
  EXPECT_FALSE(store_->record_grade(g, "dead"));
  g.graded_by = "w2";
  g.failed = true;
  EXPECT_TRUE(store_->record_grade(g, "w2"));
  EXPECT_EQ(store_->submission("alice", a.id)->state, SubmissionState::Failed);
  EXPECT_TRUE(store_->latest_grade(a.id)->failed);
}

TEST_P(StoreConformance, ConcurrentSubmittersGetDistinctAttempts) {
  constexpr int kThreads = 8, kEach = 40;
  std::vector<std::thread> threads;
  std::vector<std::vector<SubmissionRecord>> got(kThreads);
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int i = 0; i < kEach; ++i) got[t].push_back(store_->submit(sub("alice", "p1", i)));
    });
  for (auto& t : threads) t.join();
  std::set<std::int64_t> ids;
  std::set<int> attempts;
  for (const auto& g : got)
    for (const auto& r : g) {
      ids.insert(r.id);
      attempts.insert(r.attempt);
    }
  EXPECT_EQ(ids.size(), std::size_t{kThreads * kEach});
  EXPECT_EQ(attempts.size(), std::size_t{kThreads * kEach});
  EXPECT_EQ(*attempts.begin(), 1);
  EXPECT_EQ(*attempts.rbegin(), kThreads * kEach);
}

// Several stores on one database (as worker processes are) claim and grade concurrently:
// every submission is graded exactly once.
TEST_P(StoreConformance, ConcurrentWorkersGradeEachSubmissionOnce) {
  constexpr int kSubmissions = 200, kWorkers = 4;
  for (int i = 0; i < kSubmissions; ++i) store_->submit(sub("s" + std::to_string(i % 7), "p1", i));
  std::atomic<int> recorded{0};
  std::vector<std::thread> workers;
  for (int w = 0; w < kWorkers; ++w)
    workers.emplace_back([&, w] {
      const std::unique_ptr<Store> mine = open_store(url_);
      const std::string name = "w" + std::to_string(w);
      while (const auto c = mine->claim(name, 1000, 60000))
        if (mine->record_grade(GradeRecord{c->id, "{}", 1, 1, "v1", name, 1001}, name)) ++recorded;
    });
  for (auto& t : workers) t.join();
  EXPECT_EQ(recorded.load(), kSubmissions);
  EXPECT_EQ(store_->pending_count(), 0);
}

INSTANTIATE_TEST_SUITE_P(Backends, StoreConformance, ::testing::ValuesIn(backends()),
                         [](const auto& info) { return info.param.name; });

// SQLite only: a database written by a newer frustum is refused with a message saying so.
TEST(SqliteStore, RefusesADatabaseNewerThanTheBinary) {
  const std::string url = fresh_sqlite("newer");
  open_store(url).reset();
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(url.substr(7).c_str(), &db), SQLITE_OK);
  const std::string bump = "INSERT INTO schema_migrations VALUES (" +
                           std::to_string(latest_schema_version() + 1) + ", 0)";
  ASSERT_EQ(sqlite3_exec(db, bump.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  try {
    open_store(url);
    FAIL() << "a newer database was opened";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("newer than this frustum"), std::string::npos) << e.what();
  }
}

TEST(SqliteStore, UsesWalAndFullSync) {
  const std::string url = fresh_sqlite("wal");
  open_store(url).reset();
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(url.substr(7).c_str(), &db), SQLITE_OK);
  std::string mode;
  sqlite3_exec(
      db, "PRAGMA journal_mode",
      [](void* out, int, char** v, char**) {
        *static_cast<std::string*>(out) = v[0];
        return 0;
      },
      &mode, nullptr);
  sqlite3_close(db);
  EXPECT_EQ(mode, "wal");
}

TEST(OpenStore, NamesWhatItCannotOpen) {
  EXPECT_THROW(open_store("mysql://x"), StoreError);
  EXPECT_THROW(open_store("sqlite:"), StoreError);
  EXPECT_THROW(open_store("sqlite:/nonexistent-dir/x/y.sqlite"), StoreError);
}

}  // namespace
}  // namespace frustum::server
