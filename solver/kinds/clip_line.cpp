// Cohen–Sutherland line clipping (seed 000: コーエン・サザランド法, 6-bit codes in 3D) of the
// segment pq against a 2D `window` or a 3D `volume` (default: the NDC cube [−1, 1]³).
// Outcodes are written most significant bit first: 2D 1000 top (y > ymax), 0100 bottom
// (y < ymin), 0010 right (x > xmax), 0001 left (x < xmin); 3D adds 100000 (z > zmax) and
// 010000 (z < zmin) in front. A point on a boundary is inside.
#include "solver/clipping/line_clip.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/clip_given.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kOutcodeP{"outcode_p", "p の領域コード", "код области p"};
constexpr Phrase kOutcodeQ{"outcode_q", "q の領域コード", "код области q"};
constexpr Phrase kAccept{"accept", "採択", "принятие"};
constexpr Phrase kReject{"reject", "棄却", "отбрасывание"};

constexpr Phrase kBitCodes2D{
    "{0}-bit codes, most significant first: 1000 top (y > ymax), 0100 bottom (y < ymin), 0010 "
    "right (x > xmax), 0001 left (x < xmin).",
    "{0} ビットのコード (上位ビットから): 1000 上 (y > ymax), 0100 下 (y < ymin), 0010 右 (x > "
    "xmax), 0001 左 (x < xmin).",
    "{0}-битные коды, старший бит первым: 1000 сверху (y > ymax), 0100 снизу (y < ymin), 0010 "
    "справа (x > xmax), 0001 слева (x < xmin)."};
constexpr Phrase kBitCodes3D{
    "{0}-bit codes (the 2D codes with two bits for z added), most significant first: 100000 z > "
    "zmax, 010000 z < zmin, 001000 top (y > ymax), 000100 bottom (y < ymin), 000010 right "
    "(x > xmax), 000001 left (x < xmin).",
    "{0} ビットのコード (2 次元のコードに z の 2 ビットを加えたもの, 上位ビットから): 100000 z > "
    "zmax, 010000 z < zmin, 001000 上 (y > ymax), 000100 下 (y < ymin), 000010 右 (x > xmax), "
    "000001 左 (x < xmin).",
    "{0}-битные коды (двумерные коды плюс два бита для z), старший бит первым: 100000 z > zmax, "
    "010000 z < zmin, 001000 сверху (y > ymax), 000100 снизу (y < ymin), 000010 справа "
    "(x > xmax), 000001 слева (x < xmin)."};
constexpr Phrase kPointOnBoundaryInside{"A point on a boundary is inside (bit 0).",
                                        "境界上の点は内側とする (ビット 0).",
                                        "Точка на границе считается внутренней (бит 0)."};
constexpr Phrase kTop{"top (y > ymax)", "上 (y > ymax)", "сверху (y > ymax)"};
constexpr Phrase kBottom{"bottom (y < ymin)", "下 (y < ymin)", "снизу (y < ymin)"};
constexpr Phrase kRight{"right (x > xmax)", "右 (x > xmax)", "справа (x > xmax)"};
constexpr Phrase kLeft{"left (x < xmin)", "左 (x < xmin)", "слева (x < xmin)"};
constexpr Phrase kOutcodeOfP{"Outcode of p", "p のアウトコード", "Код области точки p"};
constexpr Phrase kOutcodeOfQ{"Outcode of q", "q のアウトコード", "Код области точки q"};
constexpr Phrase kTrivialAccept{"Trivial accept? (both codes 0)", "自明な採用? (両方のコードが 0)",
                                "Тривиальное принятие? (оба кода 0)"};
constexpr Phrase kTrivialReject{"Trivial reject? (a common outside bit)",
                                "自明な棄却? (共通の外側ビット)",
                                "Тривиальное отбрасывание? (общий бит «снаружи»)"};
constexpr Phrase kYesWholeSegmentInside{"yes: the whole segment is inside", "はい: 線分全体が内側",
                                        "да: весь отрезок внутри"};
constexpr Phrase kYesBothOutsideSameBoundary{"yes: both endpoints are outside the same boundary",
                                             "はい: 両端点が同じ境界の外側にある",
                                             "да: оба конца вне одной и той же границы"};
constexpr Phrase kIteration{
    "Iteration {0}: {1} ({2}) is outside {3} (bit {4}): move it to {5}",
    "反復 {0}: {1} ({2}) は {3} の外側 (ビット {4}): {5} へ移す",
    "Итерация {0}: {1} ({2}) вне границы {3} (бит {4}): переносим её на {5}"};
