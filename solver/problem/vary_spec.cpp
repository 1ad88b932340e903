#include "solver/problem/vary_spec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/util/suggest.hpp"

namespace frustum {

namespace {

// More values than this in one range is a mistake (a step of 0.000001 over [0, 1000]).
constexpr double kMaxRangeValues = 1e9;

[[noreturn]] void fail_at(const YAML::Node& n, const std::string& file, const std::string& field,
                          const std::string& message) {
  throw InputError(Diagnostic{location_of(n, file), field, message});
}

bool has_key(const YAML::Node& n, const char* key) { return n.IsMap() && n[key].IsDefined(); }

void check_keys(const YAML::Node& spec, const std::vector<std::string>& known,
                const std::string& file, const std::string& field) {
  for (auto it = spec.begin(); it != spec.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    if (std::find(known.begin(), known.end(), k) == known.end())
      fail_at(it->first, file, field + "." + k, "unknown option" + did_you_mean(k, known));
  }
}

// The number of values of a range, and its lower end and step.
struct Range {
  Exact lo, step;
  std::uint64_t count = 0;
};

Range read_range(const YAML::Node& spec, const std::string& file, const std::string& field) {
  check_keys(spec, {"range", "step"}, file, field);
  const YAML::Node r = spec["range"];
  if (!r.IsSequence() || r.size() != 2) fail_at(r, file, field + ".range", "expected [lo, hi]");
  Range out;
  out.lo = read_number(r[0], file, field + ".range[0]");
  const Exact hi = read_number(r[1], file, field + ".range[1]");
  out.step = spec["step"].IsDefined() ? read_number(spec["step"], file, field + ".step") : Exact(1);
  if (exact_sign(out.step) <= 0) fail_at(spec["step"], file, field + ".step", "must be positive");
  if (exact_sign(hi - out.lo) < 0) fail_at(r, file, field + ".range", "lo must not exceed hi");
  const Exact q = canonical((hi - out.lo) / out.step);
  double steps = 0;
  if (GiNaC::is_a<GiNaC::numeric>(q) && GiNaC::ex_to<GiNaC::numeric>(q).is_rational()) {
    const GiNaC::numeric nq = GiNaC::ex_to<GiNaC::numeric>(q);
    const GiNaC::numeric whole = GiNaC::iquo(nq.numer(), nq.denom());
    if (whole > GiNaC::numeric(static_cast<long>(kMaxRangeValues)))
      fail_at(r, file, field + ".range", "more than 10⁹ values: use a larger step");
    steps = static_cast<double>(whole.to_long());
  } else {
    steps = std::floor(to_double(q) + 1e-12);
    if (!(steps < kMaxRangeValues))
      fail_at(r, file, field + ".range", "more than 10⁹ values: use a larger step");
  }
  out.count = static_cast<std::uint64_t>(steps) + 1;
  return out;
}

void check_spec(const YAML::Node& spec, const std::string& file, const std::string& field) {
  if (has_key(spec, "range")) {
    read_range(spec, file, field);
  } else if (has_key(spec, "choices")) {
    check_keys(spec, {"choices"}, file, field);
    if (!spec["choices"].IsSequence() || spec["choices"].size() == 0)
      fail_at(spec["choices"], file, field + ".choices", "expected a non-empty list of values");
  } else if (has_key(spec, "each")) {
    check_keys(spec, {"each", "count"}, file, field);
    check_spec(spec["each"], file, field + ".each");
    if (spec["count"].IsDefined()) {
      const Exact c = read_number(spec["count"], file, field + ".count");
      if (!GiNaC::is_a<GiNaC::numeric>(c) || !GiNaC::ex_to<GiNaC::numeric>(c).is_pos_integer() ||
          exact_sign(c - 1000) > 0)
        fail_at(spec["count"], file, field + ".count", "must be a whole number from 1 to 1000");
    }
  } else if (spec.IsSequence()) {
    for (std::size_t i = 0; i < spec.size(); ++i)
      check_spec(spec[i], file, field + "[" + std::to_string(i) + "]");
  } else if (spec.IsMap()) {
    for (auto it = spec.begin(); it != spec.end(); ++it)
      check_spec(it->second, file, field + "." + it->first.as<std::string>());
  }
}

YAML::Node draw(const YAML::Node& spec, const YAML::Node& base, Rng& rng, const std::string& file,
                const std::string& field) {
  if (has_key(spec, "range")) {
    const Range r = read_range(spec, file, field);
    const auto k = static_cast<long>(rng.below(r.count));
    return gen_number(Exact(r.lo + r.step * k));
  }
  if (has_key(spec, "choices"))
    return clone_node(spec["choices"][static_cast<std::size_t>(rng.below(spec["choices"].size()))]);
  if (has_key(spec, "each")) {
    std::size_t count = base.IsSequence() ? base.size() : 0;
    if (spec["count"].IsDefined())
      count =
          static_cast<std::size_t>(to_double(read_number(spec["count"], file, field + ".count")));
    if (count == 0)
      fail_at(spec, file, field, "`each` needs a list in `given` to vary, or a `count`");
    YAML::Node out(YAML::NodeType::Sequence);
    for (std::size_t i = 0; i < count; ++i)
      out.push_back(draw(spec["each"],
                         base.IsSequence() && i < base.size() ? base[i] : YAML::Node(), rng, file,
                         field + ".each"));
    out.SetStyle(YAML::EmitterStyle::Flow);
    return out;
  }
  if (spec.IsSequence()) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (std::size_t i = 0; i < spec.size(); ++i)
      out.push_back(draw(spec[i], base.IsSequence() && i < base.size() ? base[i] : YAML::Node(),
                         rng, file, field + "[" + std::to_string(i) + "]"));
    out.SetStyle(YAML::EmitterStyle::Flow);
    return out;
  }
  if (spec.IsMap()) {
    YAML::Node out = base.IsMap() ? clone_node(base) : YAML::Node(YAML::NodeType::Map);
    for (auto it = spec.begin(); it != spec.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      out[k] = draw(it->second, base.IsMap() ? base[k] : YAML::Node(), rng, file, field + "." + k);
    }
    return out;
  }
  return clone_node(spec);
}

}  // namespace

