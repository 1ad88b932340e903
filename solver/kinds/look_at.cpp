// The view matrix of gluLookAt / Processing's camera() (seed 000: camera(eye, center, up)),
// or DirectX's LookAtLH: rows are the camera's axes, the last column moves the eye to the
// origin.
#include "solver/kinds/given_reader.hpp"
#include "solver/kinds/kind_steps.hpp"
#include "solver/kinds/registry.hpp"
#include "solver/kinds/viewing_steps.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

struct LookAt {
  static constexpr const char* kName = "look_at";
  static constexpr const char* kSummary = "the view matrix of a camera at eye looking at center";
  struct Given {
    Vec3<Exact> eye, center, up;
    std::vector<Vec3<Exact>> points;
    Api api;
  };
  static std::vector<std::string> given_fields() { return {"eye", "center", "up", "points"}; }
  static std::vector<AnswerSpec> answers() {
    return {{"matrix", AnswerKind::Matrix, {}, {}}, {"points", AnswerKind::Matrix, {"matrix"}, {}}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g{r.vector<3>("eye"), r.vector<3>("center"), r.vector<3>("up"), {}, c.api};
    if (r.has("points")) g.points = r.points("points", 1);
    return g;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const MatX<Exact> m = look_at_with_steps(g.eye, g.center, g.up, g.api, "", steps);
    Answers out;
    out.set("matrix", matrix_value(paper_form(m, g.api)));
    if (steps) steps->yields("matrix");
    std::vector<std::vector<Exact>> points;
    for (const Vec3<Exact>& p : g.points) points.push_back({p(0), p(1), p(2)});
    out.set("points", transform_points_with_steps(m, points, "A point in view coordinates", "p", steps));
    return out;
  }
};

}  // namespace

KindInfo look_at_kind() { return make_kind<LookAt>(); }

}  // namespace frustum
