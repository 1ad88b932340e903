#include "solver/problem/text_literals.hpp"

#include <ginac/ginac.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

namespace frustum {

namespace {

using GiNaC::numeric;

// A number of the given, with its placeholder path ("A.0", "perspective.near").
struct Leaf {
  std::string path;
  std::string key;  // the field's name when its parent is a mapping, else ""
  numeric value;
};

// A list or mapping whose children are all numbers: leaves [first, last].
struct Container {
  std::size_t first = 0, last = 0;
  bool map = false;
};

struct Given {
  std::vector<Leaf> leaves;
  std::vector<Container> containers;  // in document order
};

bool ascii_digit(char c) { return c >= '0' && c <= '9'; }
bool ascii_word(char c) {
  return ascii_digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

// Unicode vulgar fractions as their UTF-8 bytes.
struct Vulgar {
  const char* utf8;
  int num, den;
};
constexpr Vulgar kVulgar[] = {
    {"\u00bd", 1, 2}, {"\u00bc", 1, 4}, {"\u00be", 3, 4}, {"\u2153", 1, 3}, {"\u2154", 2, 3}};
constexpr const char* kMinus = "\u2212";
constexpr const char* kDegree = "\u00b0";
constexpr const char* kTimes = "\u00d7";

bool at(const std::string& s, std::size_t i, const char* what) {
  return s.compare(i, std::char_traits<char>::length(what), what) == 0;
}

std::optional<Vulgar> vulgar_at(const std::string& s, std::size_t i) {
  for (const Vulgar& v : kVulgar)
    if (at(s, i, v.utf8)) return v;
  return std::nullopt;
}

// Superscripts (10⁻³⁰) and ^ make a number part of a power: not a value of its own.
bool power_at(const std::string& s, std::size_t i) {
  for (const char* p : {"^", "\u207b", "\u00b9", "\u00b2", "\u00b3", "\u2070", "\u2074", "\u2075",
                        "\u2076", "\u2077", "\u2078", "\u2079"})
    if (at(s, i, p)) return true;
  return false;
}

constexpr long kMaxExponent = 1000;

numeric pow10(long k) { return GiNaC::pow(numeric(10), numeric(k)); }

// A number written at s[i] (no sign): its value and where it ends.
std::optional<std::pair<numeric, std::size_t>> unsigned_number(const std::string& s,
                                                               std::size_t i) {
  if (const auto v = vulgar_at(s, i))
    return std::make_pair(numeric(v->num, v->den), i + std::strlen(v->utf8));
  std::size_t j = i;
  std::string digits;
  while (j < s.size() && ascii_digit(s[j])) digits += s[j++];
  if (digits.empty() || digits.size() > 400) return std::nullopt;
  long scale = 0;
  if (j + 1 < s.size() && s[j] == '.' && ascii_digit(s[j + 1])) {
    ++j;
    while (j < s.size() && ascii_digit(s[j])) {
      digits += s[j++];
      --scale;
    }
  }
  numeric value(digits.c_str());
  if (j + 1 < s.size() && (s[j] == 'e' || s[j] == 'E')) {
    std::size_t k = j + 1;
    const bool negative = s[k] == '-' || s[k] == '+' ? s[k++] == '-' : false;
    std::string exponent;
    while (k < s.size() && ascii_digit(s[k]) && exponent.size() < 5) exponent += s[k++];
    if (!exponent.empty()) {
      scale += (negative ? -1 : 1) * std::stol(exponent);
      j = k;
    }
  }
  // Beyond any value a given holds (1e-310 is the smallest bundled), and 10^99999 is costly.
  if (scale < -kMaxExponent || scale > kMaxExponent) return std::nullopt;
  value *= pow10(scale);
  if (scale == 0 && j < s.size()) {
    if (const auto v = vulgar_at(s, j))  // 4½
      return std::make_pair(value + numeric(v->num, v->den), j + std::strlen(v->utf8));
    if (s[j] == '/' && j + 1 < s.size() && ascii_digit(s[j + 1])) {
      std::size_t k = j + 1;
      std::string den;
      while (k < s.size() && ascii_digit(s[k]) && den.size() < 30) den += s[k++];
      if (k < s.size() && s[k] == '.') return std::nullopt;  // 0.7/0.7: an expression
      if (numeric(den.c_str()).is_zero()) return std::nullopt;
      return std::make_pair(value / numeric(den.c_str()), k);
    }
  }
  return std::make_pair(value, j);
}

// A given's scalar as a number, when it is one written plainly (not sqrt(2) or pi/3).
std::optional<numeric> given_number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  const bool negative = s[0] == '-';
  const std::size_t start = s[0] == '-' || s[0] == '+' ? 1 : 0;
  const auto n = unsigned_number(s, start);
  if (!n || n->second != s.size()) return std::nullopt;
  return negative ? -n->first : n->first;
}

void flatten(const YAML::Node& n, const std::string& path, const std::string& key, Given& out) {
  if (n.IsScalar()) {
    // A polygon's label ("3") names it: a word, not a value.
    if (const auto v = given_number(n.Scalar()); v && key != "label")
      out.leaves.push_back(Leaf{path, key, *v});
    return;
  }
  if (!n.IsMap() && !n.IsSequence()) return;
  const std::string prefix = path.empty() ? "" : path + ".";
  const std::size_t first = out.leaves.size();
  bool all_numbers = n.size() > 0;
  if (n.IsMap()) {
    for (auto it = n.begin(); it != n.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      all_numbers = all_numbers && it->second.IsScalar() && given_number(it->second.Scalar());
      flatten(it->second, prefix + k, k, out);
    }
  } else {
    for (std::size_t i = 0; i < n.size(); ++i) {
      all_numbers = all_numbers && n[i].IsScalar() && given_number(n[i].Scalar());
      flatten(n[i], prefix + std::to_string(i), "", out);
    }
  }
  if (all_numbers) out.containers.push_back(Container{first, out.leaves.size() - 1, n.IsMap()});
}

// A number of the text: [begin, end) with its sign, its value, a degree sign after it.
struct Token {
  std::size_t begin = 0, end = 0;
  numeric value;
  bool degree = false;
};

std::vector<Token> tokens(const std::string& s) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t start = i, digits = i;
    bool negative = false;
    if (s[i] == '-' || s[i] == '+') {
      negative = s[i] == '-';
      digits = i + 1;
    } else if (at(s, i, kMinus)) {
      negative = true;
      digits = i + std::strlen(kMinus);
    }
    // A sign after a word or a bracket is an operator (a − 1), not part of the number.
    const bool signed_ = digits != start;
    const char before = start > 0 ? s[start - 1] : ' ';
    const bool free_before = !ascii_word(before) && before != '.' && before != '^' &&
                             before != '/' && !(signed_ && (before == ')' || before == ']'));
    const auto n = free_before ? unsigned_number(s, digits) : std::nullopt;
    if (!n) {
      // Skip this character (whole UTF-8 sequence) and, after a word character, the word.
      if (ascii_word(s[i]) || s[i] == '.') {
        while (i < s.size() && (ascii_word(s[i]) || s[i] == '.')) ++i;
      } else {
        ++i;
        while (i < s.size() && (static_cast<unsigned char>(s[i]) & 0xc0) == 0x80) ++i;
      }
      continue;
    }
    std::size_t end = n->second;
    const bool word_after =
        end < s.size() && (ascii_word(s[end]) || s[end] == '\'' ||
                           (s[end] == '.' && end + 1 < s.size() && ascii_digit(s[end + 1])));
    if (word_after || power_at(s, end)) {  // 3D, 9.10's, 10⁻³⁰: not a value
      i = end;
      while (i < s.size() && (ascii_word(s[i]) || s[i] == '.')) ++i;
      continue;
    }
    Token t{start, end, negative ? -n->first : n->first, at(s, end, kDegree)};
    out.push_back(t);
    i = end;
  }
  return out;
}

