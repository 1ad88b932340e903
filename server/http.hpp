// HTTP as plain data: what a handler gets and gives back. Nothing here knows about sockets, so
// every handler is tested by calling it (http_beast.cpp alone speaks the protocol).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frustum::server {

struct Request {
  std::string method;  // "GET", "POST", …
  std::string target;  // path and query as sent: "/set/week1?x=1"
  std::vector<std::pair<std::string, std::string>> headers;  // names lower-case
  std::string body;
  std::string peer;  // the client's address (the proxy's, behind one)

  std::optional<std::string> header(const std::string& lower_name) const;
  std::string path() const;  // target without the query
  std::string query() const;
};

struct Response {
  int status = 200;
  std::vector<std::pair<std::string, std::string>> headers;
  std::string body;

  Response& set(const std::string& name, const std::string& value);
  std::optional<std::string> header(const std::string& name) const;  // case-insensitive
};

using Handler = std::function<Response(const Request&)>;

// A=1&b=%20… (application/x-www-form-urlencoded, also a query) into name → value; a repeated
// name keeps its first value. Malformed escapes are kept as written.
std::map<std::string, std::string> parse_form(const std::string& text);
std::string url_decode(const std::string& text);
std::string url_encode(const std::string& text);
// The cookies of a Cookie header.
std::map<std::string, std::string> parse_cookies(const std::string& header);

// Text for an HTML element or a double-quoted attribute: & < > " ' as entities.
std::string html_escape(std::string_view text);

// The status line's reason ("Not Found").
const char* status_reason(int status);

}  // namespace frustum::server
