// The stores of `frustum serve` held to one set of expectations (conformance): durability,
// attempt numbering, drafts, sessions, scoping by student, claims and leases, migrations. Every
// case runs against each backend. The PostgreSQL cases need a server: FRUSTUM_TEST_PG names it
// (ctest starts one with tools/postgres_cluster.sh and sets it); without it they are SKIPPED,
// never passed.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <barrier>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "server/postgres_connection.hpp"
#include "server/postgres_store.hpp"
#include "server/store.hpp"

namespace frustum::server {
namespace {

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

std::unique_ptr<Scratch> make_scratch(const std::string& backend) {
  if (backend == "postgresql") {
    const std::string server = postgres_server();
    if (server.empty()) return nullptr;
    return std::make_unique<PostgresScratch>(server);
  }
  ADD_FAILURE() << "unknown backend " << backend;
  return nullptr;
}

std::unique_ptr<Store> open_for_test(const std::string& url) { return open_postgres_store(url); }

int latest_version() { return postgres_latest_version(); }

NewSubmission attempt_of(const std::string& student, const std::string& set,
                         const std::string& problem, Millis received) {
  return NewSubmission{student, set, "sha-" + set, "seed-7", problem, R"({"z":"-3/2"})", received};
}

GradeRecord grade_of(std::int64_t submission, const std::string& worker, double score) {
  return GradeRecord{
      submission, R"({"score":)" + std::to_string(score) + "}", score, 4.0, "sha-s", worker, 5000,
      false};
}

class ServerStore : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    scratch_ = make_scratch(GetParam());
    if (!scratch_) GTEST_SKIP() << kPostgresUnset;
    store_ = open_for_test(scratch_->url());
  }
  std::unique_ptr<Scratch> scratch_;
  std::unique_ptr<Store> store_;
};

TEST_P(ServerStore, FreshDatabaseReachesTheLatestSchema) {
  EXPECT_EQ(store_->schema_version(), latest_version());
  EXPECT_EQ(scratch_->number("SELECT count(*) FROM schema_migrations"), latest_version());
  EXPECT_EQ(store_->pending_count(), 0);
  EXPECT_TRUE(store_->students().empty());
}

TEST_P(ServerStore, ReopeningKeepsEverythingAndMigratesNothing) {
  store_->put_student("ann", "hash-ann");
  const SubmissionRecord s = store_->submit(attempt_of("ann", "s", "p1", 1000));
  store_.reset();
  const std::unique_ptr<Store> again = open_for_test(scratch_->url());
  EXPECT_EQ(again->schema_version(), latest_version());
  EXPECT_EQ(scratch_->number("SELECT count(*) FROM schema_migrations"), latest_version());
  EXPECT_EQ(again->student_by_token("hash-ann"), "ann");
  const std::optional<SubmissionRecord> kept = again->submission("ann", s.id);
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->answers, R"({"z":"-3/2"})");
  EXPECT_EQ(kept->set_version, "sha-s");
  EXPECT_EQ(kept->variant, "seed-7");
  EXPECT_EQ(kept->received, 1000);
  EXPECT_EQ(kept->state, SubmissionState::Pending);
}

TEST_P(ServerStore, ASchemaNewerThanTheBinaryIsRefused) {
  store_.reset();
  scratch_->exec(scratch_->future_schema_sql(latest_version() + 1));
  try {
    open_for_test(scratch_->url());
    FAIL() << "a database with schema version " << latest_version() + 1 << " was opened";
  } catch (const StoreError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("schema version " + std::to_string(latest_version() + 1)),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("newer than this frustum's"), std::string::npos) << message;
  }
}

TEST_P(ServerStore, SeveralInstancesStartingAtOnceMigrateOnce) {
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
        if (open_for_test(fresh->url())->schema_version() == latest_version()) ++opened;
      } catch (const std::exception& e) {
        errors[static_cast<std::size_t>(i)] = e.what();
      }
    });
  for (std::thread& t : instances) t.join();
  for (const std::string& e : errors) EXPECT_EQ(e, "");
  EXPECT_EQ(opened, kInstances);
  EXPECT_EQ(fresh->number("SELECT count(*) FROM schema_migrations"), latest_version());
}

TEST_P(ServerStore, ASubmissionIsCommittedWhenSubmitReturns) {
  const SubmissionRecord s = store_->submit(attempt_of("ann", "s", "p1", 1234));
  EXPECT_GT(s.id, 0);
  EXPECT_EQ(s.attempt, 1);
  EXPECT_EQ(s.state, SubmissionState::Pending);
  // Another instance (its own connections) sees it at once.
  const std::unique_ptr<Store> other = open_for_test(scratch_->url());
  const std::optional<SubmissionRecord> seen = other->submission("ann", s.id);
  ASSERT_TRUE(seen);
  EXPECT_EQ(seen->received, 1234);
  EXPECT_EQ(other->pending_count(), 1);
}

