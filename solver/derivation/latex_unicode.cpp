#include "solver/derivation/latex_unicode.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

namespace frustum {

namespace {

// Commands read as one Unicode text; a command not listed is kept as written.
constexpr std::pair<std::string_view, std::string_view> kSymbols[] = {
    {"cdot", "·"},   {"times", "×"},      {"lVert", "‖"}, {"rVert", "‖"},       {"lvert", "|"},
    {"rvert", "|"},  {"theta", "θ"},      {"pi", "π"},    {"iff", "⇔"},         {"le", "≤"},
    {"ge", "≥"},     {"leq", "≤"},        {"geq", "≥"},   {"ne", "≠"},          {"neq", "≠"},
    {"approx", "≈"}, {"infty", "∞"},      {"to", "→"},    {"Rightarrow", "⇒"},  {"lambda", "λ"},
    {"sin", "sin"},  {"cos", "cos"},      {"tan", "tan"}, {"arccos", "arccos"}, {"min", "min"},
    {"max", "max"},  {"alpha", "α"},      {"beta", "β"},  {"gamma", "γ"},       {"kappa", "κ"},
    {"Delta", "Δ"},  {"in", "∈"},         {"cdots", "⋯"}, {"ldots", "…"},       {"pm", "±"},
    {"circ", "°"},   {"colon", ":"},      {"quad", "  "}, {"qquad", "    "},    {"left", ""},
    {"right", ""},   {"displaystyle", ""}};
// Subscripts and superscripts Unicode has a character for.
constexpr std::pair<char, std::string_view> kSubscripts[] = {
    {'0', "₀"}, {'1', "₁"}, {'2', "₂"}, {'3', "₃"}, {'4', "₄"}, {'5', "₅"},
    {'6', "₆"}, {'7', "₇"}, {'8', "₈"}, {'9', "₉"}, {'x', "ₓ"}};
constexpr std::pair<std::string_view, std::string_view> kSuperscripts[] = {
    {"2", "²"}, {"3", "³"}, {"-1", "⁻¹"}, {"−1", "⁻¹"}, {"T", "ᵀ"}, {"°", "°"}};

class Reader {
 public:
  explicit Reader(std::string_view s) : s_(s) {}

  std::string all() {
    std::string out;
    while (i_ < s_.size()) one(out);
    return out;
  }

 private:
  // The text of the brace group at i_ ({…}, nested braces kept), or the one character there.
  std::string_view group() {
    while (i_ < s_.size() && s_[i_] == ' ') ++i_;
    if (i_ >= s_.size()) return {};
    if (s_[i_] == '\\') {  // a command is one token (x^\circ)
      std::size_t j = i_ + 1;
      while (j < s_.size() && std::isalpha(static_cast<unsigned char>(s_[j]))) ++j;
      const std::string_view g = s_.substr(i_, std::max<std::size_t>(j, i_ + 2) - i_);
      i_ += g.size();
      return g;
    }
    if (s_[i_] != '{') return s_.substr(i_++, 1);
    int depth = 0;
    for (std::size_t j = i_; j < s_.size(); ++j) {
      depth += s_[j] == '{' ? 1 : s_[j] == '}' ? -1 : 0;
      if (depth == 0) {
        const std::string_view g = s_.substr(i_ + 1, j - i_ - 1);
        i_ = j + 1;
        return g;
      }
    }
    const std::string_view g = s_.substr(i_ + 1);
    i_ = s_.size();
    return g;
  }

  static std::string inner(std::string_view g) { return Reader(g).all(); }

  // (a + b) when a holds a space or a sign, as a fraction's part written on one line.
  static std::string part(const std::string& t) {
    const bool wrap = t.find(' ') != std::string::npos || t.find('+') != std::string::npos ||
                      t.find("−") != std::string::npos || t.find('-') != std::string::npos;
    return wrap ? "(" + t + ")" : t;
  }

  void command(std::string& out) {
    std::size_t j = i_ + 1;
    while (j < s_.size() && std::isalpha(static_cast<unsigned char>(s_[j]))) ++j;
    if (j == i_ + 1) {  // \, \; \! \\ and escaped characters
      const char c = i_ + 1 < s_.size() ? s_[i_ + 1] : ' ';
      i_ += 2;
      if (c == ',' || c == ';' || c == ' ')
        out += ' ';
      else if (c == '\\')
        out += "; ";
      else if (c != '!')
        out += c;
      return;
    }
    const std::string_view name = s_.substr(i_ + 1, j - i_ - 1);
    i_ = j;
    if (name == "text") {
      out += group();
      return;
    }
    if (name == "mathbf" || name == "mathrm") {
      out += inner(group());
      return;
    }
    if (name == "hat" || name == "tilde") {
      out += inner(group()) + (name == "hat" ? "\u0302" : "\u0303");
      return;
    }
    if (name == "frac" || name == "tfrac") {
      const std::string a = inner(group()), b = inner(group());
      out += part(a) + "/" + part(b);
      return;
    }
    if (name == "sqrt") {
      out += "√" + inner(group());
      return;
    }
    for (const auto& [command, text] : kSymbols)
      if (command == name) {
        out += text;
        return;
      }
    out += "\\";
    out += name;
  }

  void script(std::string& out, bool sub) {
    ++i_;
    const std::string g = inner(group());
    if (sub) {
      std::string chars;
      for (const char c : g) {
        bool found = false;
        for (const auto& [ch, text] : kSubscripts)
          if (ch == c) {
            chars += text;
            found = true;
          }
        if (!found) {
          out += "_" + g;
          return;
        }
      }
      out += chars;
      return;
    }
    for (const auto& [from, to] : kSuperscripts)
      if (from == g) {
        out += to;
        return;
      }
    out += "^" + g;
  }

  void one(std::string& out) {
    const char c = s_[i_];
    if (c == '\\') return command(out);
    if (c == '_' || c == '^') return script(out, c == '_');
    ++i_;
    if (c == '-')
      out += "−";
    else if (c == '\'')
      out += "′";
    else if (c != '{' && c != '}')
      out += c;
  }

  std::string_view s_;
  std::size_t i_ = 0;
};

}  // namespace

std::string unicode_of_latex(std::string_view latex) { return Reader(latex).all(); }

}  // namespace frustum
