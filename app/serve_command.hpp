// `frustum serve COURSE_DIR [--db sqlite:PATH | --db postgresql://…] [--listen HOST:PORT]`:
// students open their links and answer in the browser (server/). Registered on the command
// line by add_serve_command (app/cli_options.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/commands.hpp"

namespace CLI {
class App;
}

namespace frustum::app {

struct ServeOptions {
  std::string course;
  std::optional<std::string> db;  // default sqlite:COURSE/.frustum/serve.sqlite
  std::string listen = "127.0.0.1:8080";
  std::optional<std::string> issue_links;  // write student,url for students without a link
  std::vector<std::string> rotate;         // students whose links are issued anew
  std::string public_url;                  // the links' start (default http://LISTEN)
  int workers = 2;
  int grade_seconds = 10;
  bool secure_cookies = false;
  bool access_log = false;
  std::size_t max_connections = 10000;
  std::size_t max_in_flight = 256;
  double preview_rate = 10;  // per session, a second (the burst is three times as many)
  double submit_rate = 1;
  std::optional<std::string> worker;  // internal: run as grading worker NAME
  // internal: the authoring page's preview of the set on stdin, named NAME (server/author_preview)
  std::optional<std::string> author_preview;
  std::string author_student;  // whose variant it shows ("" for the set as written)
  bool author_check = false;   // errors and samples only
};

int run_serve(const ServeOptions& options, const Output& o);

}  // namespace frustum::app
