// Homogeneous coordinates of a point (seed 002): a point (x, y) is (w·x, w·y, w) for every w ≠ 0,
// so (5, 7) is (5, 7, 1), (10, 14, 2), …; a homogeneous (X, Y, W) is the point (X/W, Y/W); and
// two tuples are one point when their quotients are equal. In 2-D or 3-D.
#include <fmt/format.h>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/derivation_parts.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kHomogeneous{"homogeneous", "同次座標", "однородные координаты"};
constexpr Phrase kCartesian{"cartesian", "通常座標", "декартовы координаты"};
constexpr Phrase kSamePoint{"same_point", "同じ点か", "та же ли точка"};

constexpr Phrase kHomogeneousCoordinates{"Homogeneous coordinates of the point", "点の同次座標",
                                         "Однородные координаты точки"};
constexpr Phrase kBackToThePoint{"Back to the point", "通常座標に戻す", "Обратно к точке"};
constexpr Phrase kTheSamePoint{"The same point?", "同じ点か?", "Та же точка?"};
constexpr Phrase kEqualQuotients{"equal quotients", "商が等しい", "частные равны"};
constexpr Phrase kTheSamePointWord{"the same point", "同じ点", "та же точка"};
constexpr Phrase kWrittenWithW{"With W = {0} the point {1} is written {2}.",
                               "W = {0} とすると, 点 {1} は {2} と表される.",
                               "При W = {0} точка {1} записывается как {2}."};
constexpr Phrase kWAppended{"w appended, coordinates not multiplied",
                            "w を付け加えただけで座標に掛けていない",
                            "w дописан, координаты не умножены"};
constexpr Phrase kEveryCoordinateMultiplied{
    "Every coordinate is multiplied by w, not only the last one added: (x, y) with weight w is "
    "(w·x, w·y, w).",
    "追加した成分だけでなく, すべての座標に w を掛けます: 重み w の (x, y) は (w·x, w·y, w) です.",
    "На w умножается каждая координата, а не только дописывается последняя: точка (x, y) с "
    "весом w — это (w·x, w·y, w)."};
constexpr Phrase kWLeftAt1{"coordinates multiplied, w left at 1",
                           "座標に w を掛けたが最後の成分を 1 のままにした",
                           "координаты умножены, w оставлен равным 1"};
constexpr Phrase kLastCoordinateIsW{
    "The last coordinate is w itself: after multiplying x and y by w, write w, not 1.",
    "最後の成分は w そのものです: x と y に w を掛けたら, 最後は 1 ではなく w と書きます.",
    "Последняя координата — само w: умножив x и y на w, пишите w, а не 1."};
constexpr Phrase kMultipliedByW{"multiplied by W instead of dividing", "W で割らずに掛けた",
                                "умножено на W вместо деления"};
constexpr Phrase kDivideByW{"From (X, Y, W) the point is (X/W, Y/W): divide by W.",
                            "(X, Y, W) が表す点は (X/W, Y/W) です: W で割ります.",
                            "Кортеж (X, Y, W) задаёт точку (X/W, Y/W): делите на W."};
constexpr Phrase kWDropped{"W dropped without dividing", "W で割らずに W を取り除いた",
                           "W отброшен без деления"};
constexpr Phrase kDroppingWOnlyWhenOne{
    "Dropping W gives the point only when W = 1; otherwise divide X and Y by W.",
    "W を取り除くだけで点になるのは W = 1 のときだけです. それ以外は X と Y を W で割ります.",
    "Отбросить W можно только при W = 1; иначе делите X и Y на W."};

// The names written in the formulas: x, y[, z] and X, Y[, Z], W.
MathText coordinates(std::size_t dim, bool upper, bool with_w) {
  static constexpr const char* kLower[] = {"x", "y", "z"};
  static constexpr const char* kUpper[] = {"X", "Y", "Z"};
  std::string text = "(";
  for (std::size_t i = 0; i < dim; ++i)
    text += std::string(i ? ", " : "") + (upper ? kUpper[i] : kLower[i]);
  if (with_w) text += upper ? ", W" : ", w";
  return math(text + ")");
}

// (w·x, w·y[, w·z], w).
MathText scaled_names(std::size_t dim) {
  static constexpr const char* kLower[] = {"x", "y", "z"};
  std::string latex = "(";
  for (std::size_t i = 0; i < dim; ++i)
    latex += fmt::format("{}w\\cdot{{{}}}", i ? ", " : "", kLower[i]);
  return tex(latex + ", w)");
}

