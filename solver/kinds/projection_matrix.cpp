// The matrix of perspective(), frustum() or ortho() in the set's conventions (seeds 000, 004).
#include "solver/kinds/given_reader.hpp"
#include "solver/kinds/registry.hpp"
#include "solver/kinds/viewing_steps.hpp"

namespace frustum {

namespace {

struct ProjectionMatrix {
  static constexpr const char* kName = "projection_matrix";
  static constexpr const char* kSummary = "the matrix of perspective(), frustum() or ortho()";
  struct Given {
    ProjectionSpec projection;
    Api api;
  };
  static std::vector<std::string> given_fields() { return {"perspective", "frustum", "ortho"}; }
  static std::vector<AnswerSpec> answers() { return {{"matrix", AnswerKind::Matrix, {}, {}}}; }
  static Given parse(GivenReader& r, const Conventions& c) { return {read_projection(r, c), c.api}; }
  static Answers solve(const Given& g, Derivation* steps) {
    Answers out;
    out.set("matrix", matrix_value(paper_form(projection_with_steps(g.projection, g.api, steps), g.api)));
    return out;
  }
};

}  // namespace

KindInfo projection_matrix_kind() { return make_kind<ProjectionMatrix>(); }

}  // namespace frustum
