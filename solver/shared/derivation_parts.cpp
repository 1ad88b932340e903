#include "solver/shared/derivation_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "solver/core/exact_vector.hpp"
#include "solver/core/rational_power.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/geometry/polygon_normal.hpp"
#include "solver/geometry/predicates.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/shared/digits_said.hpp"
#include "solver/shared/viewing_parts.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/util/exact_format.hpp"
#include "solver/viewing/projection.hpp"

namespace frustum {

namespace {

constexpr Phrase kNormalDirectionIllConditioned{"The normal's direction is ill-conditioned ({0}).",
                                                "法線の向きは条件が悪い ({0}).",
                                                "Направление нормали плохо обусловлено ({0})."};
constexpr Phrase kEdgeVectors{"Edge vectors", "辺ベクトル", "Векторы рёбер"};
constexpr Phrase kLeftHandedTriangleFront{
    "In left-handed coordinates the side from which p₀, p₁, p₂ run counter-clockwise is the side "
    "of e₁ × e₀ = −(e₀ × e₁): the right-handed formula e₀ × e₁ gives the opposite normal, that of "
    "the mirror image.",
    "左手系では p₀, p₁, p₂ が反時計回りに見える側は e₁ × e₀ = −(e₀ × e₁) の側である: 右手系の式 "
    "e₀ × e₁ は逆向きの法線, すなわち鏡像の法線を与える.",
    "В левой системе координат сторона, откуда p₀, p₁, p₂ идут против часовой стрелки, — это "
    "сторона e₁ × e₀ = −(e₀ × e₁): формула правой системы e₀ × e₁ даёт противоположную нормаль, "
    "нормаль зеркального образа."};
constexpr Phrase kNewellNormalLeftHanded{"Normal of the {0}-gon by Newell's method, left-handed",
                                         "Newell の方法による {0} 角形の法線 (左手系)",
                                         "Нормаль {0}-угольника методом Newell, левая система"};
constexpr Phrase kLeftHandedNewellSign{
    "In left-handed coordinates the counter-clockwise side's normal is the right-handed sum with "
    "its sign changed (e₁ × e₀ for a triangle).",
    "左手系では反時計回りに見える側の法線は右手系の和の符号を変えたもの (三角形では e₁ × e₀).",
    "В левой системе координат нормаль стороны, откуда обход идёт против часовой стрелки, — это "
    "сумма правой системы с обратным знаком (для треугольника e₁ × e₀)."};
constexpr Phrase kNewellNormal{"Normal of the {0}-gon by Newell's method",
                               "Newell の方法による {0} 角形の法線",
                               "Нормаль {0}-угольника методом Newell"};
constexpr Phrase kNewellSumsEveryPair{
    "Newell's method sums every edge pair, so it stays accurate when some edges are nearly "
    "parallel or nearly zero (where eᵢ × eᵢ₊₁ loses accuracy), and gives twice the vector area "
    "(the same direction as eᵢ × eᵢ₊₁ for a convex polygon).",
    "Newell の方法はすべての辺の組を足し合わせるので, ほぼ平行な辺やほぼ長さ 0 "
    "の辺があっても精度を保ち (eᵢ × eᵢ₊₁ では精度が落ちる), ベクトル面積の 2 倍を与える "
    "(凸多角形では eᵢ × eᵢ₊₁ と同じ向き).",
    "Метод Newell суммирует все пары рёбер, поэтому остаётся точным, когда некоторые рёбра почти "
    "параллельны или почти нулевые (где eᵢ × eᵢ₊₁ теряет точность), и даёт удвоенную векторную "
    "площадь (то же направление, что eᵢ × eᵢ₊₁, для выпуклого многоугольника)."};
constexpr Phrase kRepeatedVertex{"Repeated vertex", "重複した頂点", "Повторяющаяся вершина"};
constexpr Phrase kZeroEdge{
    "e{0} = p{1} − p{2} is the zero vector (a repeated vertex); the normal uses the other edges.",
    "e{0} = p{1} − p{2} は零ベクトル (重複した頂点) なので, 法線は残りの辺から求める.",
    "e{0} = p{1} − p{2} — нулевой вектор (повторяющаяся вершина); нормаль строится по остальным "
    "рёбрам."};
constexpr Phrase kNearlyParallelEdges{"Nearly parallel edges", "ほぼ平行な辺",
                                      "Почти параллельные рёбра"};
constexpr Phrase kEdgesNearlyParallel{
    "e{0} and e{1} are nearly parallel (sin θ ≈ {2}); e × e loses about {3} of double precision's "
    "16 digits here, but this normal is computed exactly.",
    "e{0} と e{1} はほぼ平行 (sin θ ≈ {2}). ここで e × e は double の 16 桁のうちおよそ {3} "
    "桁を失うが, この法線は厳密に計算している.",
    "e{0} и e{1} почти параллельны (sin θ ≈ {2}); здесь e × e теряет около {3} из 16 цифр double, "
    "но эта нормаль вычислена точно."};
constexpr Phrase kNonPlanarPolygon{"Non-planar polygon", "平面でない多角形",
                                   "Неплоский многоугольник"};
constexpr Phrase kVertexOffPlane{
    "vertex p{0} is not in the plane of the others; the normal is the best-fit (Newell) "
    "direction.",
    "頂点 p{0} は他の頂点の平面上にない. 法線は最もよく当てはまる (Newell の) 向きとする.",
    "вершина p{0} не лежит в плоскости остальных; нормаль — направление наилучшего приближения "
    "(Newell)."};
constexpr Phrase kIsPixelInside{"Is the pixel inside the projected triangle?",
                                "画素は投影された三角形の内側か?",
                                "Лежит ли пиксель внутри спроецированного треугольника?"};
constexpr Phrase kSignsAgree{
    "The signs agree (0 = on an edge), so the pixel is inside the closed triangle.",
    "符号がそろっている (0 = 辺上) ので, 画素は閉じた三角形の内側にある.",
    "Знаки совпадают (0 — на ребре), поэтому пиксель внутри замкнутого треугольника."};
constexpr Phrase kSignsDifferPlane{
    "The signs differ, so the pixel is outside; the plane still gives its z.",
    "符号がそろっていないので画素は外側にある. それでも平面から z は求まる.",
    "Знаки различаются, поэтому пиксель снаружи; плоскость всё равно даёт его z."};
constexpr Phrase kSignsDifferInterpolation{
    "The signs differ, so the pixel is outside (some λᵢ is negative); the interpolation still "
    "gives its z.",
    "符号がそろっていないので画素は外側にある (負の λᵢ がある). それでも補間から z は求まる.",
    "Знаки различаются, поэтому пиксель снаружи (некоторое λᵢ отрицательно); интерполяция всё "
    "равно даёт его z."};
constexpr Phrase kYouTookRightHandedFormula{
    "You took e₀ × e₁, the right-handed formula: in these left-handed coordinates, with the "
    "vertices counter-clockwise seen from the front, the front normal is n = e₁ × e₀.",
    "右手系の式 e₀ × e₁ を計算しています. この左手系の座標では, 表から見て頂点が反時計回りなので, "
    "表向きの法線は n = e₁ × e₀ です.",
    "Вы взяли e₀ × e₁, формулу правой системы: в этих левых координатах, когда вершины обходятся "
    "против часовой стрелки при взгляде с лицевой стороны, лицевая нормаль n = e₁ × e₀."};
constexpr Phrase kYouTookE1CrossE0{
    "You took e₁ × e₀: with the vertices counter-clockwise seen from the front, the front normal "
    "is n = e₀ × e₁.",
    "e₁ × e₀ を計算しています. 表から見て頂点が反時計回りなので, 表向きの法線は n = e₀ × e₁ です.",
    "Вы взяли e₁ × e₀: вершины обходятся против часовой стрелки, если смотреть с лицевой стороны, "
    "поэтому лицевая нормаль n = e₀ × e₁."};
constexpr Phrase kConstantOnTheWrongSide{"constant on the wrong side", "定数項の符号が逆",
                                         "свободный член не с той стороны"};
constexpr Phrase kConstantDWrongSign{"Your constant d has the wrong sign.",
                                     "定数 d の符号が逆です.", "У свободного члена d не тот знак."};
constexpr Phrase kPlaneWrittenWithD{
    "Here the plane is written a·x + b·y + c·z = d with d = n·{0}; a list [a, b, c, d] means the "
    "same form, not a·x + b·y + c·z + d = 0.",
    "ここでは平面を a·x + b·y + c·z = d (d = n·{0}) と書きます. "
    "リスト [a, b, c, d] も同じ形を表し, a·x + b·y + c·z + d = 0 ではありません.",
    "Здесь плоскость записывается как a·x + b·y + c·z = d, где d = n·{0}; список [a, b, c, d] "
    "означает ту же форму, а не a·x + b·y + c·z + d = 0."};
constexpr Phrase kPlaneConstantWrongSign{
    "Your plane's constant has the wrong sign: the plane through {0} is n·p = n·{1} (from "
    "n·(p − {2}) = 0), and yours is n·p = −n·{3}.",
    "平面の定数項の符号が逆です. {0} を通る平面は n·p = n·{1} (n·(p − {2}) = 0 から) ですが, "
    "あなたの平面は n·p = −n·{3} です.",
    "У свободного члена плоскости не тот знак: плоскость через {0} — это n·p = n·{1} (из "
    "n·(p − {2}) = 0), а у вас n·p = −n·{3}."};

}  // namespace

std::array<Exact, 4> carried_plane(const Vec3<Exact>& n, const std::vector<Vec3<Exact>>& points,
                                   const std::optional<std::vector<Exact>>& student) {
  const auto proportional = [](const std::array<Exact, 4>& p, const std::vector<Exact>& q) {
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = i + 1; j < 4; ++j)
        if (!canonical(p[i] * q[j] - p[j] * q[i]).is_zero()) return false;
    return true;
  };
  if (student && student->size() == 4)
    for (const Vec3<Exact>& v : points) {
      const std::array<Exact, 4> p = paper_plane(n, canonical(n.dot(v)));
      if (proportional(p, *student)) return p;
    }
  return paper_plane(n, canonical(n.dot(points.front())));
}