struct Homogeneous {
  static constexpr const char* kName = "homogeneous";
  static constexpr Phrase kSummary{"a point in homogeneous coordinates and back",
                                   "点の同次座標表現と通常座標への変換",
                                   "точка в однородных координатах и обратно"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  struct Given {
    std::vector<Exact> point;                     // Cartesian, 2 or 3 coordinates
    std::optional<Exact> w;                       // the weight of `homogeneous`
    std::optional<std::vector<Exact>> candidate;  // a homogeneous tuple: dim + 1 numbers
  };
  static std::vector<std::string> given_fields() { return {"point", "w", "candidate"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "homogeneous",
             .kind = AnswerKind::Vector,
             .needs_given = "w",
             .label = say(kHomogeneous)},
            {.name = "cartesian",
             .kind = AnswerKind::Vector,
             .needs_given = "candidate",
             .label = say(kCartesian)},
            {.name = "same_point",
             .kind = AnswerKind::Bool,
             .depends_on = {"cartesian"},
             .needs_given = "candidate",
             .label = say(kSamePoint)}};
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    const std::size_t given = r.has("point") && r.is_list("point") ? r.node()["point"].size() : 0;
    if (given != 2 && given != 3) r.fail("point", "give the point's 2 or 3 coordinates");
    const std::size_t dim = given;
    g.point = r.numbers("point", dim);
    if (r.has("w")) {
      g.w = r.number("w");
      if (exact_sign(*g.w) == 0) r.fail("w", "must not be 0: (0, 0, 0) is no point");
    }
    if (r.has("candidate")) {
      g.candidate = r.numbers("candidate", dim + 1);
      if (exact_sign(g.candidate->back()) == 0)
        r.fail("candidate", "its last number (W) must not be 0: W = 0 is a point at infinity");
    }
    if (!g.w && !g.candidate) r.fail("w", "give w (to write the point) or candidate (to read one)");
    return g;
  }

  // The mistakes: the coordinates not multiplied by w (only w appended), or w kept at 1; X, Y
  // multiplied by W instead of divided, or W simply dropped.
  static std::vector<Misconception> misconceptions(const Given& g) {
    std::vector<Misconception> out;
    const std::size_t dim = g.point.size();
    if (g.w && exact_sign(*g.w - 1) != 0) {
      std::vector<Exact> appended = g.point, unit_w;
      appended.push_back(*g.w);
      for (const Exact& x : g.point) unit_w.push_back(canonical(*g.w * x));
      unit_w.push_back(Exact(1));
      Answers a, b;
      a.set("homogeneous", Value::vector(appended));
      b.set("homogeneous", Value::vector(unit_w));
      out.push_back(
          {say(kWAppended), say(kEveryCoordinateMultiplied), say(kHomogeneousCoordinates), a});
      out.push_back({say(kWLeftAt1), say(kLastCoordinateIsW), say(kHomogeneousCoordinates), b});
    }
    if (g.candidate && exact_sign(g.candidate->back() - 1) != 0 &&
        exact_sign(g.candidate->back() + 1) != 0) {
      const Exact& w = g.candidate->back();
      std::vector<Exact> times, dropped;
      for (std::size_t i = 0; i < dim; ++i) {
        times.push_back(canonical((*g.candidate)[i] * w));
        dropped.push_back((*g.candidate)[i]);
      }
      Answers a, b;
      a.set("cartesian", Value::vector(times));
      a.set("same_point", Value::boolean(same_point(g.point, times)));
      b.set("cartesian", Value::vector(dropped));
      b.set("same_point", Value::boolean(same_point(g.point, dropped)));
      out.push_back({say(kMultipliedByW), say(kDivideByW), say(kBackToThePoint), a});
      out.push_back({say(kWDropped), say(kDroppingWOnlyWhenOne), say(kBackToThePoint), b});
    }
    return out;
  }

