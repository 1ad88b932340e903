// The viewport transform: NDC to window coordinates and depth in [0, 1] (seed 000 9.6).
#include <fmt/format.h>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/accuracy_draws.hpp"
#include "solver/shared/numeric_path_common.hpp"
#include "solver/shared/viewing_parts.hpp"

namespace frustum {

namespace {

std::unique_ptr<NumericSolver> viewport_numeric(const Vec3<Exact>& ndc, const Exact& width,
                                                const Exact& height, Api api, Precision p) {
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Vec3<T> ndc;
      T width, height;
      Api api;
    };
    auto core = [](const In& in) { return viewport(in.ndc, in.width, in.height, in.api); };
    auto report = [p](const In&, const Vec3<T>& w) {
      NumericOut<T> out(p);
      out.vector("window", w);
      return out.take();
    };
    return prepare(In{conv<T>(ndc), from_exact<T>(width), from_exact<T>(height), api}, core,
                   report);
  });
}

struct Viewport {
  static constexpr const char* kName = "viewport";
  static constexpr Phrase kSummary{"NDC to window coordinates", "NDC からウィンドウ座標へ",
                                   "из NDC в оконные координаты"};
  static constexpr ConventionUse kUses{.api = true, .angles = false};
  struct Given {
    Vec3<Exact> ndc;
    Exact width, height;
    Api api;
  };
  static std::vector<std::string> given_fields() { return {"ndc", "width", "height"}; }
  static std::vector<AnswerSpec> answers() {
    return {
        {.name = "window", .kind = AnswerKind::Vector, .label = say(words::kWindowCoordinates)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g{r.vector<3>("ndc"), r.number("width"), r.number("height"), c.api};
    if (exact_sign(g.width) <= 0) r.fail("width", "must be positive");
    if (exact_sign(g.height) <= 0) r.fail("height", "must be positive");
    return g;
  }

  static AnswerScales scales(const Given& g, const Answers&) {
    return {{"window", window_scale(g.width, g.height)}};
  }

  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    return viewport_numeric(g.ndc, g.width, g.height, g.api, p);
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const Vec3<Exact> w = viewport(g.ndc, g.width, g.height, g.api);
    const Vec3<Exact> window(canonical(w(0)), canonical(w(1)), canonical(w(2)));
    Answers out;
    out.set("window", Value::vector(window));
    viewport_step(steps, g.api, g.width, g.height, window, &g.ndc);
    return out;
  }
  // Default generator: NDC in quarters of [−1, 1] (nice: halves; hard: on the cube's faces or
  // just outside, ±5/4) and a common screen size.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const auto [w, h] = rng.pick(std::vector<std::pair<std::int64_t, std::int64_t>>{
        {200, 200}, {400, 300}, {640, 480}, {800, 600}});
    std::vector<Exact> ndc;
    for (int i = 0; i < 3; ++i)
      ndc.push_back(
          o.hard   ? Exact(GiNaC::numeric(rng.pick(std::vector<std::int64_t>{-5, -4, 4, 5}), 4))
          : o.nice ? Exact(GiNaC::numeric(rng.integer(-2, 2), 2))
                   : Exact(GiNaC::numeric(rng.integer(-4, 4), 4)));
    YAML::Node g;
    g["ndc"] = gen_list(ndc);
    g["width"] = gen_number(w);
    g["height"] = gen_number(h);
    return g;
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given).
std::optional<std::string> accuracy_given(Rng& rng) {
  using accuracy::decimal;
  return fmt::format("{{ndc: [{}, {}, {}], width: {}, height: {}}}", decimal(rng, -1, 1),
                     decimal(rng, -1, 1), decimal(rng, -1, 1), rng.integer(100, 1920),
                     rng.integer(100, 1080));
}

}  // namespace

KindInfo viewport_kind() {
  KindInfo k = make_kind<Viewport>();
  k.order = 120;
  k.doc_given = "`ndc`, `width`, `height`";
  k.doc_answers = "`window`";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
