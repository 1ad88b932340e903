// Files the pages load, all from the binary: the page's module and style (compiled in) and
// KaTeX from Debian's libjs-katex (/usr/share/javascript/katex, read once), and CodeMirror 5
// from libjs-codemirror (/usr/share/javascript/codemirror) for the authoring page.
#pragma once

#include <optional>

#include "server/http.hpp"

namespace frustum::server {

// The response for GET /static/PATH, or nullopt when there is no such file.
std::optional<Response> static_asset(const std::string& path);

}  // namespace frustum::server
