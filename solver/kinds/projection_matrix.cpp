// The matrix of perspective(), frustum() or ortho() in the set's conventions (seeds 000, 004).
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/viewing_parts.hpp"

namespace frustum {

namespace {

struct ProjectionMatrix {
  static constexpr const char* kName = "projection_matrix";
  static constexpr Phrase kSummary{"the matrix of perspective(), frustum() or ortho()",
                                   "perspective(), frustum() または ortho() の行列",
                                   "матрица perspective(), frustum() или ortho()"};
  struct Given {
    ProjectionSpec projection;
    Api api;
  };
  static std::vector<std::string> given_fields() { return {"perspective", "frustum", "ortho"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "matrix", .kind = AnswerKind::Transform, .label = say(words::kMatrix)}};
  }
  static Given parse(GivenReader& r, const Conventions& c) {
    return {read_projection(r, c), c.api};
  }
  static Answers solve(const Given& g, Derivation* steps) {
    Answers out;
    out.set("matrix",
            matrix_value(paper_form(projection_with_steps(g.projection, g.api, steps), g.api)));
    return out;
  }
  static std::vector<Misconception> misconceptions(const Given& g) {
    std::vector<Misconception> out;
    for (const ProjectionMistake& m : projection_mistakes(g.projection)) {
      try {
        Given changed = g;
        changed.projection = m.projection;
        const bool ortho = g.projection.type == ProjectionSpec::Type::Ortho;
        out.push_back({m.name, m.feedback,
                       m.step.empty() ? say(ortho ? kOrthographicProjectionMatrix
                                                  : kPerspectiveProjectionMatrix)
                                      : Said(m.step),
                       solve(changed, nullptr)});
      } catch (const std::exception&) {
        // A mistake that leads to no volume (near = far) cannot be matched.
      }
    }
    return out;
  }

  // Default generator: perspective (fovy, aspect, near, far), frustum or ortho with integer
  // bounds; nice: fovy 90° or 60°; hard: a tiny near plane (1/100) against a far one of 1000.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    YAML::Node g, p;
    const auto which = rng.below(3);
    const std::int64_t near = rng.integer(1, 4);
    const YAML::Node n = o.hard ? gen_fraction(1, 100) : gen_number(near);
    const YAML::Node f = o.hard ? gen_number(1000) : gen_number(near + rng.integer(2, 60));
    if (which == 0) {
      p["fovy"] = gen_angle(rng.pick(o.nice ? std::vector<std::int64_t>{60, 90}
                                            : std::vector<std::int64_t>{30, 45, 60, 90, 120}),
                            o.conventions);
      p["aspect"] = rng.pick(std::vector<YAML::Node>{gen_number(1), gen_fraction(4, 3),
                                                     gen_fraction(16, 9), gen_number(2)});
      p["near"] = n;
      p["far"] = f;
      g["perspective"] = p;
      return g;
    }
    const std::int64_t half = rng.integer(1, 4);
    p["left"] = gen_number(rng.chance(1, 2) ? -half : -rng.integer(1, 4));
    p["right"] = gen_number(half);
    p["bottom"] = gen_number(-rng.integer(1, 3));
    p["top"] = gen_number(rng.integer(1, 3));
    p["near"] = n;
    p["far"] = f;
    g[which == 1 ? "frustum" : "ortho"] = p;
    return g;
  }
};

}  // namespace

KindInfo projection_matrix_kind() {
  KindInfo k = make_kind<ProjectionMatrix>();
  k.order = 80;
  k.doc_given =
      "`perspective` {`fovy`, `aspect`, `near`, `far`}, `frustum` or `ortho` {`left`, `right`, "
      "`bottom`, `top`, `near`, `far`}";
  k.doc_answers = "`matrix`";
  return k;
}

}  // namespace frustum
