// The stores of `frustum serve` held to one set of expectations (conformance): durability,
// attempt numbering, drafts where the last write wins, sessions that expire, every read scoped by
// the student, claims that grade each submission exactly once, migrations. Every case runs
// against each backend: SQLite, and PostgreSQL when there is a server — FRUSTUM_TEST_PG names it
// (ctest starts one with tools/postgres_cluster.sh and passes it on); without it the PostgreSQL
// cases are SKIPPED with a message, never passed.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <barrier>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <thread>

#include "server/postgres_connection.hpp"
#include "server/postgres_store.hpp"
#include "server/store.hpp"

namespace frustum::server {
namespace {

namespace fs = std::filesystem;

// An empty database of one backend, its URL, and plain SQL on it (what the store's interface
// cannot show: rows counted, a schema from the future).
class Scratch {
 public:
  virtual ~Scratch() = default;
  virtual std::string url() const = 0;
  virtual void exec(const std::string& sql) = 0;
  virtual std::int64_t number(const std::string& sql) = 0;
  // The statement that marks the schema one version newer than this binary's.
  virtual std::string future_schema_sql(int version) const = 0;
};

// `url` whose connections see only the schema `schema` (created tables go there too).
std::string with_schema(const std::string& url, const std::string& schema) {
  return url + (url.find('?') == std::string::npos ? "?" : "&") + "options=-csearch_path%3D" +
         schema;
}

// A schema created for one test in the database FRUSTUM_TEST_PG names, dropped after it: a
// database of its own would do the same, in a second instead of milliseconds.
class PostgresScratch final : public Scratch {
 public:
  explicit PostgresScratch(const std::string& server) : server_(server) {
    std::random_device random;
    name_ = "frustum_test_" + std::to_string(::getpid()) + "_" + std::to_string(random());
    PgConnection(server_).exec("CREATE SCHEMA " + name_);
    url_ = with_schema(server_, name_);
  }
  ~PostgresScratch() override {
    try {
      PgConnection(server_).exec("DROP SCHEMA IF EXISTS " + name_ + " CASCADE");
    } catch (const StoreError&) {  // a test that failed may have left it; the cluster is scratch
    }
  }
  std::string url() const override { return url_; }
  void exec(const std::string& sql) override { PgConnection(url_).exec(sql); }
  std::int64_t number(const std::string& sql) override {
    return std::stoll(PgConnection(url_).exec(sql).rows.at(0).at(0));
  }
  std::string future_schema_sql(int version) const override {
    return "INSERT INTO schema_migrations (version, applied, applied_by) VALUES (" +
           std::to_string(version) + ", 0, 0)";
  }