  // Error carried forward: whether the student's own point is the given one.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    if (const auto p = carried(student, "cartesian", g.point.size()))
      out.set("same_point", Value::boolean(same_point(g.point, *p)));
    return out;
  }

  static bool same_point(const std::vector<Exact>& a, const std::vector<Exact>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (exact_sign(a[i] - b[i]) != 0) return false;
    return true;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const std::size_t dim = g.point.size();
    Answers out;
    if (g.w) {
      std::vector<Exact> h;
      MathText substituted = math("(");
      for (std::size_t i = 0; i < dim; ++i) {
        h.push_back(canonical(*g.w * g.point[i]));
        substituted += math(i ? ", " : "") + exact(*g.w) + tex("\\cdot") + exact(g.point[i]);
      }
      h.push_back(*g.w);
      substituted += math(", ") + exact(*g.w) + math(")");
      if (steps)
        steps
            ->add(say(kHomogeneousCoordinates),
                  coordinates(dim, false, false) + tex(" \\equiv ") + scaled_names(dim) +
                      tex(",\\ w \\neq 0"),
                  substituted, vec(h))
            .yields("homogeneous");
      out.set("homogeneous", Value::vector(h));
    }
    if (g.candidate) {
      const std::vector<Exact>& c = *g.candidate;
      const Exact& w = c.back();
      std::vector<Exact> p;
      MathText substituted = math("(");
      for (std::size_t i = 0; i < dim; ++i) {
        p.push_back(canonical(c[i] / w));
        // W in brackets when it is negative or not a whole number: 10/(−2), 5/(1/2).
        const bool bracket = exact_sign(w) < 0 || needs_approx(w);
        substituted += math(i ? ", " : "") + exact(c[i]) + math(bracket ? "/(" : "/") + exact(w) +
                       math(bracket ? ")" : "");
      }
      substituted += math(")");
      std::string latex = "\\left(";
      static constexpr const char* kUpper[] = {"X", "Y", "Z"};
      for (std::size_t i = 0; i < dim; ++i)
        latex += fmt::format("{}\\frac{{{}}}{{W}}", i ? ", " : "", kUpper[i]);
      const bool same = same_point(g.point, p);
      if (steps) {
        steps
            ->add(say(kBackToThePoint),
                  coordinates(dim, true, true) + tex(" \\mapsto " + latex + "\\right)"),
                  substituted, vec(p, true))
            .yields("cartesian");
        Step& step =
            steps
                ->add(say(kTheSamePoint),
                      word(kEqualQuotients) + tex(" \\Leftrightarrow ") + word(kTheSamePointWord),
                      vec(p) + tex(same ? " = " : " \\neq ") + vec(g.point),
                      word(same ? words::kYes : words::kNo))
                .yields("same_point");
        if (!same) {
          std::vector<Exact> scaled;
          for (const Exact& x : g.point) scaled.push_back(canonical(w * x));
          scaled.push_back(w);
          step.note =
              say(kWrittenWithW, exact(w).unicode, vec(g.point).unicode, vec(scaled).unicode);
        }
      }
      out.set("cartesian", Value::vector(p));
      out.set("same_point", Value::boolean(same));
    }
    return out;
  }

  // Default generator: a small integer point, a weight of 2–4 (or a fraction when not nice), and
  // a candidate that is the point (half of the draws) or a near miss of it (one coordinate off by
  // one before scaling: the slip the exercise is about).
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const std::size_t dim = rng.integer(0, 2) == 0 ? 3 : 2;
    std::vector<std::int64_t> point;
    for (std::size_t i = 0; i < dim; ++i) point.push_back(rng.integer(-9, 9));
    YAML::Node g;
    g["point"] = gen_list(point);
    const std::int64_t w = rng.integer(2, 4) * (rng.integer(0, 3) == 0 ? -1 : 1);
    g["w"] = o.nice || rng.integer(0, 1) == 0 ? gen_number(w) : gen_fraction(1, std::abs(w));
    std::vector<std::int64_t> candidate;
    const std::int64_t cw = rng.integer(2, 5);
    const bool same = rng.integer(0, 1) == 0;
    const std::size_t off =
        static_cast<std::size_t>(rng.integer(0, static_cast<std::int64_t>(dim) - 1));
    for (std::size_t i = 0; i < dim; ++i)
      candidate.push_back(cw * point[i] + (!same && i == off ? 1 : 0));
    candidate.push_back(cw);
    g["candidate"] = gen_list(candidate);
    return g;
  }
};

}  // namespace

KindInfo homogeneous_kind() {
  KindInfo k = make_kind<Homogeneous>();
  k.order = 55;
  k.doc_given =
      "`point` (2 or 3 coordinates), `w` (the weight, not 0) and/or `candidate` (a homogeneous "
      "tuple, its last number W not 0)";
  k.doc_answers =
      "`homogeneous` (w·point, w), `cartesian` (the candidate's point), `same_point` (yes/no)";
  return k;
}

}  // namespace frustum
