// What the tests of `frustum serve`'s handlers share: the sets of their course and reading a
// session cookie and a page's CSRF token, and the check of every phrase's languages.
#pragma once

#include <gtest/gtest.h>

#include <regex>
#include <span>
#include <string>

#include "server/http.hpp"
#include "solver/derivation/i18n.hpp"

namespace frustum::server::test {

inline constexpr const char* kWeek1 = R"(title: "Depth"
problems:
  - id: zbuf
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    ask: [normal, plane, z]
)";

// Every student their own triangle.
inline constexpr const char* kVaried = R"(title: "Back faces"
variants: per_student
problems:
  - id: bf
    kind: backface
    given: {points: [[1,0,0],[1,1,1],[0,1,2]], eye: [0,1,0]}
    ask: [df, facing]
)";

// The session cookie's value that a sign-in's response sets.
inline std::string session_cookie(const Response& start) {
  EXPECT_EQ(start.status, 303);
  const std::string cookie = start.header("Set-Cookie").value_or("");
  std::smatch m;
  EXPECT_TRUE(std::regex_search(cookie, m, std::regex("frustum_session=([0-9a-f]{32})")));
  return m[1].str();
}

// The CSRF token a page carries for its module.
inline std::string csrf_in(const std::string& page) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(page, m, std::regex("name=\"csrf\" content=\"([0-9a-f]+)\"")));
  return m[1].str();
}

// Every phrase of a page's list has all three languages, and no English in Japanese or Russian.
inline void expect_three_languages(std::span<const Phrase* const> phrases) {
  for (std::size_t i = 0; i < phrases.size(); ++i) {
    const std::string en(phrases[i]->in(Lang::En)), ja(phrases[i]->in(Lang::Ja)),
        ru(phrases[i]->in(Lang::Ru));
    EXPECT_FALSE(en.empty()) << i;
    EXPECT_NE(ja, en) << en;
    EXPECT_NE(ru, en) << en;
    EXPECT_FALSE(std::regex_search(ja, std::regex("[A-Za-z]{2,}"))) << ja;
    EXPECT_FALSE(std::regex_search(ru, std::regex("[A-Za-z]{2,}"))) << ru;
  }
}

}  // namespace frustum::server::test
