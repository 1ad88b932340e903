#include "solver/input/given_reader.hpp"

#include <algorithm>
#include <cctype>

#include "solver/core/work_budget.hpp"
#include "solver/util/exact_format.hpp"
#include "solver/util/expression.hpp"
#include "solver/util/suggest.hpp"
#include "solver/util/words.hpp"

namespace frustum {

SourceLocation location_of(const YAML::Node& node, const std::string& file) {
  SourceLocation loc{file, 0, 0};
  if (node.IsDefined()) {
    const YAML::Mark m = node.Mark();
    if (m.line >= 0) {
      loc.line = m.line + 1;
      loc.column = m.column + 1;
    }
  }
  return loc;
}

namespace {

bool names_non_finite(const std::string& text) {
  std::string t = ascii_lower(text);
  t.erase(std::remove(t.begin(), t.end(), ' '), t.end());
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) t.erase(0, 1);
  return t == ".nan" || t == "nan" || t == ".inf" || t == "inf" || t == "infinity" || t == "∞";
}

std::string describe_node(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Sequence:
      return "a list of " + std::to_string(n.size());
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Null:
      return "nothing";
    case YAML::NodeType::Scalar:
      return quote_excerpt(n.Scalar());
    default:
      return "nothing";
  }
}

// The irrational values e is built from, nested ones included: √(2 + √3) holds √(2 + √3) and
// √3. Rationals, and sums and products of atoms, are not atoms.
void collect_atoms(const Exact& e, std::set<Exact, GiNaC::ex_is_less>& atoms) {
  if (is_rational(e)) return;
  const bool whole_power = GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
                           GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_integer();
  if (!GiNaC::is_a<GiNaC::add>(e) && !GiNaC::is_a<GiNaC::mul>(e) && !whole_power) atoms.insert(e);
  for (std::size_t i = 0; i < e.nops(); ++i) collect_atoms(e.op(i), atoms);
}

// read_number, also adding to `atoms` the irrational values the expression is written with
// (before simplification: 1/(√2 + √3) uses √2 and √3, and its simplified form √3 − √2 still
// lives among them; √6 written as such is one more).
Exact read_exact(const YAML::Node& n, const std::string& file, const std::string& field,
                 std::set<Exact, GiNaC::ex_is_less>* atoms) {
  auto fail = [&](const std::string& message) -> Exact {
    throw InputError(Diagnostic{location_of(n, file), field, message});
  };
  if (!n.IsDefined() || n.IsNull()) return fail("expected a number, got nothing");
  if (!n.IsScalar()) return fail("expected a number, got " + describe_node(n));
  const std::string& text = n.Scalar();
  if (names_non_finite(text)) return fail(quote_excerpt(text) + " is not a finite number");
  const std::string l = ascii_lower(text);
  if (l == "true" || l == "false" || l == "yes" || l == "no")
    return fail("expected a number, got " + quote_excerpt(text));
  const ExpressionResult r = parse_expression(text);
  if (!r) return fail("cannot read " + quote_excerpt(text) + " as a number: " + r.error.en());
  WorkBudget budget;
  const Exact e = canonical(*r.value, budget);
  if (budget.exceeded())
    return fail(quote_excerpt(text) +
                " is too complex for exact solving (simplifying it takes more than " +
                std::to_string(static_cast<long>(budget.limit())) +
                " steps): simplify it, or give it as a decimal");
  if (!is_real_constant(e)) return fail(quote_excerpt(text) + " is not a real number");
  if (atoms) collect_atoms(*r.value, *atoms);
  return e;
}

}  // namespace

Exact read_number(const YAML::Node& n, const std::string& file, const std::string& field) {
  return read_exact(n, file, field, nullptr);
}

struct GivenReader::ExactInputs {
  std::set<Exact, GiNaC::ex_is_less> atoms;
};

GivenReader::GivenReader(YAML::Node node, std::string file, std::string field,
                         std::vector<std::string> known_fields)
    : GivenReader(std::move(node), std::move(file), std::move(field), std::move(known_fields),
                  std::make_shared<ExactInputs>()) {}

GivenReader::GivenReader(YAML::Node node, std::string file, std::string field,
                         std::vector<std::string> known_fields, std::shared_ptr<ExactInputs> exact)
    : node_(std::move(node)),
      file_(std::move(file)),
      field_(std::move(field)),
      known_(std::move(known_fields)),
      exact_(std::move(exact)) {
  if (!node_.IsDefined() || node_.IsNull())
    fail_at(node_, field_,
            "missing: expected a mapping of " + std::to_string(known_.size()) + " possible fields");
  if (!node_.IsMap()) fail_at(node_, field_, "expected a mapping, got " + describe_node(node_));
}