enum class Separator { None, Comma, Times };

// Between two numbers of one run: optional °, spaces, one comma or ×, spaces.
Separator run_separator(const std::string& s, std::size_t from, std::size_t to) {
  std::size_t i = from;
  if (at(s, i, kDegree)) i += std::strlen(kDegree);
  while (i < to && s[i] == ' ') ++i;
  Separator sep = Separator::None;
  if (i < to && s[i] == ',') {
    ++i;
    sep = Separator::Comma;
  } else if (at(s, i, kTimes)) {
    i += std::strlen(kTimes);
    sep = Separator::Times;
  }
  while (i < to && s[i] == ' ') ++i;
  return i == to ? sep : Separator::None;
}

// How the numbers [begin, end) are bracketed: (1, 2) and [0, 4] on both sides, the last
// arguments of perspective(PI/3, width/height, 10, 10000) on one.
enum class Brackets { None, One, Both };

Brackets brackets(const std::string& s, std::size_t begin, std::size_t end) {
  if (at(s, end, kDegree)) end += std::strlen(kDegree);
  while (begin > 0 && s[begin - 1] == ' ') --begin;
  while (end < s.size() && s[end] == ' ') ++end;
  const bool open = begin > 0 && (s[begin - 1] == '(' || s[begin - 1] == '[');
  const bool close = end < s.size() && (s[end] == ')' || s[end] == ']');
  return open && close ? Brackets::Both : open || close ? Brackets::One : Brackets::None;
}