TEST_P(ServerStore, AttemptsAreNumberedPerStudentSetAndProblem) {
  EXPECT_EQ(store_->submit(attempt_of("ann", "s", "p1", 1)).attempt, 1);
  EXPECT_EQ(store_->submit(attempt_of("ann", "s", "p1", 2)).attempt, 2);
  EXPECT_EQ(store_->submit(attempt_of("ann", "s", "p2", 3)).attempt, 1);
  EXPECT_EQ(store_->submit(attempt_of("bob", "s", "p1", 4)).attempt, 1);
  EXPECT_EQ(store_->submit(attempt_of("ann", "t", "p1", 5)).attempt, 1);
  EXPECT_EQ(store_->submit(attempt_of("ann", "s", "p1", 6)).attempt, 3);
  const std::vector<SubmissionRecord> ann = store_->submissions("ann", "s");  // oldest first
  std::vector<std::pair<std::string, int>> seen;
  for (const SubmissionRecord& r : ann) seen.emplace_back(r.problem, r.attempt);
  EXPECT_EQ(seen,
            (std::vector<std::pair<std::string, int>>{{"p1", 1}, {"p1", 2}, {"p2", 1}, {"p1", 3}}));
  EXPECT_EQ(ann[3].received, 6);
}

TEST_P(ServerStore, SubmissionsAtOnceGetEveryAttemptOnce) {
  constexpr int kThreads = 6, kEach = 5;
  std::vector<std::vector<int>> attempts(kThreads);
  std::vector<std::thread> threads;
  std::barrier start(kThreads);
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      start.arrive_and_wait();
      for (int i = 0; i < kEach; ++i)
        attempts[static_cast<std::size_t>(t)].push_back(
            store_->submit(attempt_of("ann", "s", "p1", t * 100 + i)).attempt);
    });
  for (std::thread& t : threads) t.join();
  std::multiset<int> all;
  for (const auto& a : attempts) all.insert(a.begin(), a.end());
  std::multiset<int> expected;
  for (int i = 1; i <= kThreads * kEach; ++i) expected.insert(i);
  EXPECT_EQ(all, expected);
}

TEST_P(ServerStore, DraftsKeepTheLatestWriteOfEachAnswer) {
  store_->save_draft("ann", Draft{"s", "p2", "z", "1", 100});
  store_->save_draft("ann", Draft{"s", "p1", "n", "(1,0,0)", 100});
  store_->save_draft("ann", Draft{"s", "p1", "n", "(0,1,0)", 300});
  store_->save_draft("ann", Draft{"s", "p1", "n", "stale", 200});  // arrived late: ignored
  store_->save_draft("ann", Draft{"t", "p1", "n", "other set", 400});
  store_->save_draft("bob", Draft{"s", "p1", "n", "bob's", 500});
  const std::vector<Draft> ann = store_->drafts("ann", "s");
  ASSERT_EQ(ann.size(), 2u);
  EXPECT_EQ(ann[0].problem, "p1");
  EXPECT_EQ(ann[0].text, "(0,1,0)");
  EXPECT_EQ(ann[0].saved, 300);
  EXPECT_EQ(ann[1].problem, "p2");
  EXPECT_EQ(ann[1].text, "1");
  ASSERT_EQ(store_->drafts("bob", "s").size(), 1u);
  EXPECT_EQ(store_->drafts("bob", "s")[0].text, "bob's");
  EXPECT_TRUE(store_->drafts("cid", "s").empty());
}

