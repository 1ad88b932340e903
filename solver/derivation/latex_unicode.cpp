#include "solver/derivation/latex_unicode.hpp"

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

#include "solver/util/scripts.hpp"

namespace frustum {

namespace {

// Commands read as one Unicode text; a command not listed is kept as written.
constexpr std::pair<std::string_view, std::string_view> kSymbols[] = {
    {"cdot", "·"},   {"theta", "θ"},      {"pi", "π"},
    {"iff", "⇔"},    {"le", "≤"},         {"ge", "≥"},
    {"leq", "≤"},    {"geq", "≥"},        {"ne", "≠"},
    {"neq", "≠"},    {"approx", "≈"},     {"infty", "∞"},
    {"to", "→"},     {"Rightarrow", "⇒"}, {"Leftrightarrow", "⇔"},
    {"equiv", "≡"},  {"mapsto", "↦"},     {"forall", "∀"},
    {"lambda", "λ"}, {"alpha", "α"},      {"beta", "β"},
    {"gamma", "γ"},  {"kappa", "κ"},      {"Delta", "Δ"},
    {"sum", "Σ"},    {"in", "∈"},         {"cdots", "⋯"},
    {"ldots", "…"},  {"dots", "…"},       {"pm", "±"},
    {"circ", "°"},   {"bigcirc", "○"},    {"colon", ":"}};
// Named functions: written upright, a space between the name and an argument that is not in
// parentheses (sin θ, tan 30°), a fraction argument put in parentheses (tan(fovy/2)).
constexpr std::string_view kFunctions[] = {"sin",    "cos", "tan", "arccos", "arcsin",
                                           "arctan", "min", "max", "sign"};
// Commands that only typeset their argument differently (bold, upright, sans-serif, a binary
// operator's spacing): the Unicode is the argument.
// \overrightarrow{AB}, the vector from A to B, is written AB on one line, as bold is dropped;
// \mathord{\times} is a × that is a mark, not an operator.
constexpr std::string_view kStyles[] = {"mathbf",  "mathrm",     "mathsf",
                                        "mathtt",  "mathit",     "mathbin",
                                        "mathord", "boldsymbol", "overrightarrow"};
// Subscripts and superscripts Unicode has a character for.
constexpr std::pair<std::string_view, std::string_view> kSubscripts[] = {
    {"0", "₀"}, {"1", "₁"}, {"2", "₂"}, {"3", "₃"}, {"4", "₄"}, {"5", "₅"}, {"6", "₆"},
    {"7", "₇"}, {"8", "₈"}, {"9", "₉"}, {"x", "ₓ"}, {"i", "ᵢ"}, {"+", "₊"}, {"−", "₋"}};
constexpr std::pair<std::string_view, std::string_view> kSuperscripts[] = {
    {"2", "²"}, {"3", "³"}, {"-1", "⁻¹"}, {"−1", "⁻¹"}, {"T", "ᵀ"}, {"°", "°"}};

bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }

void trim_right(std::string& s) {
  while (!s.empty() && s.back() == ' ') s.pop_back();
}

// Whether the text ends with something a factor may follow (a letter, a digit, a closing
// bracket, an index), not with an operator, a relation, a comma or a space.
bool ends_with_operand(std::string_view s) {
  if (s.empty()) return false;
  const std::vector<std::string_view> cs = characters_of(s);
  const std::string_view last = cs.back();
  if (last.size() == 1) {
    const char c = last[0];
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == ')' || c == ']';
  }
  static constexpr std::string_view kNotOperands[] = {"−", "×", "·", "≤", "≥", "≠", "≈", "∈",
                                                      "→", "⇒", "⇔", "≡", "↦", "∀", "Σ", "√"};
  return std::find(std::begin(kNotOperands), std::end(kNotOperands), last) ==
         std::end(kNotOperands);
}

// Whether the text holds, outside every bracket ((…), [, ], ‖…‖, |…|), one of the given
// characters: what decides whether a part written on one line needs parentheses around it.
bool holds_outside_brackets(std::string_view t, std::initializer_list<std::string_view> chars) {
  int depth = 0;
  bool in_norm = false, in_abs = false;
  for (const std::string_view c : characters_of(t)) {
    if (c == "(" || c == "[") {
      ++depth;
    } else if (c == ")" || c == "]") {
      --depth;
    } else if (c == "‖") {
      in_norm = !in_norm;
    } else if (c == "|") {
      in_abs = !in_abs;
    } else if (depth == 0 && !in_norm && !in_abs &&
               std::find(chars.begin(), chars.end(), c) != chars.end()) {
      return true;
    }
  }
  return false;
}

// A part of a fraction or a root written on one line, in parentheses where it would otherwise
// be read wrongly: a sum, a product written with a space, a quotient; below the bar (and
// under a root) also a product written with · or ×.
std::string operand(std::string_view t, bool below) {
  bool wrap = false;
  if (below) {
    // A number times a root (3√6) is a product too.
    const std::string_view after_first = t.empty() ? t : t.substr(characters_of(t).front().size());
    wrap = holds_outside_brackets(t, {" ", "+", "−", "-", "/", "·", "×"}) ||
           holds_outside_brackets(after_first, {"√"});
  } else {
    wrap = holds_outside_brackets(t, {" ", "+", "−", "-", "/"});
  }
  return wrap ? "(" + std::string(t) + ")" : std::string(t);
}

bool holds_any(std::string_view t, std::initializer_list<std::string_view> parts) {
  return std::any_of(parts.begin(), parts.end(),
                     [&](std::string_view p) { return t.find(p) != std::string_view::npos; });
}

class Reader {
 public:
  explicit Reader(std::string_view s) : s_(s) {}