std::optional<Value> carried_points(const Answers& student,
                                    const std::vector<std::vector<Exact>>& points, std::size_t n,
                                    Api api) {
  const auto m = carried(student, "matrix", n * n);
  if (!m || points.empty()) return std::nullopt;
  MatX<Exact> paper(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j)
      paper(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = (*m)[i * n + j];
  try {
    return transform_points_with_steps(paper_form(paper, api), points, {}, "P", nullptr, api);
  } catch (const std::exception&) {
    return std::nullopt;  // a point sent to infinity (w = 0) by the student's matrix
  }
}

std::optional<std::vector<Exact>> carried(const Answers& student, const std::string& name,
                                          std::size_t size) {
  const Value* v = student.find(name);
  if (!v || v->exact.size() != size) return std::nullopt;
  bool all_zero = true;
  for (const Exact& e : v->exact) all_zero = all_zero && canonical(e).is_zero();
  if (all_zero) return std::nullopt;
  return v->exact;
}

std::optional<Value> carried_inverse(const Answers& student, const std::string& name,
                                     std::size_t n) {
  const auto m = carried(student, name, n * n);
  if (!m) return std::nullopt;
  const auto at = [&](std::size_t i, std::size_t j) { return (*m)[i * n + j]; };
  const bool rational = std::all_of(m->begin(), m->end(), [](const Exact& e) {
    return GiNaC::is_a<GiNaC::numeric>(e) && GiNaC::ex_to<GiNaC::numeric>(e).is_rational();
  });
  std::vector<std::vector<Exact>> rows(n, std::vector<Exact>(n));
  if (rational) {
    GiNaC::matrix g(static_cast<unsigned>(n), static_cast<unsigned>(n));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        g(static_cast<unsigned>(i), static_cast<unsigned>(j)) = at(i, j);
    if (g.determinant().is_zero()) return std::nullopt;
    const GiNaC::matrix inverse = g.inverse();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        rows[i][j] = canonical(inverse(static_cast<unsigned>(i), static_cast<unsigned>(j)));
  } else {
    Eigen::MatrixXd d(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        d(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = to_double(at(i, j));
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(d);
    if (!d.allFinite() || !lu.isInvertible()) return std::nullopt;
    const Eigen::MatrixXd inverse = lu.inverse();
    if (!inverse.allFinite()) return std::nullopt;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        rows[i][j] =
            exact_from_double(inverse(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
  }
  return Value::matrix(rows);
}

void warn_condition(Derivation* steps, double kappa, const Said& title, const Phrase& sentence) {
  if (!steps || !(kappa > kIllConditioned)) return;
  steps->warn(title, say(sentence, digits_said(kappa)));
}

namespace {

std::vector<Eigen::Vector3d> to_doubles(const Polygon3<Exact>& p) {
  std::vector<Eigen::Vector3d> out;
  for (const Vec3<Exact>& v : p) out.push_back(to_double(v));
  return out;
}

}  // namespace

std::string point_name(const std::string& stem, std::size_t i) { return stem + std::to_string(i); }

Value plane_answer(const std::array<Exact, 4>& plane) {
  Value v = Value::vector(std::vector<Exact>(plane.begin(), plane.end()));
  v.display = plane_equation(plane[0], plane[1], plane[2], plane[3]);
  return v;
}

std::optional<Misconception> reversed_normal_mistake(const Vec3<Exact>& n, std::size_t vertices,
                                                     bool left_handed,
                                                     const std::optional<CrossOrder>& order) {
  if (!order && vertices != 3) return std::nullopt;
  const Vec3<Exact> r(-n);
  Answers answers;
  answers.set("normal", Value::vector(r));
  if (!canonical(r.dot(r)).is_zero()) answers.set("unit_normal", Value::vector(unit(r)));
  if (order)
    return Misconception{say(kind_words::kReversedCrossProduct),
                         say(kind_words::kYouTook, order->second + " × " + order->first),
                         say(kind_words::kNormalTitle), answers};
  return Misconception{
      say(kind_words::kReversedCrossProduct),
      say(left_handed ? kYouTookRightHandedFormula : kYouTookE1CrossE0),
      say(left_handed ? kind_words::kNormalLeftHandedTitle : kind_words::kNormalRightHandedTitle),
      answers};
}

std::optional<Misconception> constant_sign_mistake(const Vec3<Exact>& n, const Exact& d,
                                                   const std::string& point, const Said& step) {
  if (canonical(d).is_zero()) return std::nullopt;
  Answers answers;
  answers.set("plane", plane_answer(paper_plane(n, canonical(-d))));
  // Said in the student's form: a list [a, b, c, d] is read as a·x + b·y + c·z = d, which is
  // what a list writer may have taken for … + d = 0; an equation says its own constant.
  return Misconception{say(kConstantOnTheWrongSide),
                       say(kConstantDWrongSign) + say(kPlaneWrittenWithD, point),
                       step,
                       answers,
                       {{"equation", say(kPlaneConstantWrongSign, point, point, point, point)}}};
}

Vec3<Exact> unit(const Vec3<Exact>& n) {
  const Exact len = canonical_norm(n);
  Vec3<Exact> u;
  // A rational vector's length, canonical, is c·√r (c rational, r a square-free integer) or
  // rational: then nᵢ/‖n‖ = nᵢ/(c·r)·√r, the canonical form itself, with the one √r reused
  // instead of each quotient simplified again.
  GiNaC::numeric c;
  Exact root;
  if (is_rational(n(0)) && is_rational(n(1)) && is_rational(n(2)) && !len.is_zero() &&
      rational_times_square_root(len, c, root)) {
    const GiNaC::numeric scale =
        root.is_equal(1) ? c : c * GiNaC::ex_to<GiNaC::numeric>(root.op(0));
    for (int i = 0; i < 3; ++i) u(i) = GiNaC::ex_to<GiNaC::numeric>(n(i)) / scale * root;
    return u;
  }
  for (int i = 0; i < 3; ++i) u(i) = canonical(n(i) / len);
  return u;
}

Vec3<Exact> unit_normal_with_steps(const Vec3<Exact>& n, Derivation* steps) {
  const Vec3<Exact> u = unit(n);
  record_unit_normal(n, u, steps);
  return u;
}

void record_unit_normal(const Vec3<Exact>& n, const Vec3<Exact>& u, Derivation* steps) {
  if (steps)
    steps
        ->add(say(kind_words::kUnitNormalTitle),
              tex("\\hat{\\mathbf{n}} = \\mathbf{n} / \\lVert\\mathbf{n}\\rVert,\\; "
                  "\\lVert\\mathbf{n}\\rVert = \\sqrt{n_x^2 + n_y^2 + n_z^2}"),
              tex("\\lVert\\mathbf{n}\\rVert = ") + exact(norm(n), true),
              tex("\\hat{\\mathbf{n}} = ") + vec(u, true))
        .yields("unit_normal");
}

Polygon3<Exact> reversed_winding(const Polygon3<Exact>& p) {
  Polygon3<Exact> out(p.rbegin(), p.rend());
  if (!out.empty()) std::rotate(out.begin(), out.end() - 1, out.end());
  return out;
}

Vec3<Exact> polygon_normal_with_steps(const Polygon3<Exact>& p, const std::string& field,
                                      Derivation* steps, bool left_handed) {
  const PolygonAnalysis a = analyse_polygon(p);
  if (a.degenerate)
    throw DomainError(field,
                      "the polygon is degenerate: its vertices are collinear or "
                      "coincident, so it has no normal");
  // The normal by the formula the numeric paths use, on the polygon in the winding they read
  // (a left-handed front normal, e₁ × e₀ or −Newell's, is that of the reversed polygon); the
  // steps show it.
  Vec3<Exact> n = polygon_normal_formula(left_handed ? reversed_winding(p) : p);
  for (int i = 0; i < 3; ++i) n(i) = canonical(n(i));
  if (p.size() == 3) {
    const Vec3<Exact> e0 = edge(p, 0), e1 = edge(p, 1);
    if (steps) {
      steps->add(say(kEdgeVectors),
                 tex("\\mathbf{e}_0 = \\mathbf{p}_1 - \\mathbf{p}_0,\\; \\mathbf{e}_1 = "
                     "\\mathbf{p}_2 - \\mathbf{p}_1"),
                 {}, tex("\\mathbf{e}_0 = ") + vec(e0) + tex(",\\; \\mathbf{e}_1 = ") + vec(e1));
      if (left_handed)
        steps
            ->add(say(kind_words::kNormalLeftHandedTitle),
                  tex("\\mathbf{n} = \\mathbf{e}_1 \\times \\mathbf{e}_0"),
                  tex("\\mathbf{n} = ") + vec(e1) + tex(" \\times ") + vec(e0),
                  tex("\\mathbf{n} = ") + vec(n))
            .note = say(kLeftHandedTriangleFront);
      else
        steps->add(say(kind_words::kNormalRightHandedTitle),
                   tex("\\mathbf{n} = \\mathbf{e}_0 \\times \\mathbf{e}_1"),
                   tex("\\mathbf{n} = ") + vec(e0) + tex(" \\times ") + vec(e1),
                   tex("\\mathbf{n} = ") + vec(n));
    }
  } else {
    if (steps && left_handed)
      steps
          ->add(say(kNewellNormalLeftHanded, p.size()),
                tex("\\mathbf{n} = -\\sum_i (\\mathbf{p}_i - \\mathbf{p}_0) \\times "
                    "(\\mathbf{p}_{i+1} - \\mathbf{p}_0)"),
                {}, tex("\\mathbf{n} = ") + vec(n))
          .note = say(kLeftHandedNewellSign);
    else if (steps)
      steps
          ->add(say(kNewellNormal, p.size()),
                tex("\\mathbf{n} = \\sum_i (\\mathbf{p}_i - \\mathbf{p}_0) \\times "
                    "(\\mathbf{p}_{i+1} - \\mathbf{p}_0)"),
                {}, tex("\\mathbf{n} = ") + vec(n))
          .note = say(kNewellSumsEveryPair);
  }
  if (steps) {
    for (std::size_t i : a.zero_edges)
      steps->warn(say(kRepeatedVertex), say(kZeroEdge, i, (i + 1) % p.size(), i));
    if (a.min_sine < kNearParallelSine)
      steps->warn(say(kNearlyParallelEdges),
                  say(kEdgesNearlyParallel, a.worst_pair, (a.worst_pair + 1) % p.size(),
                      format_approx(a.min_sine), fmt::format("{:.0f}", std::log10(a.condition))));
    warn_condition(steps, normal_condition(to_doubles(p)), say(kIllConditionedNormal),
                   kNormalDirectionIllConditioned);
    if (!a.planar) steps->warn(say(kNonPlanarPolygon), say(kVertexOffPlane, a.off_plane_vertex));
  }
  return n;
}

namespace {

// c[i] / |c[first]| for i = 0..3, each canonical, or nullopt when one is not rational. When
// every non-zero c[i] is a rational multiple of the same positive root, the quotient is the
// ratio of the rationals (what canonical() of the quotient gives), found without dividing
// expressions.
std::optional<std::array<Exact, 4>> rational_ratios(const std::array<Exact, 4>& c, int first,
                                                    bool by_quotients) {
  std::array<Exact, 4> r;
  if (!by_quotients) {
    std::array<GiNaC::numeric, 4> q;
    std::optional<std::optional<RationalPower>> common;
    bool shared = true;
    for (int i = 0; i < 4 && shared; ++i) {
      RationalMultiple m;
      shared = rational_multiple(c[i], m);
      q[i] = m.q;
      if (shared && !q[i].is_zero()) {
        if (!common) common = m.radical;
        shared = same_radical(*common, m.radical);
      }
    }
    if (shared) {
      const GiNaC::numeric lead = GiNaC::abs(q[first]);
      for (int i = 0; i < 4; ++i) r[i] = q[i] / lead;
      return r;
    }
  }
  const Exact lead = exact_sign(c[first]) < 0 ? Exact(-c[first]) : c[first];
  for (int i = 0; i < 4; ++i) {
    r[i] = canonical(c[i] / lead);
    if (!is_rational(r[i])) return std::nullopt;
  }
  return r;
}

}  // namespace

std::array<Exact, 4> paper_plane(const Vec3<Exact>& n, const Exact& d, bool by_quotients) {
  std::array<Exact, 4> c = {canonical(n(0)), canonical(n(1)), canonical(n(2)), canonical(d)};
  // Divide by the first non-zero coefficient's magnitude; if everything is then rational,
  // clear denominators and common factors.
  int first = 0;
  while (first < 3 && c[first].is_zero()) ++first;
  if (first == 3) return c;
  std::optional<std::array<Exact, 4>> ratios = rational_ratios(c, first, by_quotients);
  if (!ratios) return c;
  std::array<Exact, 4>& r = *ratios;
  GiNaC::numeric denominators = 1, numerators = 0;
  for (const Exact& x : r) {
    const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(x);
    denominators = GiNaC::lcm(denominators, q.denom());
  }
  for (const Exact& x : r)
    numerators = GiNaC::gcd(numerators, GiNaC::ex_to<GiNaC::numeric>(x * denominators).numer());
  for (Exact& x : r) x = canonical(x * denominators / numerators);
  return r;
}

}  // namespace frustum

#include "solver/input/given_reader.hpp"

namespace frustum {

namespace {

bool valid_edge_name(const std::string& s) {
  return s.size() == 2 && s[0] != s[1] && std::string("ABC").find(s[0]) != std::string::npos &&
         std::string("ABC").find(s[1]) != std::string::npos;
}

}  // namespace

CrossOrder read_cross(GivenReader& r, const std::string& key, CrossOrder fallback) {
  if (!r.has(key)) return fallback;
  const std::vector<std::string> w = r.words(key, 2);
  for (const std::string& s : w)
    if (!valid_edge_name(s))
      r.fail(key, "'" + s + "' is not an edge of triangle ABC (use AB, AC, BC, BA, CA or CB)");
  return {w[0], w[1]};
}

Vec3<Exact> named_edge(const std::string& name, const std::array<Vec3<Exact>, 3>& abc) {
  const Vec3<Exact>& from = abc[static_cast<std::size_t>(name[0] - 'A')];
  const Vec3<Exact>& to = abc[static_cast<std::size_t>(name[1] - 'A')];
  return to - from;
}

std::array<int, 4> cross_indices(const CrossOrder& order) {
  return {order.first[0] - 'A', order.first[1] - 'A', order.second[0] - 'A', order.second[1] - 'A'};
}

void refuse_edge_on_triangle(const std::string& field) {
  throw DomainError(
      field,
      "the triangle is edge-on (c = 0 in ax + by + cz = d): its plane has no single z "
      "above a pixel");
}

Vec3<Exact> cross_normal_with_steps(const std::array<Vec3<Exact>, 3>& abc, const CrossOrder& order,
                                    const std::string& field, Derivation* steps) {
  Vec3<Exact> n = cross_order_normal<Exact>(abc, cross_indices(order));
  for (int i = 0; i < 3; ++i) n(i) = canonical(n(i));
  if (canonical_dot(n, n).is_zero())
    throw DomainError(field, "the points are collinear (" + order.first + " × " + order.second +
                                 " = 0): the triangle has no normal");
  if (steps) {
    const Vec3<Exact> u = named_edge(order.first, abc), v = named_edge(order.second, abc);
    auto edge_text = [&](const std::string& e, const Vec3<Exact>& value) {
      const std::string from(1, e[0]), to(1, e[1]);
      return tex("\\overrightarrow{" + e + "} = " + to + " - " + from + " = ") + vec(value);
    };
    steps->add(say(kEdgeVectors), {}, {},
               edge_text(order.first, u) + tex(",\\; ") + edge_text(order.second, v));
    steps->add(say(kind_words::kNormalTitle),
               tex("\\mathbf{n} = \\overrightarrow{" + order.first + "} \\times \\overrightarrow{" +
                   order.second + "}"),
               tex("\\mathbf{n} = ") + vec(u) + tex(" \\times ") + vec(v),
               tex("\\mathbf{n} = ") + vec(n));
    warn_condition(steps, normal_condition(to_doubles({abc[0], abc[1], abc[2]})),
                   say(kIllConditionedNormal), kNormalDirectionIllConditioned);
  }
  return n;
}

}  // namespace frustum

namespace frustum {

bool inside_triangle_with_steps(const std::array<Vec3<Exact>, 3>& triangle,
                                const Vec2<Exact>& pixel, Derivation* steps, ZFrom z_from) {
  const PixelSides sides = pixel_sides(triangle, pixel, triangle, pixel, true);
  const int s0 = sides.sign[0], s1 = sides.sign[1], s2 = sides.sign[2];
  const bool inside = sides.inside;
  if (steps) {
    const auto sign_text = [](int s) { return s > 0 ? math("+") : s < 0 ? tex("-") : math("0"); };
    steps
        ->add(say(kIsPixelInside),
              tex("\\operatorname{sign} E_{AB}(x_S, y_S),\\; \\operatorname{sign} E_{BC}(x_S, "
                  "y_S),\\; "
                  "\\operatorname{sign} E_{CA}(x_S, y_S)"),
              sign_text(s0) + math(", ") + sign_text(s1) + math(", ") + sign_text(s2),
              word(inside ? words::kInside : words::kOutside))
        .yields("inside")
        .note = say(inside                   ? kSignsAgree
                    : z_from == ZFrom::Plane ? kSignsDifferPlane
                                             : kSignsDifferInterpolation);
  }
  return inside;
}

}  // namespace frustum