// The name before "=" ending at s[begin) (spaces skipped), or nullopt when there is no "=" or
// a number stands before it.
std::optional<std::string> equals_name(const std::string& s, std::size_t begin) {
  std::size_t i = begin;
  while (i > 0 && s[i - 1] == ' ') --i;
  if (i == 0 || s[i - 1] != '=') return std::nullopt;
  --i;
  while (i > 0 && s[i - 1] == ' ') --i;
  if (i > 0 && ascii_digit(s[i - 1])) return std::nullopt;  // 0.7/0.7 = 1: a result, no name
  std::size_t j = i;
  while (j > 0 && ascii_word(s[j - 1])) --j;
  return s.substr(j, i - j);
}

// The name a bound states: "0 ≤ x" or "x ≤ 4" (the number at [begin, end)).
std::optional<std::string> bound_name(const std::string& s, std::size_t begin, std::size_t end) {
  constexpr const char* kAtMost = " \u2264 ";
  const std::size_t n = std::strlen(kAtMost);
  if (at(s, end, kAtMost)) {
    std::size_t j = end + n;
    while (j < s.size() && ascii_word(s[j])) ++j;
    if (j > end + n) return s.substr(end + n, j - end - n);
  }
  if (begin >= n && at(s, begin - n, kAtMost)) {
    std::size_t j = begin - n;
    while (j > 0 && ascii_word(s[j - 1])) --j;
    if (j < begin - n) return s.substr(j, begin - n - j);
  }
  return std::nullopt;
}

using Window = std::vector<std::size_t>;  // leaf indices, one per number of a literal

struct Mention {
  std::size_t first, last;  // token indices
  std::vector<Window> candidates;
};

std::vector<Window> run_candidates(const Given& g, const std::vector<Token>& t, std::size_t first,
                                   std::size_t last) {
  const std::size_t k = last - first + 1;
  const auto equal = [&](std::size_t leaf0) {
    for (std::size_t j = 0; j < k; ++j)
      if (leaf0 + j >= g.leaves.size() || g.leaves[leaf0 + j].value != t[first + j].value)
        return false;
    return true;
  };
  const auto window = [&](std::size_t leaf0) {
    Window w;
    for (std::size_t j = 0; j < k; ++j) w.push_back(leaf0 + j);
    return w;
  };
  std::vector<Window> whole, part, spans;
  for (std::size_t c = 0; c < g.containers.size(); ++c) {
    const Container& box = g.containers[c];
    const std::size_t size = box.last - box.first + 1;
    if (size == k && equal(box.first)) whole.push_back(window(box.first));
    // A pair of a mapping's bounds in order: [left, right], [near, far], [xmin, xmax].
    if (box.map && size > k && k == 2)
      for (std::size_t s = box.first; s + k <= box.last + 1; s += 2)
        if (equal(s)) part.push_back(window(s));
    // Consecutive whole containers, adjacent in the given (camera(eye, center, up)).
    std::size_t total = size;
    for (std::size_t d = c + 1; d < g.containers.size() && total < k; ++d) {
      if (g.containers[d].first != g.containers[d - 1].last + 1) break;
      total += g.containers[d].last - g.containers[d].first + 1;
      if (total == k && equal(box.first)) spans.push_back(window(box.first));
    }
  }
  return !whole.empty() ? whole : !part.empty() ? part : spans;
}

std::string literal_text(const std::string& s, const std::vector<Token>& t, const Mention& m) {
  std::size_t begin = t[m.first].begin, end = t[m.last].end;
  if (t[m.last].degree) end += std::strlen(kDegree);
  if (begin > 0 && (s[begin - 1] == '(' || s[begin - 1] == '[')) --begin;
  if (end < s.size() && (s[end] == ')' || s[end] == ']')) ++end;
  return s.substr(begin, end - begin);
}