  std::string all() {
    std::string out;
    while (i_ < s_.size()) one(out);
    return out;
  }

 private:
  void skip_spaces() {
    while (i_ < s_.size() && s_[i_] == ' ') ++i_;
  }

  // The name of the command at i_ (a backslash and letters), or empty.
  std::string_view command_at(std::size_t at) const {
    if (at >= s_.size() || s_[at] != '\\') return {};
    std::size_t j = at + 1;
    while (j < s_.size() && is_alpha(s_[j])) ++j;
    return s_.substr(at + 1, j - at - 1);
  }

  // The text of the brace group at i_ ({…}, nested braces kept), or the one token there.
  std::string_view group() {
    skip_spaces();
    if (i_ >= s_.size()) return {};
    if (s_[i_] == '\\') {  // a command is one token (x^\circ)
      const std::size_t n = std::max<std::size_t>(command_at(i_).size() + 1, 2);
      const std::string_view g = s_.substr(i_, n);
      i_ += g.size();
      return g;
    }
    if (s_[i_] != '{') {
      const std::size_t n = characters_of(s_.substr(i_, 4)).front().size();
      const std::string_view g = s_.substr(i_, n);
      i_ += n;
      return g;
    }
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

  // A matrix environment's body: rows split at \\, entries at &, each read on its own.
  void matrix(std::string& out, std::string_view environment) {
    const std::string end = "\\end{" + std::string(environment) + "}";
    const std::size_t stop = s_.find(end, i_);
    const std::string_view body =
        s_.substr(i_, stop == std::string_view::npos ? s_.npos : stop - i_);
    i_ = stop == std::string_view::npos ? s_.size() : stop + end.size();
    const bool round = environment == "pmatrix";
    out += round ? "(" : "[";
    std::size_t row_start = 0;
    bool first_row = true;
    while (row_start <= body.size()) {
      std::size_t row_end = body.find("\\\\", row_start);
      if (row_end == std::string_view::npos) row_end = body.size();
      const std::string_view row = body.substr(row_start, row_end - row_start);
      if (!first_row) out += "; ";
      first_row = false;
      std::size_t cell_start = 0;
      bool first_cell = true;
      while (cell_start <= row.size()) {
        std::size_t cell_end = row.find('&', cell_start);
        if (cell_end == std::string_view::npos) cell_end = row.size();
        std::string cell = inner(row.substr(cell_start, cell_end - cell_start));
        trim_right(cell);
        cell.erase(0, cell.find_first_not_of(' ') == std::string::npos
                          ? cell.size()
                          : cell.find_first_not_of(' '));
        if (!first_cell) out += ", ";
        first_cell = false;
        out += cell;
        cell_start = cell_end + 1;
      }
      row_start = row_end + 2;
    }
    out += round ? ")" : "]";
  }

  // A named function: a product's dot before it right after a factor (n·tan), then its argument.
  void function(std::string& out, std::string_view name) {
    if (ends_with_operand(out)) out += "·";
    out += name;
    skip_spaces();
    const std::string_view next = command_at(i_);
    if (next == "frac" || next == "tfrac") {
      i_ += next.size() + 1;
      const std::string a = inner(group()), b = inner(group());
      out += "(" + fraction_unicode(a, b) + ")";
    } else if (i_ < s_.size() && s_[i_] != '(' && next != "left" && s_[i_] != '_' &&
               s_[i_] != '^') {
      out += ' ';
    }
  }

  // \, between two factors is a product (a·x); elsewhere a thin space.
  void thin_space(std::string& out) {
    skip_spaces();
    const bool factor_follows =
        i_ < s_.size() &&
        (std::isalnum(static_cast<unsigned char>(s_[i_])) != 0 || s_[i_] == '(' || [&] {
          const std::string_view c = command_at(i_);
          return c == "mathbf" || c == "text" || c == "mathrm" || c == "hat" || c == "tilde" ||
                 c == "frac" || c == "lVert" || c == "left" || c == "theta" || c == "lambda";
        }());
    out += ends_with_operand(out) && factor_follows ? "·" : " ";
  }

  void command(std::string& out) {
    const std::string_view name = command_at(i_);
    if (name.empty()) {  // \, \; \! \\ and escaped characters
      const char c = i_ + 1 < s_.size() ? s_[i_ + 1] : ' ';
      i_ += 2;
      if (c == ',')
        thin_space(out);
      else if (c == ';' || c == ' ')
        out += ' ';
      else if (c == '\\')
        out += "; ";
      else if (c != '!')
        out += c;
      return;
    }
    i_ += name.size() + 1;
    if (name == "text") {
      out += group();
      return;
    }
    if (std::find(std::begin(kStyles), std::end(kStyles), name) != std::end(kStyles)) {
      out += inner(group());
      return;
    }
    if (name == "hat" || name == "tilde") {
      out += inner(group()) + (name == "hat" ? "\u0302" : "\u0303");
      return;
    }
    if (name == "frac" || name == "tfrac") {
      const std::string a = inner(group()), b = inner(group());
      out += fraction_unicode(a, b);
      return;
    }
    if (name == "sqrt") {
      const std::string a = inner(group());
      out += "√" + operand(a, true);
      return;
    }
    if (name == "operatorname") {
      function(out, inner(group()));
      return;
    }
    if (std::find(std::begin(kFunctions), std::end(kFunctions), name) != std::end(kFunctions)) {
      function(out, name);
      return;
    }
    if (name == "begin") {
      matrix(out, group());
      return;
    }
    if (name == "times") {  // a binary operator: one space on each side (a mark when first)
      const bool first = out.empty();
      trim_right(out);
      out += first ? "×" : " × ";
      skip_spaces();
      return;
    }
    if (name == "cdot") {  // as tight on the right as on the left: a·b, a · b
      const bool spaced = !out.empty() && out.back() == ' ';
      trim_right(out);
      out += spaced ? " · " : "·";
      skip_spaces();
      return;
    }
    if (name == "quad" || name == "qquad") {  // a wide space, whatever spaces stand around it
      trim_right(out);
      out += name == "quad" ? "  " : "    ";
      skip_spaces();
      return;
    }
    if (name == "left" || name == "lVert" || name == "lvert" || name == "displaystyle") {
      out += name == "lVert" ? "‖" : name == "lvert" ? "|" : "";
      skip_spaces();  // nothing between an opening bracket and what it opens
      return;
    }
    if (name == "right" || name == "rVert" || name == "rvert") {
      trim_right(out);
      out += name == "rVert" ? "‖" : name == "rvert" ? "|" : "";
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
      for (const std::string_view c : characters_of(g)) {
        const auto* found = std::find_if(std::begin(kSubscripts), std::end(kSubscripts),
                                         [&](const auto& s) { return s.first == c; });
        if (found == std::end(kSubscripts)) {
          const bool wrap = holds_any(g, {" ", "+", "−"});
          out += wrap ? "_(" + g + ")" : "_" + g;
          return;
        }
        chars += found->second;
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

std::string fraction_unicode(std::string_view numerator, std::string_view denominator) {
  return operand(numerator, false) + "/" + operand(denominator, true);
}

std::string unicode_of_latex(std::string_view latex) { return Reader(latex).all(); }

}  // namespace frustum
