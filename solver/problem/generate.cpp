#include "solver/problem/generate.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "solver/util/exact_format.hpp"

namespace frustum {

namespace {

bool integer_literal(const std::string& s) {
  std::size_t i = s[0] == '-' ? 1 : 0;
  if (i >= s.size() || s.size() > 12) return false;
  for (; i < s.size(); ++i)
    if (s[i] < '0' || s[i] > '9') return false;
  return true;
}

// A number as written in a given: digits, a fraction, a decimal or an expression (sqrt(2), pi/3).
bool number_literal(const std::string& s) {
  if (s.empty()) return false;
  return s.find_first_of("0123456789") != std::string::npos || s.find("pi") != std::string::npos;
}

// A mesh's vertices drawn again as one solid: every vertex moved by the same map
// v ↦ (a·x + p, b·y + q, c·z + r) with a, b, c in {1, 2} and p, q, r in [−2, 2], so faces stay
// planar, the solid keeps its orientation (a, b, c > 0) and convex stays convex. Vertices that
// are not all integers stay as they are.
std::optional<YAML::Node> redraw_vertices(const YAML::Node& n, Rng& rng) {
  std::vector<std::vector<std::int64_t>> v;
  for (const YAML::Node& vertex : n) {
    if (!vertex.IsSequence() || vertex.size() != 3) return std::nullopt;
    std::vector<std::int64_t> p;
    for (const YAML::Node& c : vertex) {
      if (!c.IsScalar() || !integer_literal(c.Scalar())) return std::nullopt;
      p.push_back(std::stoll(c.Scalar()));
    }
    v.push_back(p);
  }
  std::int64_t scale[3], shift[3];
  for (int i = 0; i < 3; ++i) {
    scale[i] = rng.integer(1, 2);
    shift[i] = rng.integer(-2, 2);
  }
  YAML::Node out(YAML::NodeType::Sequence);
  for (const std::vector<std::int64_t>& p : v) {
    YAML::Node q(YAML::NodeType::Sequence);
    for (int i = 0; i < 3; ++i) q.push_back(gen_number(scale[i] * p[i] + shift[i]));
    q.SetStyle(YAML::EmitterStyle::Flow);
    out.push_back(q);
  }
  out.SetStyle(YAML::EmitterStyle::Flow);
  return out;
}

YAML::Node redraw(const YAML::Node& n, const std::string& key, Rng& rng) {
  if (key == "vertices" && n.IsSequence())
    if (std::optional<YAML::Node> moved = redraw_vertices(n, rng)) return *moved;
  if (n.IsMap()) {
    YAML::Node out(YAML::NodeType::Map);
    for (auto it = n.begin(); it != n.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      out[k] = redraw(it->second, k, rng);
    }
    out.SetStyle(n.Style());
    return out;
  }
  if (n.IsSequence()) {
    YAML::Node out(YAML::NodeType::Sequence);
    for (const YAML::Node& item : n) out.push_back(redraw(item, key, rng));
    out.SetStyle(YAML::EmitterStyle::Flow);
    return out;
  }
  if (!n.IsScalar() || !integer_literal(n.Scalar())) return YAML::Node(n.Scalar());
  static const std::vector<std::string> kept = {"dim",   "width", "height",
                                                "label", "faces", "pixels"};
  if (std::find(kept.begin(), kept.end(), key) != kept.end()) return YAML::Node(n.Scalar());
  const std::int64_t v = std::stoll(n.Scalar());
  if (v == 0) return gen_number(0);
  const bool angle = key == "fovy" || key == "fov" || key == "angle" || key.rfind("rotate", 0) == 0;
  if (angle) {
    const std::int64_t a = rng.pick(std::vector<std::int64_t>{30, 45, 60, 90, 120, 135, 150});
    return gen_number(v < 0 ? -a : std::abs(v) < 180 ? a : v);
  }
  const std::int64_t mag = std::abs(v), r = std::max<std::int64_t>(2, mag / 2);
  const std::int64_t m = rng.integer(std::max<std::int64_t>(1, mag - r), mag + r);
  return gen_number(v < 0 ? -m : m);
}

}  // namespace

namespace {

// given_shape written onto the end of `out` (every draw of a written exercise's default variant
// compares up to kShapeTries of these, so lists are written in place rather than joined).
void append_shape(const YAML::Node& n, std::string& out) {
  if (n.IsMap()) {
    std::vector<std::string> parts;
    for (auto it = n.begin(); it != n.end(); ++it) {
      std::string part = it->first.as<std::string>() + ":";
      append_shape(it->second, part);
      parts.push_back(std::move(part));
    }
    std::sort(parts.begin(), parts.end());
    out += '{';
    for (const std::string& p : parts) (out += p) += ',';
    out += '}';
  } else if (n.IsSequence()) {
    out += '[';
    for (const YAML::Node& item : n) {
      append_shape(item, out);
      out += ',';
    }
    out += ']';
  } else if (n.IsScalar()) {
    const std::string& text = n.Scalar();
    if (number_literal(text))
      out += '#';
    else
      ((out += '\'') += text) += '\'';
  } else {
    out += '~';
  }
}

}  // namespace

std::string given_shape(const YAML::Node& n) {
  std::string out;
  append_shape(n, out);
  return out;
}

YAML::Node redraw_values(const YAML::Node& given, Rng& rng) { return redraw(given, "", rng); }

YAML::Node gen_number(std::int64_t v) { return YAML::Node(std::to_string(v)); }

YAML::Node gen_number(const Exact& v) {
  const Exact c = canonical(v);
  return YAML::Node(format_exact(c, MathStyle::Plain));
}

namespace {

// Fills n, a node of the tree being built, as a flow list of the numbers. Items made through
// n[i] live in n's memory; push_back(Node) would give each its own and then merge it in, which
// is most of the cost of a generated variant.
void fill_list(YAML::Node n, const std::vector<std::int64_t>& v) {
  for (std::size_t i = 0; i < v.size(); ++i) n[i] = std::to_string(v[i]);
  n.SetStyle(YAML::EmitterStyle::Flow);
}

}  // namespace

YAML::Node gen_list(const std::vector<std::int64_t>& v) {
  YAML::Node n(YAML::NodeType::Sequence);
  fill_list(n, v);
  return n;
}

YAML::Node gen_list(const std::vector<Exact>& v) {
  YAML::Node n(YAML::NodeType::Sequence);
  for (const Exact& x : v) n.push_back(gen_number(x));
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

YAML::Node gen_rows(const std::vector<std::vector<std::int64_t>>& rows) {
  YAML::Node n(YAML::NodeType::Sequence);
  for (std::size_t i = 0; i < rows.size(); ++i) fill_list(n[i], rows[i]);
  n.SetStyle(YAML::EmitterStyle::Flow);
  return n;
}

YAML::Node gen_word(const std::string& w) { return YAML::Node(w); }

YAML::Node gen_window(std::int64_t xmin, std::int64_t xmax, std::int64_t ymin, std::int64_t ymax) {
  YAML::Node w;
  w["xmin"] = gen_number(xmin);
  w["xmax"] = gen_number(xmax);
  w["ymin"] = gen_number(ymin);
  w["ymax"] = gen_number(ymax);
  return w;
}

YAML::Node gen_fraction(std::int64_t num, std::int64_t den) {
  return gen_number(Exact(GiNaC::numeric(num, den)));
}

YAML::Node gen_angle(std::int64_t degrees, const Conventions& c) {
  if (c.angles == AngleUnit::Degrees) return gen_number(degrees);
  return gen_number(Exact(GiNaC::numeric(degrees, 180) * GiNaC::Pi));
}

IVec3 gen_ivec3(Rng& rng, std::int64_t lo, std::int64_t hi) {
  IVec3 v;
  for (std::int64_t& x : v) x = rng.integer(lo, hi);
  return v;
}

IVec3 isub(const IVec3& a, const IVec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
IVec3 iadd(const IVec3& a, const IVec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
IVec3 iscale(std::int64_t k, const IVec3& a) { return {k * a[0], k * a[1], k * a[2]}; }
IVec3 icross(const IVec3& a, const IVec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
std::int64_t idot(const IVec3& a, const IVec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

bool is_square(std::int64_t v) {
  if (v < 0) return false;
  auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
  while (r * r > v) --r;
  while ((r + 1) * (r + 1) <= v) ++r;
  return r * r == v;
}

std::vector<std::int64_t> to_list(const IVec3& v) { return {v[0], v[1], v[2]}; }

YAML::Node gen_points(const std::vector<IVec3>& points) {
  std::vector<std::vector<std::int64_t>> rows;
  for (const IVec3& p : points) rows.push_back(to_list(p));
  return gen_rows(rows);
}

std::array<IVec3, 3> gen_triangle(Rng& rng, const GenerateOptions& o, std::int64_t lo,
                                  std::int64_t hi) {
  constexpr int kTries = 2000;  // nice triangles are a few percent of all
  std::array<IVec3, 3> t{};
  for (int attempt = 0; attempt < kTries; ++attempt) {
    t = {gen_ivec3(rng, lo, hi), gen_ivec3(rng, lo, hi), gen_ivec3(rng, lo, hi)};
    // Hard: C a little off the line AB, beyond B.
    if (o.hard) t[2] = iadd(iadd(t[0], iscale(2, isub(t[1], t[0]))), gen_ivec3(rng, 0, 1));
    const IVec3 n = icross(isub(t[1], t[0]), isub(t[2], t[0]));
    if (idot(n, n) == 0) continue;
    std::vector<std::vector<double>> d;
    for (const IVec3& p : t) d.push_back({double(p[0]), double(p[1]), double(p[2])});
    if ((triangle_shape(d) < kMinTriangleShape) != o.hard) continue;
    if (!o.nice || is_square(idot(n, n))) break;
  }
  return t;
}

namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) s += a[i] * b[i];
  return s;
}

std::vector<double> minus(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - (i < b.size() ? b[i] : 0.0);
  return d;
}

}  // namespace

double triangle_shape(const std::vector<std::vector<double>>& p) {
  if (p.size() < 3) return 0;
  const std::vector<double> e0 = minus(p[1], p[0]), e1 = minus(p[2], p[0]), e2 = minus(p[2], p[1]);
  const double longest = std::max({dot(e0, e0), dot(e1, e1), dot(e2, e2)});
  if (longest == 0) return 0;
  // Area by Lagrange's identity: ‖e0 × e1‖² = ‖e0‖²‖e1‖² − (e0·e1)², in any dimension.
  const double cross2 = std::max(0.0, dot(e0, e0) * dot(e1, e1) - dot(e0, e1) * dot(e0, e1));
  return 0.5 * std::sqrt(cross2) / longest;
}

double sine_between(const std::vector<double>& a, const std::vector<double>& b) {
  const double aa = dot(a, a), bb = dot(b, b);
  if (aa == 0 || bb == 0) return 0;
  const double c = dot(a, b) / std::sqrt(aa * bb);
  return std::sqrt(std::max(0.0, 1 - c * c));
}

std::vector<double> doubles(const std::vector<Exact>& v) {
  std::vector<double> out;
  out.reserve(v.size());
  for (const Exact& e : v) out.push_back(to_double(e));
  return out;
}

std::vector<std::vector<double>> doubles(const std::vector<Vec3<Exact>>& points) {
  std::vector<std::vector<double>> out;
  for (const Vec3<Exact>& p : points) out.push_back(doubles(p));
  return out;
}

}  // namespace frustum
