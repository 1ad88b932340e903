// The pages' frame: one HTML document with the page's own style and ES module and KaTeX, all
// served by the binary; headers that every response carries (a strict Content-Security-Policy:
// scripts and styles only from this server, inline style attributes for KaTeX only).
#pragma once

#include <string>

#include "server/course.hpp"
#include "server/http.hpp"
#include "server/phrases.hpp"

namespace frustum::server {

// The language of pages that belong to no set: the course's first set's.
Lang course_lang(const Course& course);

// A whole page; `csrf` goes into a meta tag for the module's requests ("" for none); `head`:
// the page's own further styles and scripts (from this server).
std::string page_html(Lang lang, const std::string& title, const std::string& body,
                      const std::string& csrf = "", bool refresh = false,
                      const std::string& head = "");
Response html_response(int status, std::string html);
Response json_response(int status, std::string json);
// A page that says one thing (a refusal, a missing page), with a link home.
Response message_page(int status, Lang lang, const Phrase& what, int retry_after = 0);
// Security headers on every response (added when not already set).
void secure_headers(Response& r);

}  // namespace frustum::server
