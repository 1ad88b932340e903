#include "grader/list_items.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string_view>

#include "solver/util/words.hpp"

namespace frustum {

namespace {

// Arrows first: "->" holds a dash that must not be read as a pair's.
constexpr std::array<std::string_view, 5> kArrows = {"→", "⟶", "⇒", "->", "=>"};
constexpr std::array<std::string_view, 6> kSeparators = {",", ";", "/", "、", "，", "；"};
constexpr std::array<std::string_view, 4> kDashes = {"-", "–", "—", "−"};

std::string trimmed(std::string_view s) {
  const std::size_t a = s.find_first_not_of(" \t\r\n");
  if (a == std::string_view::npos) return "";
  const std::size_t b = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(a, b - a + 1));
}

bool in_key(std::string_view piece, const std::vector<std::string>& key) {
  return std::any_of(key.begin(), key.end(),
                     [&](const std::string& k) { return k.find(piece) != std::string::npos; });
}

// Splits every item at `separator` outside brackets ("(0, 3)" stays whole).
std::vector<std::string> split_at(const std::vector<std::string>& items,
                                  std::string_view separator) {
  std::vector<std::string> out;
  for (const std::string& item : items) {
    int depth = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i < item.size(); ++i) {
      const char c = item[i];
      if (c == '(' || c == '[') ++depth;
      if ((c == ')' || c == ']') && depth > 0) --depth;
      if (depth == 0 && item.compare(i, separator.size(), separator) == 0) {
        out.push_back(item.substr(start, i - start));
        start = i + separator.size();
        i = start - 1;
      }
    }
    out.push_back(item.substr(start));
  }
  return out;
}

// "0 - 1" → "0-1": the spaces around a dash belong to one item.
std::string dash_spaces_removed(const std::string& item) {
  std::string out;
  for (std::size_t i = 0; i < item.size();) {
    bool dash = false;
    for (std::string_view d : kDashes)
      if (item.compare(i, d.size(), d) == 0) {
        while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
        out.append(d);
        i += d.size();
        while (i < item.size() && (item[i] == ' ' || item[i] == '\t')) ++i;
        dash = true;
        break;
      }
    if (!dash) out += item[i++];
  }
  return out;
}

std::vector<std::string> split_at_spaces(const std::vector<std::string>& items) {
  std::vector<std::string> out;
  for (const std::string& item : items) {
    const std::string joined = dash_spaces_removed(item);
    std::vector<std::string> words = {joined};
    for (const char* space : {" ", "\t"}) words = split_at(words, space);
    out.insert(out.end(), words.begin(), words.end());
  }
  return out;
}

struct Pair {
  std::string a, b;
};

// "a-b", "a – b" or "(a, b)" / "[a, b]": the two ends, or nothing.
std::optional<Pair> pair_of(const std::string& written) {
  std::string s = trimmed(written);
  if (s.size() >= 2 &&
      ((s.front() == '(' && s.back() == ')') || (s.front() == '[' && s.back() == ']'))) {
    const std::vector<std::string> parts = split_at({s.substr(1, s.size() - 2)}, ",");
    if (parts.size() != 2) return std::nullopt;
    Pair p{trimmed(parts[0]), trimmed(parts[1])};
    if (p.a.empty() || p.b.empty()) return std::nullopt;
    return p;
  }
  for (std::string_view d : kDashes) {
    const std::size_t at = s.find(d);
    if (at == std::string::npos) continue;
    Pair p{trimmed(s.substr(0, at)), trimmed(s.substr(at + d.size()))};
    if (p.a.empty() || p.b.empty()) return std::nullopt;
    return p;
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> items_as_written(const std::vector<std::string>& got,
                                          const std::vector<std::string>& key) {
  std::vector<std::string> items = got;
  for (std::string_view arrow : kArrows)
    if (!in_key(arrow, key)) items = split_at(items, arrow);
  for (std::string_view separator : kSeparators)
    if (!in_key(separator, key)) items = split_at(items, separator);
  if (!in_key(" ", key) && !in_key("\t", key)) items = split_at_spaces(items);
  std::vector<std::string> out;
  for (const std::string& item : items)
    if (std::string t = trimmed(item); !t.empty()) out.push_back(std::move(t));
  return out;
}

std::string pair_as_in_key(const std::string& item, const std::vector<std::string>& key) {
  const std::optional<Pair> p = pair_of(item);
  if (!p) return item;
  // The key's spelling, the ends compared as written, then without regard to case.
  for (const bool fold : {false, true}) {
    const auto same = [fold](const std::string& x, const std::string& y) {
      return fold ? ascii_lower(x) == ascii_lower(y) : x == y;
    };
    for (const std::string& k : key) {
      const std::optional<Pair> q = pair_of(k);
      if (q && ((same(p->a, q->a) && same(p->b, q->b)) || (same(p->a, q->b) && same(p->b, q->a))))
        return k;
    }
  }
  return p->a + "-" + p->b;
}

bool is_pair(const std::string& item) { return pair_of(item).has_value(); }

std::string unreadable_item(const std::vector<std::string>& items,
                            const std::vector<std::string>& key, bool pairs) {
  const auto has_letter = [](const std::string& s) {
    return std::any_of(s.begin(), s.end(), [](unsigned char c) {
      return std::isalpha(c) != 0 || c >= 0x80;  // any letter, or any non-ASCII character
    });
  };
  const bool numbers_only = !key.empty() && std::none_of(key.begin(), key.end(), has_letter);
  for (const std::string& item : items) {
    if (pairs && !is_pair(item)) return item;
    if (numbers_only && has_letter(item)) return item;
  }
  return "";
}

}  // namespace frustum