YAML::Node clone_node(const YAML::Node& n) { return YAML::Clone(n); }

bool vary_is_default(const YAML::Node& vary) {
  return vary.IsDefined() && vary.IsScalar() && vary.Scalar() == "default";
}

void check_vary(const YAML::Node& vary, const KindInfo& kind, const std::string& file,
                const std::string& field) {
  if (vary_is_default(vary)) return;
  if (!vary.IsMap())
    fail_at(vary, file, field,
            "expected a mapping of given fields to {range}, {choices} or {each}, or `default`");
  for (auto it = vary.begin(); it != vary.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    if (std::find(kind.given_fields.begin(), kind.given_fields.end(), k) == kind.given_fields.end())
      fail_at(it->first, file, field + "." + k,
              "not a given field of " + kind.name + did_you_mean(k, kind.given_fields));
    check_spec(it->second, file, field + "." + k);
  }
}

YAML::Node apply_vary(const YAML::Node& vary, const YAML::Node& base, Rng& rng,
                      const std::string& file, const std::string& field) {
  YAML::Node out = base.IsMap() ? clone_node(base) : YAML::Node(YAML::NodeType::Map);
  for (auto it = vary.begin(); it != vary.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    out[k] = draw(it->second, base.IsMap() ? base[k] : YAML::Node(), rng, file, field + "." + k);
  }
  return out;
}

// One entry of a `vary` block as draw() reads it, read once.
struct VaryPlan::Spec {
  enum class Type { Range, Choices, Each, List, Map, Value } type = Type::Value;
  YAML::Node node;    // the entry (choices: the list)
  std::string field;  // for the error of an `each` with nothing to count
  Exact lo, step;     // range: lo + k·step, k in [0, count)
  std::uint64_t count = 0;
  // A range of integers small enough to draw in std::int64_t (its values print alike).
  std::optional<std::int64_t> int_lo, int_step;
  std::optional<std::size_t> each_count;  // each: `count`
  std::vector<Spec> items;                // list: its items; each: its one item; map: its values
  std::vector<std::string> keys;          // map: its keys
};

