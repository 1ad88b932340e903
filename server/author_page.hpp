// The authoring page, for instructors: a set's YAML edited in the browser (CodeMirror 5 from
// Debian's libjs-codemirror with its YAML mode; a plain textarea without JavaScript), previewed
// as the author types, and saved back to the course directory.
//
//   GET  /instructor/author/S           the page: the file as it is on disk, and its version
//   POST /instructor/author/S/preview   the text so far → the preview's JSON (author_preview.hpp),
//                                       made by a child process of the binary, time-bounded
//   POST /instructor/author/S/save      the text written over S.yaml atomically, the previous
//                                       file kept as COURSE/.frustum/history/S/TIME.yaml;
//                                       409 when the file changed since the page loaded it
//                                       (`base`, its SHA-256), 422 when check finds errors or a
//                                       sample graded otherwise (unless `force=1`: "save with
//                                       errors"); JSON when asked, else the page again
#pragma once

#include "server/session.hpp"

namespace frustum::server {

// `rest` is the path after /instructor/author/. 403 for anyone but an instructor.
Response author_routes(StudentApp& app, const Visitor& v, const Request& r, const std::string& rest,
                       Millis now);

}  // namespace frustum::server