 private:
  std::string server_, name_, url_;
};

// The URL of the PostgreSQL server to test against: FRUSTUM_TEST_PG, or the first line of the
// file FRUSTUM_TEST_PG_URL_FILE names (ctest's fixture, whose URL is known only once the cluster
// has started); "" when neither is set.
std::string postgres_server() {
  if (const char* url = std::getenv("FRUSTUM_TEST_PG"); url && *url) return url;
  if (const char* file = std::getenv("FRUSTUM_TEST_PG_URL_FILE"); file && *file) {
    std::ifstream in(file);
    std::string url;
    std::getline(in, url);
    if (url.empty())
      ADD_FAILURE() << "FRUSTUM_TEST_PG_URL_FILE names " << file << ", which holds no URL";
    return url;
  }
  return "";
}

const char* kPostgresUnset =
    "FRUSTUM_TEST_PG is not set, so the PostgreSQL store is NOT tested here. `ctest` sets it "
    "(it starts a cluster with tools/postgres_cluster.sh); by hand: export "
    "FRUSTUM_TEST_PG=$(tools/postgres_cluster.sh start build/postgres)";

// A SQLite file of its own, in a directory removed after the test.
class SqliteScratch final : public Scratch {
 public:
  SqliteScratch() {
    std::random_device random;
    dir_ = fs::temp_directory_path() /
           ("frustum-store-" + std::to_string(::getpid()) + "-" + std::to_string(random()));
    fs::create_directories(dir_);
  }
  ~SqliteScratch() override {
    std::error_code ignored;
    fs::remove_all(dir_, ignored);
  }
  std::string url() const override { return "sqlite:" + (dir_ / "store.sqlite").string(); }
  void exec(const std::string& sql) override { number(sql); }
  std::int64_t number(const std::string& sql) override {
    sqlite3* db = nullptr;
    std::int64_t value = 0;
    char* error = nullptr;
    const int status = sqlite3_open((dir_ / "store.sqlite").c_str(), &db) == SQLITE_OK
                           ? sqlite3_exec(
                                 db, sql.c_str(),
                                 [](void* out, int, char** v, char**) {
                                   if (v[0]) *static_cast<std::int64_t*>(out) = std::stoll(v[0]);
                                   return 0;
                                 },
                                 &value, &error)
                           : SQLITE_CANTOPEN;
    const std::string message = error ? error : sqlite3_errmsg(db);
    sqlite3_free(error);
    sqlite3_close(db);
    if (status != SQLITE_OK) ADD_FAILURE() << sql << ": " << message;
    return value;
  }
  std::string future_schema_sql(int version) const override {
    return "INSERT INTO schema_migrations (version, applied) VALUES (" + std::to_string(version) +
           ", 0)";
  }

 private:
  fs::path dir_;
};

std::unique_ptr<Scratch> make_scratch(const std::string& backend) {
  if (backend == "SQLite") return std::make_unique<SqliteScratch>();
  if (backend == "PostgreSQL") {
    const std::string server = postgres_server();
    if (server.empty()) return nullptr;
    return std::make_unique<PostgresScratch>(server);
  }
  ADD_FAILURE() << "unknown backend " << backend;
  return nullptr;
}

int latest_version() { return latest_schema_version(); }

NewSubmission attempt_of(const std::string& student, const std::string& set,
                         const std::string& problem, Millis received) {
  return NewSubmission{student, set, "sha-" + set, "seed-7", problem, R"({"z":"-3/2"})", received};
}

GradeRecord grade_of(std::int64_t submission, const std::string& worker, double score) {
  return GradeRecord{
      submission, R"({"score":)" + std::to_string(score) + "}", score, 4.0, "sha-s", worker, 5000,
      false};
}

class StoreConformance : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    scratch_ = make_scratch(GetParam());
    if (!scratch_) GTEST_SKIP() << kPostgresUnset;
    url_ = scratch_->url();
    store_ = open_store(url_);
  }
  NewSubmission sub(const std::string& student, const std::string& problem, Millis t) {
    return NewSubmission{student, "week1", "v1", "seed", problem, R"({"z":"8"})", t};
  }
  std::unique_ptr<Scratch> scratch_;
  std::string url_;
  std::unique_ptr<Store> store_;
};

TEST_P(StoreConformance, FreshDatabaseHasTheLatestSchemaAndReopens) {
  EXPECT_EQ(store_->schema_version(), latest_schema_version());
  EXPECT_GE(latest_schema_version(), 1);
  EXPECT_EQ(scratch_->number("SELECT count(*) FROM schema_migrations"), latest_version());
  EXPECT_EQ(store_->pending_count(), 0);
  EXPECT_TRUE(store_->students().empty());
  store_.reset();
  EXPECT_EQ(open_store(url_)->schema_version(), latest_schema_version());
  EXPECT_EQ(scratch_->number("SELECT count(*) FROM schema_migrations"), latest_version());
}

TEST_P(StoreConformance, ASchemaNewerThanTheBinaryIsRefused) {
  store_.reset();
  scratch_->exec(scratch_->future_schema_sql(latest_version() + 1));
  try {
    open_store(scratch_->url());
    FAIL() << "a database with schema version " << latest_version() + 1 << " was opened";
  } catch (const StoreError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("schema version " + std::to_string(latest_version() + 1)),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("newer than this frustum's"), std::string::npos) << message;
  }
}