std::string placeholders(const Given& g, const Window& w) {
  std::string out;
  for (std::size_t leaf : w) out += (out.empty() ? "{" : ", {") + g.leaves[leaf].path + "}";
  return out;
}

// Fields that hold an angle in degrees (as the default redraw reads them).
bool angle_key(const std::string& k) {
  return k == "fovy" || k == "fov" || k == "fovx" || k == "angle" || k.rfind("rotate", 0) == 0;
}

constexpr const char* kPi = "\u03c0";

// Processing's PI/3 (or π/3, 2*PI/3, PI) at s[i]: the multiple of π (p/q), its symbol, where it
// ends; a word around it (HALF_PI, PIXEL) is no angle.
struct Radians {
  long p = 1, q = 1;
  std::string symbol;
  std::size_t end = 0;
};
std::optional<Radians> radians_at(const std::string& s, std::size_t i) {
  if (i > 0 && (ascii_word(s[i - 1]) || s[i - 1] == '.' || s[i - 1] == '*' || s[i - 1] == '/'))
    return std::nullopt;
  Radians r;
  std::size_t j = i;
  std::string digits;
  while (j < s.size() && ascii_digit(s[j]) && digits.size() < 4) digits += s[j++];
  if (!digits.empty()) {
    if (j < s.size() && s[j] == '*') ++j;
    r.p = std::stol(digits);
  }
  if (at(s, j, "PI")) {
    r.symbol = "PI";
    j += 2;
  } else if (at(s, j, kPi)) {
    r.symbol = kPi;
    j += std::strlen(kPi);
  } else {
    return std::nullopt;
  }
  if (j + 1 < s.size() && s[j] == '/' && ascii_digit(s[j + 1])) {
    std::string den;
    for (++j; j < s.size() && ascii_digit(s[j]) && den.size() < 4; ++j) den += s[j];
    r.q = std::stol(den);
  }
  if ((j < s.size() && (ascii_word(s[j]) || s[j] == '.' || s[j] == '/')) || r.p == 0 || r.q == 0)
    return std::nullopt;
  r.end = j;
  return r;
}

// An angle field written in radians as a multiple of π (perspective(PI/3, …) for fovy: 60) is
// tied to {field|PI} (or {field|π}) when exactly one angle field holds that many degrees.
std::optional<std::string> tie_radians(std::string& text, const Given& g, int& tied) {
  for (std::size_t i = 0; i < text.size();) {
    if (text[i] == '{') {  // a placeholder already: left as it is
      const std::size_t close = text.find('}', i);
      i = close == std::string::npos ? text.size() : close + 1;
      continue;
    }
    const std::optional<Radians> r = radians_at(text, i);
    if (!r) {
      ++i;
      continue;
    }
    const numeric degrees = numeric(180 * r->p, r->q);
    std::vector<std::size_t> fields;
    for (std::size_t l = 0; l < g.leaves.size(); ++l)
      if (angle_key(g.leaves[l].key) && g.leaves[l].value == degrees) fields.push_back(l);
    if (fields.size() > 1)
      return "the literal \"" + text.substr(i, r->end - i) +
             "\" could state any of several angles of the given ({" + g.leaves[fields[0]].path +
             "} or {" + g.leaves[fields[1]].path + "}): write the placeholder it means instead ({" +
             g.leaves[fields[0]].path + "|" + r->symbol + "} prints it as a multiple of " +
             r->symbol + ")";
    if (fields.size() == 1) {
      const std::string placeholder = "{" + g.leaves[fields[0]].path + "|" + r->symbol + "}";
      text.replace(i, r->end - i, placeholder);
      i += placeholder.size();
      ++tied;
      continue;
    }
    i = r->end;
  }
  return std::nullopt;
}

}  // namespace