std::string GivenReader::path(std::string_view key) const {
  return field_.empty() ? std::string(key) : field_ + "." + std::string(key);
}

bool GivenReader::has(std::string_view key) const {
  const YAML::Node& n = node_;
  const YAML::Node child = n[std::string(key)];  // one lookup: yaml-cpp scans a mapping's keys
  return child.IsDefined() && !child.IsNull();
}

void GivenReader::fail_at(const YAML::Node& n, const std::string& field,
                          const std::string& message) const {
  throw InputError(Diagnostic{location_of(n, file_), field, message});
}

void GivenReader::fail(std::string_view key, const std::string& message) const {
  const YAML::Node& n = node_;
  const YAML::Node child = n[std::string(key)];
  fail_at(child.IsDefined() ? child : node_, path(key), message);
}

YAML::Node GivenReader::require(std::string_view key) {
  used_.insert(std::string(key));
  const YAML::Node& n = node_;
  YAML::Node child = n[std::string(key)];
  if (!child.IsDefined() || child.IsNull()) {
    std::string hint;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      if (std::find(known_.begin(), known_.end(), k) == known_.end() &&
          !closest_name(k, {std::string(key)}).empty())
        hint = " (found '" + k + "': a misspelling?)";
    }
    fail_at(node_, path(key), "missing required field" + hint);
  }
  return child;
}

template <typename Field>
Exact GivenReader::number_at(const YAML::Node& n, Field&& field) const {
  // Most numbers are plain literals: read them without building their path.
  if (n.IsScalar())
    if (std::optional<Exact> d = parse_decimal_literal(n.Scalar())) return *d;
  std::set<Exact, GiNaC::ex_is_less> atoms = exact_->atoms;
  const Exact e = read_exact(n, file_, field(), &atoms);
  if (atoms.size() > kMaxGivenAtoms) {
    // Sorted as text: GiNaC's order depends on hashes that differ from run to run.
    std::vector<std::string> names;
    for (const Exact& a : atoms) names.push_back(format_exact(a, MathStyle::Plain));
    std::sort(names.begin(), names.end());
    std::string list;
    for (const std::string& a : names) list += (list.empty() ? "" : ", ") + a;
    fail_at(n, field(),
            quote_excerpt(n.Scalar()) +
                " brings the irrational values in this problem's given to " +
                std::to_string(atoms.size()) + " (" + quote_excerpt(list) + "); at most " +
                std::to_string(kMaxGivenAtoms) +
                " keep exact solving fast (its work doubles with each new root): give some as "
                "decimals");
  }
  exact_->atoms = std::move(atoms);
  return e;
}

Exact GivenReader::number(std::string_view key) {
  return number_at(require(key), [&] { return path(key); });
}

std::vector<Exact> GivenReader::numbers(std::string_view key, std::size_t count) {
  const YAML::Node n = require(key);
  if (!n.IsSequence() || n.size() != count)
    fail_at(n, path(key),
            "expected a list of " + std::to_string(count) + " numbers, got " + describe_node(n));
  std::vector<Exact> out;
  for (std::size_t i = 0; i < count; ++i)
    out.push_back(number_at(n[i], [&] { return path(key) + "[" + std::to_string(i) + "]"; }));
  return out;
}

std::vector<Exact> GivenReader::numbers_at(std::string_view key, std::size_t i, std::size_t count) {
  const YAML::Node list = require(key);
  auto f = [&] { return path(key) + "[" + std::to_string(i) + "]"; };
  const YAML::Node n = list[i];
  if (!n.IsSequence() || n.size() != count)
    fail_at(n, f(),
            "expected a list of " + std::to_string(count) + " numbers, got " + describe_node(n));
  std::vector<Exact> out;
  for (std::size_t k = 0; k < count; ++k)
    out.push_back(number_at(n[k], [&] { return f() + "[" + std::to_string(k) + "]"; }));
  return out;
}

