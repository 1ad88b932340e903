#include "solver/problem/unstated_givens.hpp"

#include <cctype>
#include <set>
#include <string>
#include <string_view>

#include "solver/input/given_reader.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/text_literals.hpp"

namespace frustum {
namespace {

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The given fields a text names by placeholder: {point}, {point.0}, {viewport.width} → point,
// viewport.
std::set<std::string> placeholder_roots(std::string_view text) {
  std::set<std::string> out;
  for (std::size_t i = text.find('{'); i != std::string_view::npos; i = text.find('{', i + 1)) {
    std::size_t j = i + 1;
    while (j < text.size() && name_char(text[j])) ++j;
    if (j > i + 1 && j < text.size() && (text[j] == '}' || text[j] == '.' || text[j] == '['))
      out.emplace(text.substr(i + 1, j - i - 1));
  }
  return out;
}

// `word` in `text` with no letter or digit on either side.
bool has_word(std::string_view text, std::string_view word) {
  if (word.empty()) return false;
  for (std::size_t at = text.find(word); at != std::string_view::npos;
       at = text.find(word, at + 1)) {
    const bool before = at == 0 || !name_char(text[at - 1]);
    const std::size_t end = at + word.size();
    const bool after = end >= text.size() || !name_char(text[end]);
    if (before && after) return true;
  }
  return false;
}

// A field stated by the words or the one number it holds: every scalar leaf of `n` appears in
// `text` as a word of its own (a sign written − or -).
bool leaves_in_text(const YAML::Node& n, std::string_view text) {
  if (n.IsScalar()) {
    std::string v = n.Scalar();
    if (has_word(text, v)) return true;
    if (!v.empty() && v[0] == '-') return has_word(text, "−" + v.substr(1));
    return false;
  }
  if (!n.IsSequence() && !n.IsMap()) return false;
  bool any = false;
  for (const auto& item : n) {
    const YAML::Node value = n.IsMap() ? item.second : YAML::Node(item);
    if (!leaves_in_text(value, text)) return false;
    any = true;
  }
  return any;
}

bool numeric_leaf(const YAML::Node& n) {
  if (!n.IsScalar() || n.Scalar().empty()) return false;
  const char c = n.Scalar()[0];
  return std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '+' || c == '.';
}

// How many numbers a given holds.
int number_count(const YAML::Node& n) {
  if (n.IsScalar()) return numeric_leaf(n) ? 1 : 0;
  int count = 0;
  for (const auto& item : n) count += number_count(n.IsMap() ? item.second : YAML::Node(item));
  return count;
}

// The givens a text can state in a sentence — a dozen numbers at most: a number, a point, a
// triangle, a volume, a camera, a few transform steps. Words only (an order, a solid's name), the
// dimension, and whole meshes, polygon lists and statements are shown beside the text (its
// figure, its table), not in it.
constexpr int kNumbersASentenceStates = 12;

bool statable(const std::string& key, const YAML::Node& n) {
  const int count = number_count(n);
  return key != "dim" && count > 0 && count <= kNumbersASentenceStates;
}

// `n` with every number x written (k·(x) + 1/7): a given changed everywhere it has a number.
YAML::Node changed(const YAML::Node& n, int k) {
  if (n.IsScalar()) {
    if (!numeric_leaf(n)) return YAML::Clone(n);
    return YAML::Node(std::to_string(k) + "*(" + n.Scalar() + ")+1/7");
  }
  YAML::Node out =
      n.IsMap() ? YAML::Node(YAML::NodeType::Map) : YAML::Node(YAML::NodeType::Sequence);
  for (const auto& item : n) {
    if (n.IsMap())
      out[item.first] = changed(item.second, k);
    else
      out.push_back(changed(item, k));
  }
  return out;
}

bool same_answers(const Answers& a, const Answers& b, const std::vector<std::string>& ask) {
  for (const std::string& name : ask) {
    const Value *x = a.find(name), *y = b.find(name);
    if (!x || !y || x->numbers != y->numbers || x->words != y->words) return false;
  }
  return true;
}

// Whether an asked answer depends on `key`: it changes when that given's numbers change (twice,
// differently; a change the problem refuses counts as a dependence).
bool asked_answers_depend_on(const ProblemSpec& p, const std::string& key,
                             const Answers& key_answers, const std::string& file) {
  for (const int k : {2, -3}) {
    try {
      YAML::Node given = YAML::Clone(p.given_node);
      given[key] = changed(p.given_node[key], k);
      GivenReader reader(given, file, p.field + ".given", p.info->given_fields);
      const std::any parsed = p.info->parse(reader, p.conventions);
      reader.finish();
      if (!same_answers(p.info->solve(parsed, nullptr), key_answers, p.ask)) return true;
    } catch (const std::exception&) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::vector<Diagnostic> unstated_given_warnings(const ProblemSet& set) {
  std::vector<Diagnostic> out;
  for (const ProblemSpec& p : set.problems) {
    if (p.error || p.text.empty() || !p.given_node.IsMap()) continue;
    const std::string& text = p.text.text;
    if (!p.info) continue;
    Answers key_answers;
    try {
      key_answers = p.info->solve(p.given, nullptr);
    } catch (const std::exception&) {
      continue;  // check reports the problem's own error
    }
    TemplatedText templated = template_literals(text, p.given_node);
    const std::set<std::string> named = placeholder_roots(templated.error ? text : templated.text);
    for (const auto& field : p.given_node) {
      const std::string key = field.first.Scalar();
      if (!statable(key, field.second) || named.count(key) || leaves_in_text(field.second, text) ||
          !asked_answers_depend_on(p, key, key_answers, set.file))
        continue;
      out.push_back({location_of(field.first, set.file), p.field + ".given." + key,
                     "warning: problem " + p.id + ": its text never states " + key + " (" +
                         emit_flow(field.second) +
                         "), and the answers asked are computed from it; state it in the text or "
                         "write {" +
                         key + "} there"});
    }
  }
  return out;
}

}  // namespace frustum