TEST_P(StoreConformance, SeveralInstancesStartingAtOnceMigrateOnce) {
  // A second, empty database, opened by eight instances released at the same instant.
  const std::unique_ptr<Scratch> fresh = make_scratch(GetParam());
  constexpr int kInstances = 8;
  std::barrier start(kInstances);
  std::atomic<int> opened = 0;
  std::vector<std::string> errors(kInstances);
  std::vector<std::thread> instances;
  for (int i = 0; i < kInstances; ++i)
    instances.emplace_back([&, i] {
      start.arrive_and_wait();
      try {
        if (open_store(fresh->url())->schema_version() == latest_version()) ++opened;
      } catch (const std::exception& e) {
        errors[static_cast<std::size_t>(i)] = e.what();
      }
    });
  for (std::thread& t : instances) t.join();
  for (const std::string& e : errors) EXPECT_EQ(e, "");
  EXPECT_EQ(opened, kInstances);
  EXPECT_EQ(fresh->number("SELECT count(*) FROM schema_migrations"), latest_version());
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

TEST_P(StoreConformance, StudentsAreListedInByteOrderWhateverTheLocale) {
  store_->put_student("bob", "hash-bob");
  store_->put_student("ann", "hash-ann");
  store_->put_student("Ann", "hash-Ann");
  store_->put_student("Émile", "hash-emile");
  EXPECT_EQ(store_->students(), (std::vector<std::string>{"Ann", "ann", "bob", "Émile"}));
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
  store_->put_session("s1", SessionRecord{"alice", "csrf2", 2000});  // renewed
  ASSERT_TRUE(store_->session("s1", 1500));
  EXPECT_EQ(store_->session("s1", 1500)->csrf, "csrf2");
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
  EXPECT_FALSE(store_->submission("", a1.id));
  EXPECT_TRUE(store_->submissions("carol", "week1").empty());
  NewSubmission other_set = sub("alice", "p1", 5);
  other_set.set = "week2";
  EXPECT_EQ(store_->submit(other_set).attempt, 1);
  EXPECT_EQ(store_->submit(sub("alice", "p1", 6)).attempt, 3);
  EXPECT_EQ(store_->pending_count(), 6);
}

TEST_P(StoreConformance, ASubmissionIsCommittedWhenSubmitReturns) {
  const SubmissionRecord s = store_->submit(attempt_of("ann", "s", "p1", 1234));
  EXPECT_GT(s.id, 0);
  EXPECT_EQ(s.attempt, 1);
  EXPECT_EQ(s.state, SubmissionState::Pending);
  // Another instance (its own connections) sees it at once.
  const std::unique_ptr<Store> other = open_store(scratch_->url());
  const std::optional<SubmissionRecord> seen = other->submission("ann", s.id);
  ASSERT_TRUE(seen);
  EXPECT_EQ(seen->received, 1234);
  EXPECT_EQ(other->pending_count(), 1);
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

TEST_P(StoreConformance, ALateGradeWritesNoRowBeforeOrAfterTheNewClaimantsGrade) {
  const SubmissionRecord first = store_->submit(attempt_of("ann", "s", "p1", 1));
  const SubmissionRecord second = store_->submit(attempt_of("bob", "s", "p1", 2));
  const std::optional<SubmissionRecord> a = store_->claim("old", 1'000, 500);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->id, first.id);
  EXPECT_EQ(a->student, "ann");
  EXPECT_EQ(a->answers, R"({"z":"-3/2"})");
  const std::optional<SubmissionRecord> b = store_->claim("new", 1'400, 500);
  ASSERT_TRUE(b);
  EXPECT_EQ(b->id, second.id);
  EXPECT_FALSE(store_->claim("new", 1'499, 500));  // the old claim's lease still runs
  const std::optional<SubmissionRecord> again = store_->claim("new", 1'500, 500);
  ASSERT_TRUE(again);
  EXPECT_EQ(again->id, first.id);
  // The old claimant comes back late: nothing is written.
  EXPECT_FALSE(store_->record_grade(grade_of(first.id, "old", 1), "old"));
  EXPECT_FALSE(store_->latest_grade(first.id));
  EXPECT_TRUE(store_->record_grade(grade_of(first.id, "new", 2.5), "new"));
  EXPECT_FALSE(store_->record_grade(grade_of(first.id, "new", 4), "new"));  // graded once
  EXPECT_FALSE(store_->record_grade(grade_of(first.id, "old", 1), "old"));
  const std::optional<GradeRecord> g = store_->latest_grade(first.id);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->graded_by, "new");
  EXPECT_EQ(g->score, 2.5);
  EXPECT_EQ(g->max_score, 4.0);
  EXPECT_EQ(g->result, grade_of(first.id, "new", 2.5).result);
  EXPECT_EQ(g->graded, 5000);
  EXPECT_FALSE(g->failed);
  EXPECT_EQ(store_->submission("ann", first.id)->state, SubmissionState::Graded);
  EXPECT_EQ(scratch_->number("SELECT count(*) FROM grades WHERE submission = " +
                             std::to_string(first.id)),
            1);
  EXPECT_EQ(store_->pending_count(), 1);
  EXPECT_FALSE(store_->record_grade(grade_of(second.id, "old", 1), "old"));  // never its claim
}

TEST_P(StoreConformance, AFailedGradingLeavesTheSubmissionFailed) {
  const SubmissionRecord s = store_->submit(attempt_of("ann", "s", "p1", 1));
  ASSERT_TRUE(store_->claim("w", 10, 100));
  GradeRecord failed = grade_of(s.id, "w", 0);
  failed.failed = true;
  failed.result = R"({"error":"time limit"})";
  EXPECT_TRUE(store_->record_grade(failed, "w"));
  EXPECT_EQ(store_->submission("ann", s.id)->state, SubmissionState::Failed);
  ASSERT_TRUE(store_->latest_grade(s.id));
  EXPECT_TRUE(store_->latest_grade(s.id)->failed);
  EXPECT_EQ(store_->pending_count(), 0);
  EXPECT_FALSE(store_->claim("w", 1'000'000, 100));  // not pending: never claimed again
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

TEST_P(StoreConformance, ConcurrentWorkersGradeEachSubmissionOnce) {
  constexpr int kSubmissions = 200, kWorkers = 4;
  for (int i = 0; i < kSubmissions; ++i) store_->submit(sub("s" + std::to_string(i % 7), "p1", i));
  std::atomic<int> recorded{0};
  std::vector<std::vector<std::int64_t>> held(kWorkers);
  std::vector<std::thread> workers;
  std::barrier start(kWorkers);
  for (int w = 0; w < kWorkers; ++w)
    workers.emplace_back([&, w] {
      const std::unique_ptr<Store> mine = open_store(url_);
      const std::string name = "w" + std::to_string(w);
      start.arrive_and_wait();
      // Worker w claims w + 1 at a time (the first one by one) and writes their grades together.
      for (;;) {
        const std::vector<SubmissionRecord> batch =
            mine->claim_some(name, 1000, 60000, static_cast<std::size_t>(w + 1));
        if (batch.empty()) break;
        std::vector<GradeRecord> grades;
        for (const SubmissionRecord& c : batch) {
          held[static_cast<std::size_t>(w)].push_back(c.id);
          grades.push_back(GradeRecord{c.id, "{}", 1, 1, "v1", name, 1001});
        }
        for (const bool written : mine->record_grades(grades, name)) recorded += written ? 1 : 0;
      }
    });
  for (auto& t : workers) t.join();
  EXPECT_EQ(recorded.load(), kSubmissions);
  EXPECT_EQ(store_->pending_count(), 0);
  // No submission was held by two workers; one grade row each, counted in the database.
  std::set<std::int64_t> claimed;
  std::size_t claims = 0;
  for (const auto& h : held) {
    claimed.insert(h.begin(), h.end());
    claims += h.size();
  }
  EXPECT_EQ(claims, std::size_t{kSubmissions});
  EXPECT_EQ(claimed.size(), std::size_t{kSubmissions});
  EXPECT_EQ(scratch_->number("SELECT count(*) FROM grades"), kSubmissions);
  EXPECT_EQ(scratch_->number("SELECT count(DISTINCT submission) FROM grades"), kSubmissions);
}

std::vector<std::int64_t> ids_of(const std::vector<SubmissionRecord>& records) {
  std::vector<std::int64_t> out;
  for (const SubmissionRecord& r : records) out.push_back(r.id);
  return out;
}

TEST_P(StoreConformance, WorkersClaimBatchesOldestFirstAndWriteTheirGradesTogether) {
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 5; ++i)
    ids.push_back(store_->submit(sub("s" + std::to_string(i), "p1", i)).id);
  const std::vector<SubmissionRecord> mine = store_->claim_some("w1", 100, 1000, 3);
  EXPECT_EQ(ids_of(mine), (std::vector<std::int64_t>{ids[0], ids[1], ids[2]}));
  for (const SubmissionRecord& r : mine) EXPECT_EQ(r.claims, 1);
  EXPECT_EQ(ids_of(store_->claim_some("w2", 100, 1000, 10)),
            (std::vector<std::int64_t>{ids[3], ids[4]}));
  EXPECT_TRUE(store_->claim_some("w3", 100, 1000, 10).empty());  // all held
  // w1 writes its three and one of w2's: only its own are written, in one go.
  const std::vector<bool> written = store_->record_grades(
      {grade_of(ids[0], "w1", 1), grade_of(ids[3], "w1", 1), grade_of(ids[2], "w1", 2)}, "w1");
  EXPECT_EQ(written, (std::vector<bool>{true, false, true}));
  EXPECT_EQ(store_->pending_count(), 3);
  EXPECT_EQ(store_->record_grades({grade_of(ids[0], "w1", 1)}, "w1"), std::vector<bool>{false});
  EXPECT_EQ(scratch_->number("SELECT count(*) FROM grades"), 2);
  EXPECT_TRUE(store_->record_grades({}, "w1").empty());
  EXPECT_TRUE(store_->claim_some("w1", 100, 1000, 0).empty());
}

TEST_P(StoreConformance, AClaimWhoseLeaseRanOutIsTakenAgainAloneBeforeNewOnes) {
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 4; ++i)
    ids.push_back(store_->submit(sub("s" + std::to_string(i), "p1", i)).id);
  ASSERT_EQ(store_->claim_some("dead", 100, 1000, 3).size(), 3U);  // its worker dies
  // Before the lease runs out only the unclaimed one is there.
  EXPECT_EQ(ids_of(store_->claim_some("w2", 1099, 1000, 10)), std::vector<std::int64_t>{ids[3]});
  // After it, each of the dead worker's claims comes alone (one of them may kill workers).
  for (int k = 0; k < 3; ++k) {
    const std::vector<SubmissionRecord> again = store_->claim_some("w2", 1100, 1000, 10);
    ASSERT_EQ(again.size(), 1U);
    EXPECT_EQ(again[0].id, ids[static_cast<std::size_t>(k)]);
    EXPECT_EQ(again[0].claims, 2);
  }
  EXPECT_TRUE(store_->claim_some("w2", 1100, 1000, 10).empty());
  EXPECT_EQ(store_->record_grades({grade_of(ids[0], "dead", 1)}, "dead"), std::vector<bool>{false});
}

TEST_P(StoreConformance, ReleasedClaimsArePendingAgainAndNotCounted) {
  std::vector<std::int64_t> ids;
  for (int i = 0; i < 3; ++i)
    ids.push_back(store_->submit(sub("s" + std::to_string(i), "p1", i)).id);
  ASSERT_EQ(store_->claim_some("w1", 100, 1000, 3).size(), 3U);
  store_->release({ids[1], ids[2]}, "w2");  // not w2's: nothing happens
  EXPECT_TRUE(store_->claim_some("w2", 100, 1000, 3).empty());
  store_->release({ids[1], ids[2]}, "w1");
  const std::vector<SubmissionRecord> taken = store_->claim_some("w2", 100, 1000, 3);
  EXPECT_EQ(ids_of(taken), (std::vector<std::int64_t>{ids[1], ids[2]}));
  for (const SubmissionRecord& r : taken) EXPECT_EQ(r.claims, 1);  // the released one not counted
  EXPECT_EQ(store_->record_grades({grade_of(ids[1], "w1", 1)}, "w1"), std::vector<bool>{false});
  EXPECT_EQ(store_->record_grades({grade_of(ids[1], "w2", 1), grade_of(ids[0], "w1", 1)}, "w2"),
            (std::vector<bool>{true, false}));
  store_->release({ids[0]}, "w1");
  EXPECT_TRUE(store_->record_grade(grade_of(ids[2], "w2", 1), "w2"));
  store_->release({ids[2]}, "w2");  // graded: stays graded
  EXPECT_EQ(store_->submission("s2", ids[2])->state, SubmissionState::Graded);
  EXPECT_EQ(store_->pending_count(), 1);
}

TEST_P(StoreConformance, TextIsKeptByteForByte) {
  NewSubmission n = attempt_of("ann", "s", "p1", 1);
  n.answers = "{\"z\":\"\\u00bd – ½ 'quoted' \\\"x\\\" $1 \\\\ ;DROP TABLE submissions;--\"}";
  const SubmissionRecord s = store_->submit(n);
  EXPECT_EQ(store_->submission("ann", s.id)->answers, n.answers);
  store_->save_draft("ann", Draft{"s", "p1", "z", "½ – \"x\"\n\ty", 1});
  EXPECT_EQ(store_->drafts("ann", "s").at(0).text, "½ – \"x\"\n\ty");
}

TEST_P(StoreConformance, InstructorsAreFoundByTheirOwnTokensAndAreNoStudents) {
  store_->put_student("alice", "hash-a");
  store_->put_instructor("prof", "hash-p");
  EXPECT_EQ(store_->instructor_by_token("hash-p"), "prof");
  EXPECT_EQ(store_->student_by_token("hash-p"), std::nullopt);  // not a student's link
  EXPECT_EQ(store_->instructor_by_token("hash-a"), std::nullopt);
  EXPECT_EQ(store_->students(), std::vector<std::string>{"alice"});
  EXPECT_EQ(store_->instructors(), std::vector<std::string>{"prof"});
  store_->put_instructor("prof", "hash-p2");  // rotated
  EXPECT_EQ(store_->instructor_by_token("hash-p"), std::nullopt);
  EXPECT_EQ(store_->instructor_by_token("hash-p2"), "prof");
}

TEST_P(StoreConformance, SessionsCarryTheirRole) {
  store_->put_student("alice", "hash-a");
  store_->put_instructor("prof", "hash-p");
  store_->put_session("s-a", SessionRecord{"alice", "c1", 100});
  store_->put_session("s-p", SessionRecord{"prof", "c2", 100, Role::Instructor});
  EXPECT_EQ(store_->session("s-a", 50)->role, Role::Student);
  EXPECT_EQ(store_->session("s-p", 50)->role, Role::Instructor);
  EXPECT_EQ(store_->session("s-p", 50)->student, "prof");
}

TEST_P(StoreConformance, ARegradeKeepsEveryGradeBeforeIt) {
  const SubmissionRecord a = store_->submit(sub("alice", "p1", 1));
  const SubmissionRecord b = store_->submit(sub("bob", "p1", 2));
  NewSubmission elsewhere = sub("carol", "p1", 3);
  elsewhere.set = "week2";
  const SubmissionRecord c = store_->submit(elsewhere);
  for (int i = 0; i < 3; ++i) {
    const auto claimed = store_->claim("w", 10, 1000);
    ASSERT_TRUE(claimed);
    ASSERT_TRUE(store_->record_grade(grade_of(claimed->id, "w", 1.0 + claimed->id % 2), "w"));
  }
  const std::int64_t mark = store_->change_mark();
  GradeRecord again = grade_of(a.id, "instructor:prof", 4.0);
  again.set_version = "sha-t";
  GradeRecord failed = grade_of(b.id, "instructor:prof", 0.0);
  failed.failed = true;
  store_->record_regrades({again, failed});
  EXPECT_NE(store_->change_mark(), mark);
  const std::vector<GradeRecord> history = store_->grade_history(a.id);
  ASSERT_EQ(history.size(), 2u);
  EXPECT_EQ(history[0].set_version, "sha-s");
  EXPECT_EQ(history[0].graded_by, "w");
  EXPECT_EQ(history[1].set_version, "sha-t");
  EXPECT_EQ(history[1].graded_by, "instructor:prof");
  EXPECT_DOUBLE_EQ(history[1].score, 4.0);
  EXPECT_EQ(store_->submission("bob", b.id)->state, SubmissionState::Failed);
  // The class's latest grades: one per submission of the set, the regrade's.
  const std::vector<GradeRecord> latest = store_->latest_grades("week1");
  ASSERT_EQ(latest.size(), 2u);
  EXPECT_EQ(latest[0].submission, a.id);
  EXPECT_DOUBLE_EQ(latest[0].score, 4.0);
  EXPECT_TRUE(latest[1].failed);
  const std::vector<SubmissionRecord> all = store_->set_submissions("week1", 10);
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[1].student, "bob");
  EXPECT_EQ(store_->set_submissions("week1", 1).size(), 1u);
  EXPECT_EQ(store_->set_submissions("week2", 10).at(0).id, c.id);
  // All or nothing: a regrade naming a submission that is not there writes none of its grades.
  EXPECT_THROW(store_->record_regrades({grade_of(a.id, "x", 0.5), grade_of(999999, "x", 1)}),
               StoreError);
  EXPECT_EQ(store_->grade_history(a.id).size(), 2u);
}

TEST_P(StoreConformance, WaitingForAChangeEndsWithTheChange) {
  const std::int64_t mark = store_->change_mark();
  EXPECT_EQ(store_->wait_for_change(mark, 0), mark);  // nothing: the wait ends at once
  std::thread other([&] {
    const std::unique_ptr<Store> instance = open_store(url_);  // another instance's write
    instance->submit(sub("alice", "p1", 1));
  });
  std::int64_t seen = mark;
  for (int i = 0; i < 100 && seen == mark; ++i) seen = store_->wait_for_change(mark, 100);
  other.join();
  EXPECT_NE(seen, mark);
  EXPECT_EQ(seen, store_->change_mark());
}

INSTANTIATE_TEST_SUITE_P(Backends, StoreConformance, ::testing::Values("SQLite", "PostgreSQL"),
                         [](const auto& info) { return info.param; });

// SQLite only.

TEST(SqliteStore, UsesWalAndFullSync) {
  SqliteScratch scratch;
  const std::string url = scratch.url();
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
  try {
    open_store("mysql://root:pw-s3cret-9@db/x");
    FAIL();
  } catch (const StoreError& e) {
    EXPECT_EQ(std::string(e.what()).find("pw-s3cret-9"), std::string::npos) << e.what();
  }
}

TEST(OpenStore, BothStoresShareTheSchemaNumbering) {
  EXPECT_EQ(postgres_latest_version(), latest_schema_version());
}

// PostgreSQL only: what the interface shares cannot show.

TEST(PostgresStore, ConnectionFailuresNameTheHostNeverThePassword) {
  try {
    open_postgres_store("postgresql://frustum:pw-s3cret-9@127.0.0.1:1/frustum");
    FAIL() << "connected to port 1";
  } catch (const StoreError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("127.0.0.1:1"), std::string::npos) << message;
    EXPECT_NE(message.find("database frustum, user frustum"), std::string::npos) << message;
    EXPECT_EQ(message.find("pw-s3cret-9"), std::string::npos) << message;
  }
  try {
    open_postgres_store("postgresql://frustum:pw-s3cret-9@127.0.0.1:1/frustum?nonsense=1");
    FAIL() << "a URL with an unknown parameter was accepted";
  } catch (const StoreError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("invalid PostgreSQL URL"), std::string::npos) << message;
    EXPECT_EQ(message.find("pw-s3cret-9"), std::string::npos) << message;
  }
  EXPECT_EQ(redact_postgres_url("postgresql://u:p%40ss@h:5/d?x=1"), "postgresql://u@h:5/d?x=1");
  EXPECT_EQ(redact_postgres_url("postgresql://u@h/d"), "postgresql://u@h/d");
}

TEST(PostgresStore, ConnectionsTheServerClosedAreReplacedBeforeUse) {
  const std::unique_ptr<Scratch> scratch = make_scratch("PostgreSQL");
  if (!scratch) GTEST_SKIP() << kPostgresUnset;
  const std::string name = "frustum_test_" + std::to_string(::getpid());
  const std::string url = scratch->url() + "&application_name=" + name;
  const std::unique_ptr<Store> store = open_postgres_store(url);
  store->put_student("ann", "hash-ann");
  // As a restart of the server would: every session of this store ended while idle.
  const auto ended = PgConnection(scratch->url())
                         .exec(
                             "SELECT pg_terminate_backend(pid) FROM pg_stat_activity WHERE "
                             "application_name = $1",
                             {name});
  ASSERT_EQ(ended.rows.size(), 1u);
  EXPECT_EQ(ended.rows[0][0], "t");
  // Until the server has ended them (up to 10 s: on a loaded machine a backend takes its time
  // to exit, and a session still closing is not yet one the server closed).
  for (int i = 0; i < 500 && PgConnection(scratch->url())
                                     .exec("SELECT count(*) FROM pg_stat_activity WHERE "
                                           "application_name = $1",
                                           {name})
                                     .rows[0][0] != "0";
       ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(store->student_by_token("hash-ann"), "ann");
  EXPECT_EQ(store->submit(attempt_of("ann", "s", "p1", 1)).attempt, 1);
}

TEST(PostgresStore, ExactlyOneOfManyStartingInstancesMigrates) {
  const std::unique_ptr<Scratch> fresh = make_scratch("PostgreSQL");
  if (!fresh) GTEST_SKIP() << kPostgresUnset;
  constexpr int kInstances = 8;
  std::barrier start(kInstances);
  std::vector<int> applied(kInstances, -1);
  std::vector<std::thread> instances;
  for (int i = 0; i < kInstances; ++i)
    instances.emplace_back([&, i] {
      start.arrive_and_wait();
      try {
        applied[static_cast<std::size_t>(i)] = migrate_postgres(fresh->url());
      } catch (const StoreError& e) {
        ADD_FAILURE() << e.what();
      }
    });
  for (std::thread& t : instances) t.join();
  EXPECT_EQ(std::count(applied.begin(), applied.end(), postgres_latest_version()), 1);
  EXPECT_EQ(std::count(applied.begin(), applied.end(), 0), kInstances - 1);
  // The version rows were written by one server process (one instance's connection).
  EXPECT_EQ(fresh->number("SELECT count(DISTINCT applied_by) FROM schema_migrations"), 1);
}

}  // namespace
}  // namespace frustum::server
