// Escaping text for SVG and HTML pages: the five special characters become entities, every other
// byte (UTF-8 included) is copied as it is.
#include "solver/derivation/svg.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace frustum {
namespace {

std::string escaped_one_by_one(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else if (c == '\'')
      out += "&#39;";
    else
      out += c;
  }
  return out;
}

TEST(SvgEscape, EveryEntityAndEveryOtherByte) {
  EXPECT_EQ(svg_escape(""), "");
  EXPECT_EQ(svg_escape("a<b & c>'d'\"e\""), "a&lt;b &amp; c&gt;&#39;d&#39;&quot;e&quot;");
  EXPECT_EQ(svg_escape("&&"), "&amp;&amp;");
  EXPECT_EQ(svg_escape("‖n‖ = √134 ≈ 11.58"), "‖n‖ = √134 ≈ 11.58");
  EXPECT_EQ(svg_escape(std::string("a\0<b", 4)), std::string("a\0&lt;b", 7));
  // Property: the same as escaping byte by byte, over random texts of special and plain bytes.
  std::mt19937 rng(7);
  const std::string alphabet = "ab &<>\"'\xE2\x80\x96z";
  for (int i = 0; i < 2000; ++i) {
    std::string text(rng() % 40, ' ');
    for (char& c : text) c = alphabet[rng() % alphabet.size()];
    EXPECT_EQ(svg_escape(text), escaped_one_by_one(text)) << text;
  }
}

}  // namespace
}  // namespace frustum
