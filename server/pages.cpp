#include "server/pages.hpp"

#include <fmt/format.h>

namespace frustum::server {

namespace {

constexpr const char* kCsp =
    "default-src 'none'; script-src 'self'; style-src 'self'; style-src-attr 'unsafe-inline'; "
    "font-src 'self'; img-src 'self' data:; connect-src 'self'; form-action 'self'; "
    "frame-ancestors 'none'; base-uri 'none'";

}  // namespace

Lang course_lang(const Course& course) {
  return course.sets.empty() ? Lang::En : course.sets.front().set.lang;
}

std::string page_html(Lang lang, const std::string& title, const std::string& body,
                      const std::string& csrf, bool refresh, const std::string& head) {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"{}\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "{}{}<title>{}</title>\n"
      "<link rel=\"stylesheet\" href=\"/static/katex/katex.min.css\">\n"
      "<link rel=\"stylesheet\" href=\"/static/page.css\">\n"
      "<script defer src=\"/static/katex/katex.min.js\"></script>\n"
      "<script type=\"module\" src=\"/static/page.js\"></script>\n"
      "{}</head>\n<body>\n{}</body>\n</html>\n",
      to_string(lang), csrf.empty() ? "" : "<meta name=\"csrf\" content=\"" + csrf + "\">\n",
      refresh ? "<meta http-equiv=\"refresh\" content=\"2\">\n" : "", html_escape(title), head,
      body);
}

Response html_response(int status, std::string html) {
  return Response{status,
                  {{"Content-Type", "text/html; charset=utf-8"}, {"Cache-Control", "no-store"}},
                  std::move(html)};
}

Response json_response(int status, std::string json) {
  return Response{status,
                  {{"Content-Type", "application/json"}, {"Cache-Control", "no-store"}},
                  std::move(json)};
}

Response message_page(int status, Lang lang, const Phrase& what, int retry_after) {
  const std::string body =
      fmt::format("<main>\n<p class=\"message\">{}</p>\n<p><a href=\"/\">{}</a></p>\n</main>\n",
                  html_escape(what.in(lang)), html_escape(kAllSets.in(lang)));
  Response r = html_response(status, page_html(lang, std::string(what.in(lang)), body));
  if (retry_after > 0) r.set("Retry-After", std::to_string(retry_after));
  return r;
}

void secure_headers(Response& r) {
  const auto add = [&](const char* name, const char* value) {
    if (!r.header(name)) r.set(name, value);
  };
  add("Content-Security-Policy", kCsp);
  add("X-Content-Type-Options", "nosniff");
  add("Referrer-Policy", "same-origin");  // "no-referrer" makes a form's Origin "null"
  add("X-Frame-Options", "DENY");
}

}  // namespace frustum::server
