#include "app/serve_command.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <ostream>

#include "app/cli_options.hpp"
#include "batch/variant_files.hpp"
#include "server/author_preview.hpp"
#include "server/clock.hpp"
#include "server/http_server.hpp"
#include "server/instructors.hpp"
#include "server/student_app.hpp"
#include "server/tokens.hpp"
#include "server/worker.hpp"

namespace frustum::app {

namespace {

namespace fs = std::filesystem;
using server::Store;

// Thousands of idle keep-alive connections need as many descriptors.
void raise_descriptor_limit() {
  rlimit r{};
  if (::getrlimit(RLIMIT_NOFILE, &r) == 0 && r.rlim_cur < r.rlim_max) {
    r.rlim_cur = r.rlim_max;
    ::setrlimit(RLIMIT_NOFILE, &r);
  }
}

std::string db_url(const ServeOptions& s) {
  if (s.db) return *s.db;
  const fs::path dir = fs::path(s.course) / ".frustum";
  fs::create_directories(dir);
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::replace);
  return "sqlite:" + (dir / "serve.sqlite").string();
}

std::pair<std::string, unsigned short> host_port(const std::string& listen) {
  const auto colon = listen.rfind(':');
  if (colon == std::string::npos)
    throw std::runtime_error("--listen " + listen + ": expected HOST:PORT");
  const int port = std::stoi(listen.substr(colon + 1));
  if (port < 0 || port > 65535) throw std::runtime_error("--listen " + listen + ": no such port");
  return {listen.substr(0, colon), static_cast<unsigned short>(port)};
}

bool load(const ServeOptions& s, const Output& o, server::Course& course) {
  const std::string roster = (fs::path(s.course) / "roster.csv").string();
  if (!fs::exists(roster)) {
    o.err << "error: " << roster << ": missing (a CSV with a student column: who is served)\n";
    return false;
  }
  course = server::load_course(s.course, read_roster(roster));
  const fs::path instructors = fs::path(s.course) / "instructors.csv";
  if (fs::exists(instructors)) {
    course.instructors = server::read_instructors(instructors.string());
    for (const std::string& id : course.instructors)
      if (course.enrolled(id))
        course.errors.push_back(Diagnostic{SourceLocation{instructors.string(), 0, 0}, "instructor",
                                           "'" + id +
                                               "' is also on the roster: an id is a student's "
                                               "or an instructor's, not both"});
  }
  for (const Diagnostic& d : course.errors) o.err << d.format() << "\n";
  return course.errors.empty();
}

// student,url,role for every student and instructor without a link (and the rotated ones), in
// a file only its owner reads; the store keeps the tokens' hashes only.
int issue_links(const ServeOptions& s, const server::Course& course, Store& store,
                const Output& o) {
  const std::string base = s.public_url.empty() ? "http://" + s.listen : s.public_url;
  std::string csv = "student,url,role\n";
  int issued = 0;
  const auto issue = [&](const std::vector<std::string>& ids, const std::vector<std::string>& have,
                         server::Role role) {
    for (const std::string& id : ids) {
      const bool rotate = std::find(s.rotate.begin(), s.rotate.end(), id) != s.rotate.end();
      if (!rotate && std::binary_search(have.begin(), have.end(), id)) continue;
      const std::string token = server::random_token();
      if (role == server::Role::Instructor)
        store.put_instructor(id, server::sha256_hex(token));
      else
        store.put_student(id, server::sha256_hex(token));
      csv += id + "," + base + "/start?token=" + token + "," +
             (role == server::Role::Instructor ? "instructor" : "student") + "\n";
      ++issued;
    }
  };
  issue(course.roster, store.students(), server::Role::Student);
  issue(course.instructors, store.instructors(), server::Role::Instructor);
  const int fd = ::open(s.issue_links->c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0 || ::fchmod(fd, 0600) != 0 ||
      ::write(fd, csv.data(), csv.size()) != static_cast<ssize_t>(csv.size()) || ::fsync(fd) != 0) {
    if (fd >= 0) ::close(fd);
    o.err << "error: " << *s.issue_links << ": cannot write the links\n";
    return 1;
  }
  ::close(fd);
  o.out << *s.issue_links << ": " << issued << " link" << (issued == 1 ? "" : "s") << " issued\n";
  return 0;
}

int serve(const ServeOptions& s, const server::Course& course, Store& store, const std::string& url,
          const Output& o) {
  raise_descriptor_limit();
  // Workers first: processes of this binary, started by posix_spawn (no fork of a threaded
  // server).
  server::WorkerPool workers(
      {"serve", s.course, "--grade-seconds", std::to_string(s.grade_seconds)}, s.workers,
      {"FRUSTUM_DB=" + url});  // in the environment: a password never shows in `ps`
  server::StudentAppOptions app_options;
  app_options.secure_cookies = s.secure_cookies;
  app_options.preview_rate = s.preview_rate;
  app_options.preview_burst = 3 * s.preview_rate;
  app_options.submit_rate = s.submit_rate;
  app_options.submit_burst = std::max(10.0, 3 * s.submit_rate);
  // A set file changed while serving that no longer loads: its errors, and the set stays served
  // as it was.
  app_options.report = [&o](const std::vector<Diagnostic>& errors) {
    for (const Diagnostic& d : errors)
      o.err << d.format() << " (still serving the set as it was)\n";
  };
  server::StudentApp app(course, store, app_options);
  server::HttpServerOptions http;
  std::tie(http.host, http.port) = host_port(s.listen);
  http.limits.max_connections = s.max_connections;
  http.limits.max_in_flight = s.max_in_flight;
  http.on_listening = [&](unsigned short port) {
    o.err << "frustum serve: " << course.sets.size() << " sets, " << course.roster.size()
          << " students, " << s.workers << " grading workers; listening on http://" << http.host
          << ":" << port << std::endl;
  };
  if (s.access_log) http.log = [&](const std::string& line) { o.err << line << "\n"; };
  server::run_http_server(http, [&](const server::Request& r) {
    return server::handle_student(app, r, server::now_ms());
  });
  return 0;
}

// The set on stdin (bounded), previewed as the authoring page shows it: JSON on stdout.
int author_preview(const ServeOptions& s, const Output& o) {
  server::AuthorPreviewRequest r;
  r.name = *s.author_preview;
  r.student = s.author_student;
  r.check_only = s.author_check;
  std::vector<char> buffer(server::kMaxAuthoredSetBytes + 1);
  std::cin.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
  const auto got = static_cast<std::size_t>(std::cin.gcount());
  if (got > server::kMaxAuthoredSetBytes) {
    o.err << "error: the set is larger than " << server::kMaxAuthoredSetBytes << " bytes\n";
    return 1;
  }
  r.yaml.assign(buffer.data(), got);
  const std::string roster = (fs::path(s.course) / "roster.csv").string();
  if (fs::exists(roster)) r.roster = read_roster(roster);
  o.out << server::author_preview_json(r) << "\n";
  return 0;
}

}  // namespace