TemplatedText template_literals(const std::string& text, const YAML::Node& given) {
  TemplatedText out{text, std::nullopt, 0};
  Given g;
  flatten(given, "", "", g);
  if (g.leaves.empty()) return out;
  const std::vector<Token> t = tokens(text);
  // Literals: runs of numbers, then single numbers after "=" or with a degree sign.
  std::vector<Mention> mentions;
  for (std::size_t i = 0; i < t.size();) {
    // A run: numbers in brackets separated by commas, or sizes 200×200; a list that is
    // neither ("0 ≤ x ≤ 4, 0 ≤ y", "polygons 3, 2, 1") is read one number at a time.
    std::size_t j = i;
    bool sizes = true;
    for (Separator sep; j + 1 < t.size() &&
                        (sep = run_separator(text, t[j].end, t[j + 1].begin)) != Separator::None;
         ++j)
      sizes = sizes && sep == Separator::Times;
    const Brackets b = brackets(text, t[i].begin, t[j].end);
    if (j > i && !sizes && b == Brackets::None) j = i;
    Mention m{i, j, {}};
    if (j > i) {
      m.candidates = run_candidates(g, t, i, j);
      // Half-bracketed, a run states named fields only ("(1, 2, 3 の順" is no point).
      if (!sizes && b == Brackets::One)
        std::erase_if(m.candidates, [&](const Window& w) {
          return std::any_of(w.begin(), w.end(),
                             [&](std::size_t leaf) { return g.leaves[leaf].key.empty(); });
        });
      bool all_given = true, unit_only = true;  // unit_only: only 0 and ±1
      for (std::size_t k = i; k <= j; ++k) {
        unit_only = unit_only && (t[k].value.is_zero() || abs(t[k].value) == 1);
        all_given = all_given && std::any_of(g.leaves.begin(), g.leaves.end(),
                                             [&](const Leaf& l) { return l.value == t[k].value; });
      }
      // The origin, a unit axis, [0, 1]: constants, unless exactly one field holds them.
      if (unit_only && m.candidates.size() != 1) m.candidates.clear();
      // A bracketed point of given values that no field holds: stale in a variant.
      if (m.candidates.empty() && all_given && !unit_only && b == Brackets::Both) {
        out.error = "the literal \"" + literal_text(text, t, m) +
                    "\" states values of the given but not one of its fields: write "
                    "placeholders for the values a variant draws ({name} of a given field)";
        return out;
      }
    } else if (const auto name = equals_name(text, t[i].begin).has_value()
                                     ? equals_name(text, t[i].begin)
                                     : bound_name(text, t[i].begin, t[i].end);
               name || t[i].degree) {
      for (std::size_t l = 0; l < g.leaves.size(); ++l)
        if (!g.leaves[l].key.empty() && g.leaves[l].value == t[i].value)
          m.candidates.push_back(Window{l});
      // Named by its field (near = 1), or by the start of it (x = 3 for xmax).
      std::vector<Window> named, prefixed;
      for (const Window& w : m.candidates) {
        const std::string& key = g.leaves[w[0]].key;
        if (name && key == *name) named.push_back(w);
        if (name && !name->empty() && key.rfind(*name, 0) == 0) prefixed.push_back(w);
      }
      if (!named.empty()) {
        m.candidates = named;
      } else if (!prefixed.empty()) {
        m.candidates = prefixed;
      }
    }
    if (!m.candidates.empty()) mentions.push_back(std::move(m));
    i = j + 1;
  }
  // A literal stating several fields alike is tied in order when each is mentioned once.
  std::map<std::vector<Window>, std::size_t> seen;
  std::map<std::size_t, Window> tie;  // mention index → its fields
  for (std::size_t k = 0; k < mentions.size(); ++k) {
    const Mention& m = mentions[k];
    if (m.candidates.size() == 1) {
      tie[k] = m.candidates[0];
      continue;
    }
    std::size_t count = 0;
    for (const Mention& other : mentions) count += other.candidates == m.candidates;
    if (count != m.candidates.size()) {
      out.error = "the literal \"" + literal_text(text, t, m) +
                  "\" could state any of several values of the given (" +
                  placeholders(g, m.candidates[0]) + " or " + placeholders(g, m.candidates[1]) +
                  "): write the placeholders it means instead";
      return out;
    }
    tie[k] = m.candidates[seen[m.candidates]++];
  }
  // Each number of a tied literal becomes its field's placeholder, right to left; in a text that
  // writes its minus signs as U+2212, one that prints them so ({A.0|−}).
  const std::string style = text.find(kMinus) != std::string::npos ? "|" + std::string(kMinus) : "";
  for (auto it = tie.rbegin(); it != tie.rend(); ++it) {
    const Mention& m = mentions[it->first];
    for (std::size_t j = m.last + 1; j-- > m.first;) {
      const Token& token = t[j];
      out.text.replace(token.begin, token.end - token.begin,
                       "{" + g.leaves[it->second[j - m.first]].path + style + "}");
    }
    ++out.tied;
  }
  out.error = tie_radians(out.text, g, out.tied);
  return out;
}

}  // namespace frustum