constexpr Phrase kFractionOfTheWay{
    "t is the fraction of the way from {0} to {1} at which the segment crosses {2}.",
    "t は, 線分が {2} と交わる点が {0} から {1} へ向かう道のりのどれだけの割合にあるかを表す.",
    "t — доля пути от {0} к {1}, на которой отрезок пересекает {2}."};
constexpr Phrase kClippedSegment{"Clipped segment", "クリップ後の線分", "Отсечённый отрезок"};
constexpr Phrase kTriviallyAccepted{"Trivially accepted: the segment is unchanged.",
                                    "自明な採用: 線分はそのまま残る.",
                                    "Тривиально принят: отрезок не меняется."};
constexpr Phrase kBothCodesNow{"Both codes are now {0}: accept.",
                               "両方のコードが {0} になった: 採用.",
                               "Оба кода теперь {0}: принимаем."};
constexpr Phrase kNothingIsVisible{"Nothing is visible", "何も見えない", "Ничего не видно"};
constexpr Phrase kTriviallyRejected{"Trivially rejected: the segment lies outside one boundary.",
                                    "自明な棄却: 線分は一つの境界の外側にある.",
                                    "Тривиально отброшен: отрезок лежит вне одной из границ."};
constexpr Phrase kMissesAfterClipping{
    "After clipping, both endpoints share an outside bit: the segment misses the region.",
    "クリッピング後, 両端点が共通の外側ビットを持つ: 線分は領域を通らない.",
    "После отсечения оба конца имеют общий внешний бит: отрезок не проходит через область."};

// What one outside bit means (line_clip.cpp's outcode_bit_meaning).
Said bit_meaning(unsigned bit) {
  switch (bit) {
    case outcode_bit(0, false):
      return say(kLeft);
    case outcode_bit(0, true):
      return say(kRight);
    case outcode_bit(1, false):
      return say(kBottom);
    case outcode_bit(1, true):
      return say(kTop);
    case outcode_bit(2, false):
      return Said::verbatim("z < zmin");
    case outcode_bit(2, true):
      return Said::verbatim("z > zmax");
    default:
      return Said::verbatim("?");
  }
}

// What a code's set bits mean, most significant first, or inside (line_clip.cpp's
// outcode_meaning): "left (x < xmin), top (y > ymax)".
Said code_meaning(unsigned code) {
  if (code == 0) return say(words::kInside);
  Said s;
  for (int b = 5; b >= 0; --b)
    if (code & (1u << b)) {
      if (!s.empty()) s.append(Said::verbatim(", "));
      s.append(bit_meaning(1u << b));
    }
  return s;
}