TEST_P(ServerStore, SessionsExpireAtTheirTime) {
  store_->put_student("ann", "hash-ann");
  store_->put_session("sess-1", SessionRecord{"ann", "csrf-1", 10'000});
  const std::optional<SessionRecord> live = store_->session("sess-1", 9'999);
  ASSERT_TRUE(live);
  EXPECT_EQ(live->student, "ann");
  EXPECT_EQ(live->csrf, "csrf-1");
  EXPECT_EQ(live->expires, 10'000);
  EXPECT_FALSE(store_->session("sess-1", 10'000));
  EXPECT_FALSE(store_->session("sess-unknown", 0));
  store_->put_session("sess-1", SessionRecord{"ann", "csrf-2", 20'000});  // renewed
  ASSERT_TRUE(store_->session("sess-1", 15'000));
  EXPECT_EQ(store_->session("sess-1", 15'000)->csrf, "csrf-2");
}

TEST_P(ServerStore, StudentsAreFoundByTheirTokenOnly) {
  store_->put_student("bob", "hash-bob");
  store_->put_student("Ann", "hash-ann");
  store_->put_student("ann", "hash-ann2");
  EXPECT_EQ(store_->students(), (std::vector<std::string>{"Ann", "ann", "bob"}));
  EXPECT_EQ(store_->student_by_token("hash-bob"), "bob");
  EXPECT_FALSE(store_->student_by_token("bob"));
  store_->put_student("bob", "hash-bob-new");  // a new link: the old one stops working
  EXPECT_FALSE(store_->student_by_token("hash-bob"));
  EXPECT_EQ(store_->student_by_token("hash-bob-new"), "bob");
}

TEST_P(ServerStore, NoStudentReachesAnothersSubmissions) {
  const SubmissionRecord ann = store_->submit(attempt_of("ann", "s", "p1", 1));
  const SubmissionRecord bob = store_->submit(attempt_of("bob", "s", "p1", 2));
  EXPECT_TRUE(store_->submission("ann", ann.id));
  EXPECT_FALSE(store_->submission("ann", bob.id));
  EXPECT_FALSE(store_->submission("bob", ann.id));
  EXPECT_FALSE(store_->submission("", ann.id));
  ASSERT_EQ(store_->submissions("bob", "s").size(), 1u);
  EXPECT_EQ(store_->submissions("bob", "s")[0].id, bob.id);
  EXPECT_TRUE(store_->submissions("cid", "s").empty());
}

TEST_P(ServerStore, TwoWorkersNeverHoldTheSameSubmission) {
  constexpr int kSubmissions = 40, kWorkers = 4;
  std::set<std::int64_t> submitted;
  for (int i = 0; i < kSubmissions; ++i)
    submitted.insert(store_->submit(attempt_of("s" + std::to_string(i % 7), "s", "p1", i)).id);
  // Each worker is an instance of its own, as on another machine.
  std::vector<std::vector<std::int64_t>> held(kWorkers);
  std::vector<std::thread> workers;
  std::barrier start(kWorkers);
  for (int w = 0; w < kWorkers; ++w)
    workers.emplace_back([&, w] {
      const std::unique_ptr<Store> instance = open_for_test(scratch_->url());
      const std::string name = "worker-" + std::to_string(w);
      start.arrive_and_wait();
      while (const std::optional<SubmissionRecord> s = instance->claim(name, 10'000, 60'000)) {
        held[static_cast<std::size_t>(w)].push_back(s->id);
        EXPECT_TRUE(instance->record_grade(grade_of(s->id, name, 3), name));
      }
    });
  for (std::thread& t : workers) t.join();
  std::multiset<std::int64_t> claimed;
  for (const auto& h : held) claimed.insert(h.begin(), h.end());
  EXPECT_EQ(claimed, std::multiset<std::int64_t>(submitted.begin(), submitted.end()));
  EXPECT_EQ(store_->pending_count(), 0);
  // One grade row per submission, counted in the database itself.
  EXPECT_EQ(scratch_->number("SELECT count(*) FROM grades"), kSubmissions);
  EXPECT_EQ(scratch_->number("SELECT count(DISTINCT submission) FROM grades"), kSubmissions);
}

TEST_P(ServerStore, ClaimsAreOldestFirstAndExpiredLeasesAreTakenAgain) {
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

TEST_P(ServerStore, AFailedGradingLeavesTheSubmissionFailed) {
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

TEST_P(ServerStore, TextIsKeptByteForByte) {
  NewSubmission n = attempt_of("ann", "s", "p1", 1);
  n.answers = "{\"z\":\"\\u00bd – ½ 'quoted' \\\"x\\\" $1 \\\\ ;DROP TABLE submissions;--\"}";
  const SubmissionRecord s = store_->submit(n);
  EXPECT_EQ(store_->submission("ann", s.id)->answers, n.answers);
  store_->save_draft("ann", Draft{"s", "p1", "z", "½ – \"x\"\n\ty", 1});
  EXPECT_EQ(store_->drafts("ann", "s").at(0).text, "½ – \"x\"\n\ty");
}

INSTANTIATE_TEST_SUITE_P(Postgres, ServerStore, ::testing::Values("postgresql"));

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
  const std::unique_ptr<Scratch> scratch = make_scratch("postgresql");
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
  for (int i = 0; i < 50 && PgConnection(scratch->url())
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
  const std::unique_ptr<Scratch> fresh = make_scratch("postgresql");
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