namespace {

CLI::App* add_serve_options(CLI::App& cli, ServeOptions& s) {
  CLI::App* c = cli.add_subcommand(
      "serve", "Serve a course: students open their links, answer in the browser, get feedback");
  c->add_option("course", s.course, "Course directory: problem sets (*.yaml) and roster.csv")
      ->required()
      ->check(CLI::ExistingDirectory);
  c->add_option("--db", s.db,
                "Database: sqlite:PATH (default COURSE/.frustum/serve.sqlite) or postgresql://… "
                "(a password: in PGPASSWORD, ~/.pgpass or FRUSTUM_DB, not on the command line)")
      ->envname("FRUSTUM_DB");
  c->add_option("--listen", s.listen, "Address to listen on (default 127.0.0.1:8080)");
  c->add_option("--issue-links", s.issue_links,
                "Write student,url,role for every student (roster.csv) and instructor "
                "(instructors.csv) without a link to this file (mode 0600), then exit");
  c->add_option("--rotate", s.rotate, "With --issue-links: issue these students new links");
  c->add_option("--public-url", s.public_url,
                "The links' address as students reach it (default http://LISTEN)");
  c->add_option("--workers", s.workers, "Grading worker processes (default 2)")
      ->check(CLI::Range(1, 64));
  c->add_option("--grade-seconds", s.grade_seconds, "Time to grade one submission (default 10)")
      ->check(CLI::Range(1, 600));
  c->add_flag("--secure-cookies", s.secure_cookies, "Mark cookies Secure (behind a TLS proxy)");
  c->add_flag("--access-log", s.access_log, "Log each request (method, path, status) to stderr");
  c->add_option("--max-connections", s.max_connections, "Connections held at once");
  c->add_option("--max-in-flight", s.max_in_flight,
                "Requests handled at once; beyond, 429 with Retry-After");
  c->add_option("--preview-rate", s.preview_rate,
                "Previews and drafts a session may ask a second (default 10; 429 beyond)");
  c->add_option("--submit-rate", s.submit_rate,
                "Submissions a session may make a second (default 1, bursts of 10; 429 beyond)");
  c->add_option("--worker", s.worker, "")->group("");  // internal: a grading worker
  // internal: the authoring page's preview, run in a process of its own
  c->add_option("--author-preview", s.author_preview, "")->group("");
  c->add_option("--author-student", s.author_student, "")->group("");
  c->add_flag("--author-check", s.author_check, "")->group("");
  return c;
}

}  // namespace

Command add_serve_command(CLI::App& cli) {
  auto opt = std::make_shared<ServeOptions>();
  CLI::App* serve = add_serve_options(cli, *opt);
  return {serve, [opt](const Output& o) { return run_serve(*opt, o); }};
}

int run_serve(const ServeOptions& s, const Output& o) {
  if (s.author_preview) return author_preview(s, o);
  server::Course course;
  if (!load(s, o, course)) return 1;
  const std::string url = db_url(s);
  const std::unique_ptr<Store> store =
      server::open_store(url, s.worker ? server::StoreRole::Worker : server::StoreRole::Server);
  if (s.worker) {
    server::WorkerOptions w;
    w.seconds = s.grade_seconds;
    const std::atomic<bool> never{false};
    return server::run_worker(std::move(course), *store, *s.worker, w, never);
  }
  if (s.issue_links) return issue_links(s, course, *store, o);
  return serve(s, course, *store, url, o);
}

}  // namespace frustum::app