struct ClipLine {
  static constexpr const char* kName = "clip_line";
  static constexpr Phrase kSummary{
      "Cohen–Sutherland outcodes and clipping of a segment (2D or 3D)",
      "Cohen–Sutherland のアルゴリズムによる線分の領域コードとクリッピング (2次元または3次元)",
      "коды областей Коэна — Сазерленда (Cohen–Sutherland) и отсечение отрезка (2D или 3D)"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  struct Given {
    std::vector<Exact> p, q;
    clip_given::Region region;
  };
  static std::vector<std::string> given_fields() { return {"p", "q", "window", "volume"}; }
  // Error carried forward: trivial accept (both outcodes 0) and trivial reject (a bit set in
  // both) from the student's own outcodes, read with their leading zeros restored.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    const Answers key = solve(g, nullptr);
    const auto code = [&](const std::string& name) -> std::optional<std::string> {
      const Value* v = student.find(name);
      const Value* k = key.find(name);
      if (!v || !k || v->word.size() > k->word.size() ||
          v->word.find_first_not_of("01") != std::string::npos)
        return std::nullopt;
      return std::string(k->word.size() - v->word.size(), '0') + v->word;
    };
    const auto cp = code("outcode_p"), cq = code("outcode_q");
    if (!cp && !cq) return out;
    const std::string p = cp ? *cp : key.find("outcode_p")->word;
    const std::string q = cq ? *cq : key.find("outcode_q")->word;
    bool shared = false;
    for (std::size_t i = 0; i < std::min(p.size(), q.size()); ++i)
      shared = shared || (p[i] == '1' && q[i] == '1');
    out.set("accept",
            Value::boolean(p.find('1') == std::string::npos && q.find('1') == std::string::npos));
    out.set("reject", Value::boolean(shared));
    return out;
  }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "outcode_p", .kind = AnswerKind::BitString, .label = say(kOutcodeP)},
            {.name = "outcode_q", .kind = AnswerKind::BitString, .label = say(kOutcodeQ)},
            {.name = "accept",
             .kind = AnswerKind::Bool,
             .depends_on = {"outcode_p", "outcode_q"},
             .label = say(kAccept)},
            {.name = "reject",
             .kind = AnswerKind::Bool,
             .depends_on = {"outcode_p", "outcode_q"},
             .label = say(kReject)},
            {.name = "clipped",
             .kind = AnswerKind::Segment,
             .depends_on = {"outcode_p", "outcode_q"},
             .label = say(words::kClippingResult)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    const int dims = clip_given::point_dims(r, "p");
    g.p = r.numbers("p", static_cast<std::size_t>(dims));
    if (clip_given::point_dims(r, "q") != dims)
      r.fail("q", "expected " + std::to_string(dims) + " numbers like p");
    g.q = r.numbers("q", static_cast<std::size_t>(dims));
    g.region = clip_given::read_region(r, dims, "points p and q", c.api);
    return g;
  }

  static Said bits_legend(int dims) {
    return (dims == 3 ? say(kBitCodes3D, 6) : say(kBitCodes2D, 4)) + say(kPointOnBoundaryInside);
  }

  template <int N>
  static Answers solve_in(const Given& g, const ClipBox<Exact, N>& box, Derivation* steps) {
    using V = Eigen::Matrix<Exact, N, 1>;
    const V p = Eigen::Map<const V>(g.p.data());
    const V q = Eigen::Map<const V>(g.q.data());
    const LineClipResult<Exact, N> r = cohen_sutherland(p, q, box);
    Answers out;
    const std::string cp = outcode_string(r.code_p, N), cq = outcode_string(r.code_q, N);
    out.set("outcode_p", Value::category(cp));
    out.set("outcode_q", Value::category(cq));
    out.set("accept", Value::boolean(r.trivial_accept));
    out.set("reject", Value::boolean(r.trivial_reject));
    if (steps) {
      steps->add(g.region.title(), {}, {}, clip_given::box_text(box)).note = bits_legend(N);
      const auto code = [](unsigned c) {
        const std::string bits = outcode_string(c, N);
        return tex("\\mathtt{" + bits + "}");
      };
      const auto outcode_of = [&](const std::string& who, bool moved = false) {
        return tex("\\operatorname{outcode}(" + who + (moved ? "')" : ")"));
      };
      const MathText op_or = tex(" \\mathbin{\\mathrm{OR}} "),
                     op_and = tex(" \\mathbin{\\mathrm{AND}} ");
      steps
          ->add(say(kOutcodeOfP), {}, math("p = ") + vec(g.p),
                outcode_of("p") + math(" = ") + code(r.code_p))
          .yields("outcode_p")
          .note = code_meaning(r.code_p);
      steps
          ->add(say(kOutcodeOfQ), {}, math("q = ") + vec(g.q),
                outcode_of("q") + math(" = ") + code(r.code_q))
          .yields("outcode_q")
          .note = code_meaning(r.code_q);
      steps
          ->add(say(kTrivialAccept),
                outcode_of("p") + op_or + outcode_of("q") + math(" = ") + code(0),
                code(r.code_p) + op_or + code(r.code_q) + math(" = ") + code(r.code_p | r.code_q),
                word(r.trivial_accept ? kYesWholeSegmentInside : words::kNo))
          .yields("accept");
      steps
          ->add(say(kTrivialReject),
                outcode_of("p") + op_and + outcode_of("q") + tex(" \\ne ") + code(0),
                code(r.code_p) + op_and + code(r.code_q) + math(" = ") + code(r.code_p & r.code_q),
                word(r.trivial_reject ? kYesBothOutsideSameBoundary : words::kNo))
          .yields("reject");
      // The endpoints as the loop moves them: t is measured from the endpoint being moved (a)
      // towards the other one (b).
      std::array<V, 2> ends = {p, q};
      int n = 0;
      for (const auto& it : r.iterations) {
        int axis = 0;
        while (outcode_bit(axis, false) != it.bit && outcode_bit(axis, true) != it.bit) ++axis;
        const bool high = it.bit == outcode_bit(axis, true);
        const std::string x = axis_name(axis);
        const std::string bound_name = x + (high ? "max" : "min");
        const MathText bound = tex(x + "_{\\" + (high ? "max" : "min") + "}");
        const std::string who = it.endpoint == 0 ? "p" : "q", other = it.endpoint == 0 ? "q" : "p";
        const V& a = ends[static_cast<std::size_t>(it.endpoint)];
        const V& b = ends[static_cast<std::size_t>(1 - it.endpoint)];
        const Exact bound_value = high ? box.hi(axis) : box.lo(axis);
        const Exact t = canonical((bound_value - a(axis)) / (b(axis) - a(axis)));
        steps
            ->add(say(kIteration, ++n, who, outcode_string(it.code_before, N), bound_name,
                      outcode_string(it.bit, N), x + " = " + bound_name),
                  tex("t = ") +
                      frac(bound + tex(" - " + who + "_" + x),
                           tex(other + "_" + x + " - " + who + "_" + x)) +
                      tex(",\\; " + who + "' = " + who + " + t\\,(" + other + " - " + who + ")"),
                  math(who + " = ") + vec(a) + tex(",\\; " + other + " = ") + vec(b) +
                      tex(",\\; ") + bound + math(" = ") + exact(bound_value) + tex(",\\; t = ") +
                      exact(t, true),
                  tex(who + "' = ") + vec(it.after, true) + tex(",\\; ") + outcode_of(who, true) +
                      math(" = ") + code(it.code_after))
            .note = say(kFractionOfTheWay, who, other, x + " = " + bound_name);
        ends[static_cast<std::size_t>(it.endpoint)] = it.after;
      }
    }
    if (r.clipped) {
      std::vector<std::vector<Exact>> rows;
      for (const V& e : *r.clipped) rows.emplace_back(e.data(), e.data() + N);
      out.set("clipped", Value::matrix(rows));
      if (steps)
        steps
            ->add(say(kClippedSegment), {}, {},
                  tex("p' = ") + vec((*r.clipped)[0], true) + tex(",\\; q' = ") +
                      vec((*r.clipped)[1], true))
            .yields("clipped")
            .note =
            r.trivial_accept ? say(kTriviallyAccepted) : say(kBothCodesNow, outcode_string(0, N));
    } else {
      out.set("clipped", Value::null());
      if (steps)
        steps->add(say(kNothingIsVisible)).yields("clipped").note =
            say(r.trivial_reject ? kTriviallyRejected : kMissesAfterClipping);
    }
    return out;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    return g.region.dims == 2 ? solve_in<2>(g, g.region.window, steps)
                              : solve_in<3>(g, g.region.volume, steps);
  }
  // Default generator: three times in four a 2D segment with integer ends around an integer
  // window, else a 3D segment (halves) against the NDC cube; hard: a segment along the
  // window's edge or through its corner.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    YAML::Node g;
    if (!o.hard && rng.chance(1, 4)) {
      std::vector<Exact> p, q;
      for (int i = 0; i < 3; ++i) {
        p.push_back(Exact(GiNaC::numeric(rng.integer(-4, 4), 2)));
        q.push_back(Exact(GiNaC::numeric(rng.integer(-4, 4), 2)));
      }
      g["p"] = gen_list(p);
      g["q"] = gen_list(q);
      return g;
    }
    const std::int64_t xmin = rng.integer(0, 2), xmax = xmin + rng.integer(3, 6);
    const std::int64_t ymin = rng.integer(0, 2), ymax = ymin + rng.integer(3, 6);
    std::vector<std::int64_t> p, q;
    if (o.hard && rng.chance(1, 2)) {  // along the left edge, sticking out
      p = {xmin, ymin - rng.integer(0, 2)};
      q = {xmin, ymax + rng.integer(1, 2)};
    } else if (o.hard) {  // through the top-right corner
      const std::int64_t k = rng.integer(1, 2);
      p = {xmax - k, ymax - k};
      q = {xmax + k, ymax + k};
    } else {
      p = {rng.integer(xmin - 4, xmax + 4), rng.integer(ymin - 4, ymax + 4)};
      q = {rng.integer(xmin - 4, xmax + 4), rng.integer(ymin - 4, ymax + 4)};
    }
    g["p"] = gen_list(p);
    g["q"] = gen_list(q);
    g["window"] = gen_window(xmin, xmax, ymin, ymax);
    return g;
  }

  static std::string ill_conditioned(const Given& g) {
    for (std::size_t i = 0; i < g.p.size(); ++i)
      if (!canonical(g.p[i] - g.q[i]).is_zero()) return "";
    return "p and q coincide";
  }
};

}  // namespace

KindInfo clip_line_kind() {
  KindInfo k = make_kind<ClipLine>();
  k.order = 130;
  k.doc_given =
      "`p`, `q`, `window` {xmin, xmax, ymin, ymax} (2D) or `volume` (3D, default the NDC cube)";
  k.doc_answers = "`outcode_p`, `outcode_q`, `accept`, `reject`, `clipped`";
  return k;
}

}  // namespace frustum