std::vector<Vec3<Exact>> GivenReader::points(std::string_view key, std::size_t min_count,
                                             std::size_t max_count) {
  const YAML::Node n = require(key);
  if (!n.IsSequence())
    fail_at(n, path(key), "expected a list of points [x, y, z], got " + describe_node(n));
  if (n.size() < min_count || n.size() > max_count) {
    const std::string want = min_count == max_count ? std::to_string(min_count)
                                                    : "at least " + std::to_string(min_count);
    fail_at(n, path(key), "expected " + want + " points, got " + std::to_string(n.size()));
  }
  std::vector<Vec3<Exact>> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    auto f = [&] { return path(key) + "[" + std::to_string(i) + "]"; };
    const YAML::Node p = n[i];
    if (!p.IsSequence() || p.size() != 3)
      fail_at(p, f(), "expected a point [x, y, z], got " + describe_node(p));
    out.emplace_back(number_at(p[0], [&] { return f() + "[0]"; }),
                     number_at(p[1], [&] { return f() + "[1]"; }),
                     number_at(p[2], [&] { return f() + "[2]"; }));
  }
  return out;
}

std::string GivenReader::word(std::string_view key, const std::vector<std::string>& allowed) {
  const YAML::Node n = require(key);
  if (!n.IsScalar()) fail_at(n, path(key), "expected a word, got " + describe_node(n));
  const std::string w = n.Scalar();
  if (std::find(allowed.begin(), allowed.end(), w) == allowed.end()) {
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    fail_at(n, path(key), "'" + w + "' is not one of " + list + did_you_mean(w, allowed));
  }
  return w;
}

std::vector<std::string> GivenReader::words(std::string_view key, std::size_t count) {
  const YAML::Node n = require(key);
  if (!n.IsSequence() || n.size() != count)
    fail_at(n, path(key),
            "expected a list of " + std::to_string(count) + " names, got " + describe_node(n));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < count; ++i) {
    if (!n[i].IsScalar())
      fail_at(n[i], path(key) + "[" + std::to_string(i) + "]", "expected a name");
    out.push_back(n[i].Scalar());
  }
  return out;
}

GivenReader GivenReader::child(std::string_view key, std::vector<std::string> known_fields) {
  GivenReader out(require(key), file_, path(key), std::move(known_fields), exact_);
  out.text_lang_ = text_lang_;
  return out;
}

std::size_t GivenReader::list_size(std::string_view key, std::size_t min_count,
                                   std::size_t max_count) {
  const YAML::Node n = require(key);
  if (!n.IsSequence()) fail_at(n, path(key), "expected a list, got " + describe_node(n));
  if (n.size() < min_count)
    fail_at(n, path(key),
            "expected at least " + std::to_string(min_count) + " items, got " +
                std::to_string(n.size()));
  if (n.size() > max_count)
    fail_at(n, path(key),
            "at most " + std::to_string(max_count) + " items, got " + std::to_string(n.size()));
  return n.size();
}

GivenReader GivenReader::item(std::string_view key, std::size_t i,
                              std::vector<std::string> known_fields) {
  const YAML::Node n = require(key);
  GivenReader out(n[i], file_, path(key) + "[" + std::to_string(i) + "]", std::move(known_fields),
                  exact_);
  out.text_lang_ = text_lang_;
  return out;
}

bool GivenReader::is_list(std::string_view key) const {
  const YAML::Node& n = node_;
  return n[std::string(key)].IsSequence();
}

std::vector<std::string> GivenReader::keys() const {
  std::vector<std::string> out;
  for (auto it = node_.begin(); it != node_.end(); ++it) out.push_back(it->first.as<std::string>());
  return out;
}

void GivenReader::finish() {
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    if (used_.count(k)) continue;
    if (std::find(known_.begin(), known_.end(), k) != known_.end()) continue;
    fail_at(it->first, path(k), "unknown field" + did_you_mean(k, known_));
  }
}

Diagnostic GivenReader::locate(const std::string& p, const std::string& message) const {
  // Walk "a.b[1][2]" down from this mapping; stop at the deepest node that exists.
  YAML::Node n = node_;
  std::size_t i = 0;
  while (i < p.size()) {
    if (p[i] == '.') {
      ++i;
      continue;
    }
    YAML::Node next;
    if (p[i] == '[') {
      const std::size_t close = p.find(']', i);
      if (close == std::string::npos) break;
      const std::size_t index = std::stoul(p.substr(i + 1, close - i - 1));
      if (!n.IsSequence() || index >= n.size()) break;
      next = n[index];
      i = close + 1;
    } else {
      std::size_t end = p.find_first_of(".[", i);
      if (end == std::string::npos) end = p.size();
      const std::string k = p.substr(i, end - i);
      const YAML::Node& cn = n;
      if (!cn.IsMap() || !cn[k].IsDefined()) break;
      next = cn[k];
      i = end;
    }
    n.reset(next);
  }
  return Diagnostic{location_of(n, file_), path(p), message};
}

}  // namespace frustum