namespace {

// The rationals of an integer range that fit, with every value lo + k·step, in std::int64_t.
constexpr long kMaxIntegerRangeEnd = 1L << 31;

std::optional<std::int64_t> small_integer(const Exact& e) {
  if (!GiNaC::is_a<GiNaC::numeric>(e)) return std::nullopt;
  const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
  if (!n.is_integer() || GiNaC::abs(n) >= GiNaC::numeric(kMaxIntegerRangeEnd)) return std::nullopt;
  return n.to_long();
}

// What draw() does with `spec`, decided once (the same order of tests).
VaryPlan::Spec plan_spec(const YAML::Node& spec, const std::string& file,
                         const std::string& field) {
  VaryPlan::Spec out;
  out.node.reset(spec);  // reset, not =: assigning a node writes through to the block
  out.field = field;
  using Type = VaryPlan::Spec::Type;
  if (has_key(spec, "range")) {
    out.type = Type::Range;
    const Range r = read_range(spec, file, field);
    out.lo = r.lo;
    out.step = r.step;
    out.count = r.count;
    out.int_lo = small_integer(r.lo);
    out.int_step = small_integer(r.step);
  } else if (has_key(spec, "choices")) {
    out.type = Type::Choices;
    out.node.reset(spec["choices"]);
  } else if (has_key(spec, "each")) {
    out.type = Type::Each;
    if (spec["count"].IsDefined())
      out.each_count =
          static_cast<std::size_t>(to_double(read_number(spec["count"], file, field + ".count")));
    out.items.push_back(plan_spec(spec["each"], file, field + ".each"));
  } else if (spec.IsSequence()) {
    out.type = Type::List;
    for (std::size_t i = 0; i < spec.size(); ++i)
      out.items.push_back(plan_spec(spec[i], file, field + "[" + std::to_string(i) + "]"));
  } else if (spec.IsMap()) {
    out.type = Type::Map;
    for (auto it = spec.begin(); it != spec.end(); ++it) {
      out.keys.push_back(it->first.as<std::string>());
      out.items.push_back(plan_spec(it->second, file, field + "." + out.keys.back()));
    }
  }
  return out;
}

// A range's draw, as the text of its number.
std::string draw_number(const VaryPlan::Spec& s, Rng& rng) {
  const std::uint64_t k = rng.below(s.count);
  // |lo|, |step| < 2³¹ and k < 10⁹ + 1: no overflow.
  if (s.int_lo && s.int_step)
    return std::to_string(*s.int_lo + *s.int_step * static_cast<std::int64_t>(k));
  return gen_number(Exact(s.lo + s.step * static_cast<long>(k))).Scalar();
}

YAML::Node draw_planned(const VaryPlan::Spec& s, const YAML::Node& base, Rng& rng,
                        const std::string& file);

// Appends item's draw to the sequence `out`. A number is made in place, in out's own memory:
// a node made apart and pushed is merged into it, which costs more than the draw.
void append_draw(YAML::Node& out, const VaryPlan::Spec& item, const YAML::Node& base, Rng& rng,
                 const std::string& file) {
  if (item.type == VaryPlan::Spec::Type::Range) {
    out[out.size()] = draw_number(item, rng);
    return;
  }
  out.push_back(draw_planned(item, base, rng, file));
}

YAML::Node draw_planned(const VaryPlan::Spec& s, const YAML::Node& base, Rng& rng,
                        const std::string& file) {
  using Type = VaryPlan::Spec::Type;
  switch (s.type) {
    case Type::Range:
      return YAML::Node(draw_number(s, rng));
    case Type::Choices:
      return clone_node(s.node[static_cast<std::size_t>(rng.below(s.node.size()))]);
    case Type::Each: {
      const std::size_t count = s.each_count ? *s.each_count : base.IsSequence() ? base.size() : 0;
      if (count == 0)
        fail_at(s.node, file, s.field, "`each` needs a list in `given` to vary, or a `count`");
      YAML::Node out(YAML::NodeType::Sequence);
      for (std::size_t i = 0; i < count; ++i)
        append_draw(out, s.items[0], base.IsSequence() && i < base.size() ? base[i] : YAML::Node(),
                    rng, file);
      out.SetStyle(YAML::EmitterStyle::Flow);
      return out;
    }
    case Type::List: {
      YAML::Node out(YAML::NodeType::Sequence);
      for (std::size_t i = 0; i < s.items.size(); ++i)
        append_draw(out, s.items[i], base.IsSequence() && i < base.size() ? base[i] : YAML::Node(),
                    rng, file);
      out.SetStyle(YAML::EmitterStyle::Flow);
      return out;
    }
    case Type::Map: {
      // Drawn in the plan's order (the same random draws as ever), then placed: the base's fields
      // in their order, each drawn or (when not varied) copied, then the drawn fields the base
      // lacks. A varied field is not copied only to be replaced.
      std::vector<YAML::Node> drawn;
      drawn.reserve(s.items.size());
      for (std::size_t i = 0; i < s.items.size(); ++i)
        drawn.push_back(
            draw_planned(s.items[i], base.IsMap() ? base[s.keys[i]] : YAML::Node(), rng, file));
      YAML::Node out(YAML::NodeType::Map);
      std::vector<bool> placed(s.items.size(), false);
      if (base.IsMap())
        for (auto it = base.begin(); it != base.end(); ++it) {
          const std::string key = it->first.Scalar();
          const auto varied = std::find(s.keys.begin(), s.keys.end(), key);
          if (varied == s.keys.end()) {
            out[key] = clone_node(it->second);
            continue;
          }
          const auto i = static_cast<std::size_t>(varied - s.keys.begin());
          out[key] = drawn[i];
          placed[i] = true;
        }
      for (std::size_t i = 0; i < s.items.size(); ++i)
        if (!placed[i]) out[s.keys[i]] = drawn[i];
      return out;
    }
    case Type::Value:
      break;
  }
  return clone_node(s.node);
}

}  // namespace

VaryPlan::VaryPlan(const YAML::Node& vary, const KindInfo& kind, const std::string& file,
                   const std::string& field)
    : file_(file) {
  check_vary(vary, kind, file, field);
  // The block is a mapping of given fields (check_vary), drawn as apply_vary draws it even
  // when a field's name is one of range, choices or each.
  Spec root;
  root.type = Spec::Type::Map;
  for (auto it = vary.begin(); it != vary.end(); ++it) {
    root.keys.push_back(it->first.as<std::string>());
    root.items.push_back(plan_spec(it->second, file, field + "." + root.keys.back()));
  }
  root_ = std::make_unique<const Spec>(std::move(root));
}

VaryPlan::~VaryPlan() = default;

YAML::Node VaryPlan::draw(const YAML::Node& base, Rng& rng) const {
  return draw_planned(*root_, base, rng, file_);
}

}  // namespace frustum
