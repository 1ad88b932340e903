// The viewport transform: NDC to window coordinates and depth in [0, 1] (seed 000 9.6).
#include "solver/kinds/given_reader.hpp"
#include "solver/kinds/registry.hpp"
#include "solver/kinds/viewing_steps.hpp"

namespace frustum {

namespace {

struct Viewport {
  static constexpr const char* kName = "viewport";
  static constexpr const char* kSummary = "NDC to window coordinates";
  struct Given {
    Vec3<Exact> ndc;
    Exact width, height;
    Api api;
  };
  static std::vector<std::string> given_fields() { return {"ndc", "width", "height"}; }
  static std::vector<AnswerSpec> answers() { return {{"window", AnswerKind::Vector, {}, {}}}; }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g{r.vector<3>("ndc"), r.number("width"), r.number("height"), c.api};
    if (exact_sign(g.width) <= 0) r.fail("width", "must be positive");
    if (exact_sign(g.height) <= 0) r.fail("height", "must be positive");
    return g;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const Vec3<Exact> w = viewport(g.ndc, g.width, g.height, g.api);
    const Vec3<Exact> window(canonical(w(0)), canonical(w(1)), canonical(w(2)));
    Answers out;
    out.set("window", Value::vector(window));
    if (steps) {
      const std::string y_rule = g.api == Api::DirectX ? "y_w = (1 − y)/2·height" : "y_w = (y + 1)/2·height";
      steps->add("Viewport", math("x_w = (x + 1)/2·width,  " + y_rule + (g.api == Api::DirectX ? ",  depth = z" : ",  depth = (z + 1)/2")),
                 math("ndc = ") + vec(g.ndc) + math(", width = ") + exact(g.width) + math(", height = ") + exact(g.height),
                 math("(x_w, y_w, depth) = ") + vec(window, true))
          .note = g.api == Api::OpenGL ? "OpenGL's window origin is bottom-left."
                  : g.api == Api::DirectX ? "DirectX's window origin is top-left, y down; NDC z is already in [0, 1]."
                                          : "Processing's window origin is top-left with y down; its projection matrix "
                                            "already negated y, so the viewport does not flip it again.";
      steps->yields("window");
    }
    return out;
  }
};

}  // namespace

KindInfo viewport_kind() { return make_kind<Viewport>(); }

}  // namespace frustum
