#include "solver/problem/variants.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <numeric>
#include <optional>

#include "solver/input/given_reader.hpp"
#include "solver/input/text_reader.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/text_literals.hpp"
#include "solver/problem/vary_spec.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

namespace {

constexpr char kUnitSeparator = '\x1f';
constexpr const char* kSeedPrefix = "frustum-variant/1";

// Simple exact numbers (see not_nice).
constexpr long kNiceDenominator = 100;
constexpr long kNiceSquareDenominator = 10000;
constexpr long kNicePiDenominator = 12;

bool small_rational(const Exact& e, long max_denominator) {
  if (!GiNaC::is_a<GiNaC::numeric>(e)) return false;
  const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(e);
  return n.is_rational() && n.denom() <= GiNaC::numeric(max_denominator);
}

bool simple_number(const Exact& e) {
  if (small_rational(e, kNiceDenominator)) return true;
  if (small_rational(canonical(e * e), kNiceSquareDenominator)) return true;
  return small_rational(canonical(e / GiNaC::Pi), kNicePiDenominator);
}

}  // namespace

namespace {

// A default-constructed YAML::Node is defined (and null): `vary` is present when it is neither.
bool has_vary(const ProblemSpec& p) { return p.vary.IsDefined() && !p.vary.IsNull(); }

// A kind with nothing to draw (the instructor's own statements): every variant keeps it as written.
bool is_fixed(const ProblemSpec& p) { return p.info && p.info->fixed; }

// Whether variants draw this problem anew (vary_all: every problem that can be drawn).
bool drawn_anew(const ProblemSet& set, const ProblemSpec& p, bool vary_all) {
  return (vary_all && !is_fixed(p)) || problem_varies(set, p);
}

}  // namespace

bool problem_varies(const ProblemSet& set, const ProblemSpec& p) {
  return !is_fixed(p) && (has_vary(p) || set.per_student);
}

bool set_varies(const ProblemSet& set) {
  for (const ProblemSpec& p : set.problems)
    if (problem_varies(set, p)) return true;
  return false;
}

std::string set_key(const ProblemSet& set) {
  if (!set.title.empty()) return set.title.text;
  return std::filesystem::path(set.file).stem().string();
}

std::uint64_t variant_seed(const std::string& key, const std::string& who) {
  std::uint64_t h = fnv1a64(kSeedPrefix);
  h = fnv1a64(std::string(1, kUnitSeparator) + key, h);
  return fnv1a64(std::string(1, kUnitSeparator) + who, h);
}

std::uint64_t problem_seed(std::uint64_t seed, const std::string& problem_id) {
  return fnv1a64(std::string(1, kUnitSeparator) + problem_id, seed);
}

std::string not_nice(const Answers& answers, const std::vector<std::string>& ask) {
  for (const std::string& name : ask) {
    const Value* v = answers.find(name);
    if (!v) continue;
    if (!v->numbers.empty() && v->exact.empty()) continue;  // a floating-point answer (render)
    for (const Exact& e : v->exact)
      if (!simple_number(e))
        return name + " has " + format_exact(e, MathStyle::Plain) + ", not a simple number";
  }
  return "";
}

// An exercise's character, as its asked answers show it: every yes/no answer (a segment
// accepted or not, a pixel inside, a polyhedron convex), which answers are empty (a segment or
// polygon clipped away) and which shapes collapsed (a segment clipped to one point). A variant
// of a written exercise keeps it: a clip that clips stays one that clips.
std::string character(const KindInfo& kind, const Answers& answers,
                      const std::vector<std::string>& ask) {
  std::string out;
  for (const std::string& name : ask) {
    const Value* v = answers.find(name);
    const AnswerSpec* spec = kind.answer(name);
    if (!v || !spec) continue;
    if (v->shape == Value::Shape::Bool) out += name + (v->flag ? "=yes " : "=no ");
    if (v->shape == Value::Shape::Null) out += name + "=none ";
    const bool shape = spec->kind == AnswerKind::Segment || spec->kind == AnswerKind::Polygon;
    if (shape && v->shape == Value::Shape::Matrix && v->rows > 1 && v->cols > 0 &&
        v->numbers.size() == static_cast<std::size_t>(v->rows * v->cols)) {
      bool one_point = true;
      for (int r = 1; r < v->rows; ++r)
        for (int c = 0; c < v->cols; ++c)
          one_point = one_point && v->numbers[r * v->cols + c] == v->numbers[c];
      if (one_point) out += name + "=one point ";
    }
  }
  return out;
}

ProblemSpec draw_problem(const ProblemSpec& base, const std::string& file, std::uint64_t seed,
                         const GivenTexts& avoid, std::string* given_text,
                         std::vector<std::string>* repeated) {
  // yaml-cpp's Node::operator= writes through to every copy of a node (the base set's too):
  // nodes of a copied ProblemSpec are rebound with reset(), and specs are never assigned.
  ProblemSpec spec = base;
  spec.vary.reset();
  spec.vary_plan.reset();
  spec.drawn_answers.reset();
  if (base.error || !base.info) return spec;
  const KindInfo& kind = *base.info;
  const bool use_default = !has_vary(base) || vary_is_default(base.vary);
  const std::string vary_field = base.field + ".vary";
  std::shared_ptr<const VaryPlan> plan = use_default ? nullptr : base.vary_plan;
  try {
    if (!use_default && !plan)
      plan = std::make_shared<const VaryPlan>(base.vary, kind, file, vary_field);
  } catch (const InputError& e) {
    spec.error = e.diagnostic();
    return spec;
  }
  if (use_default && !kind.generate) {
    spec.error =
        Diagnostic{base.where, vary_field, kind.name + " has no default generator: give `vary`"};
    return spec;
  }
  const GenerateOptions options{base.nice, base.hard, base.conventions};
  Rng rng(seed);
  std::string last;
  // A default variant of a written exercise keeps its structure (the same steps, the same kind
  // of givens): the kind's generator is used when it draws that shape, else the given's own
  // values are drawn again. A problem with no given takes whatever the generator draws.
  const bool keep_shape = use_default && base.given_node.IsMap() && base.given_node.size() > 0;
  const std::string shape = keep_shape ? given_shape(base.given_node) : "";
  const auto default_given = [&](int attempt) {
    if (keep_shape && attempt < kMaxDrawAttempts / 2)
      for (int k = 0; k < kShapeTries; ++k)
        if (YAML::Node g = kind.generate(rng, options); given_shape(g) == shape) return g;
    return keep_shape ? redraw_values(base.given_node, rng) : kind.generate(rng, options);
  };
  // The written exercise's character, which a default variant keeps (not a `vary:` plan: its
  // ranges are the instructor's to choose).
  // A written exercise that the kind would call ill-conditioned is about that case (a polygon
  // clipped away, an eye in a face's plane): its variants are not refused for it.
  std::optional<std::string> written;
  bool refuse_ill = !base.hard && kind.ill_conditioned;
  if (keep_shape) {
    try {
      GivenReader reader(base.given_node, file, base.field + ".given", kind.given_fields);
      const std::any parsed = kind.parse(reader, base.conventions);
      const Answers answers = kind.solve(parsed, nullptr);
      written = character(kind, answers, base.ask);
      if (refuse_ill && !kind.ill_conditioned(parsed, answers).empty()) refuse_ill = false;
    } catch (const std::exception&) {  // the written given itself does not solve: no constraint
    }
  }
  for (int attempt = 0; attempt < kMaxDrawAttempts; ++attempt) {
    try {
      YAML::Node given = use_default ? default_given(attempt) : plan->draw(base.given_node, rng);
      const std::string text = emit_flow(given);
      if (avoid.count(text)) {
        if (repeated) repeated->push_back(text);
        last = "the same as another variant";
        continue;
      }
      GivenReader reader(given, file, base.field + ".given", kind.given_fields);
      std::any parsed = kind.parse(reader, base.conventions);
      reader.finish();
      // A check of the given alone refuses before solving: such a draw is refused below too,
      // whatever solving finds, so the same draw is taken. The last attempt is checked in the
      // order below, for the reason it reports.
      if (refuse_ill && kind.ill_conditioned_given_only && attempt + 1 < kMaxDrawAttempts) {
        last = kind.ill_conditioned(parsed, Answers{});
        if (!last.empty()) continue;
      }
      Answers answers = kind.solve(parsed, nullptr);
      // An empty list (no pixel covered) cannot be written as an answer: redrawn even when hard.
      last.clear();
      for (const std::string& name : base.ask)
        if (const Value* v = answers.find(name);
            v && v->shape == Value::Shape::Matrix && v->rows == 0)
          last = name + " is empty";
      if (!last.empty()) continue;
      if (refuse_ill) {
        last = kind.ill_conditioned(parsed, answers);
        if (!last.empty()) continue;
      }
      if (written && character(kind, answers, base.ask) != *written) {
        last = "not an exercise of the written one's kind (" + character(kind, answers, base.ask) +
               "where it has " + (written->empty() ? "none of these" : *written) + ")";
        continue;
      }
      if (base.nice && !base.hard) {  // hard cases are rarely nice: hard wins
        last = not_nice(answers, base.ask);
        if (!last.empty()) continue;
      }
      spec.given = std::move(parsed);
      spec.given_node.reset(given);
      // A given drawn whole (a problem with none: default_problem) asks what it makes sense
      // of, as a written problem's default `ask` does (no `array` where none is given).
      if (!keep_shape)
        std::erase_if(spec.ask, [&](const std::string& name) {
          const AnswerSpec* a = kind.answer(name);
          return a && !a->needs_given.empty() &&
                 !static_cast<const YAML::Node&>(given)[a->needs_given].IsDefined();
        });
      spec.drawn_answers = std::make_shared<const Answers>(std::move(answers));
      if (given_text) *given_text = text;
      return spec;
    } catch (const InputError& e) {
      last = e.diagnostic().field + ": " + e.diagnostic().message;
    } catch (const DomainError& e) {
      last = e.field() + ": " + e.what();
    } catch (const std::exception& e) {
      last = e.what();
    }
  }
  const YAML::Node at = has_vary(base) ? base.vary : base.given_node;
  spec.error =
      Diagnostic{location_of(at, file), vary_field,
                 "no acceptable variant in " + std::to_string(kMaxDrawAttempts) +
                     " draws (the last: " + last + "); widen the ranges or drop nice/difficulty"};
  return spec;
}

ProblemSpec default_problem(const KindInfo& kind, bool nice, bool hard) {
  ProblemSpec s;
  s.id = "p";
  s.kind = kind.name;
  s.info = &kind;
  s.field = "problems[0]";
  for (const AnswerSpec& a : kind.answers) s.ask.push_back(a.name);
  s.nice = nice;
  s.hard = hard;
  return s;
}

namespace {

// The problem's texts, in every language, with the given's literal values turned into the
// placeholders they state; the first literal that cannot be tied is an error at its text.
std::optional<Diagnostic> template_texts(ProblemSpec& p, const std::string& file) {
  if (p.error || p.text.empty()) return std::nullopt;
  std::optional<Diagnostic> error;
  const auto templated = [&](Lang lang, const std::string& text) {
    TemplatedText t = template_literals(text, p.given_node);
    if (t.error && !error) {
      const bool mapping = p.text_node.IsMap();
      const YAML::Node at = local_text_node(p.text_node, lang, p.text.lang);
      error =
          Diagnostic{mapping ? location_of(at, file) : p.where,
                     p.field + ".text" + (mapping ? "." + std::string(to_string(lang)) : ""),
                     "problem " + p.id + " (" + std::string(to_string(lang)) + "): " + *t.error +
                         "; a variant draws new values, and its text would state the old ones"};
    }
    return t.text;
  };
  LocalText out{p.text.lang, templated(p.text.lang, p.text.text), {}};
  for (const auto& [lang, text] : p.text.translations)
    out.translations.emplace(lang, templated(lang, text));
  if (!error) p.text = std::move(out);
  return error;
}

// The set as variants draw it: each problem drawn anew has its texts templated (template_texts),
// or the error of a literal that cannot be tied, and its `vary` read once (VaryPlan).
ProblemSet prepare_for_drawing(const ProblemSet& set, bool vary_all) {
  ProblemSet out = set;
  for (ProblemSpec& p : out.problems) {
    if (!drawn_anew(set, p, vary_all)) continue;
    if (std::optional<Diagnostic> e = template_texts(p, set.file)) p.error = std::move(e);
    // `vary` read once for every variant; a block in error is left to draw_problem to report.
    if (!p.error && p.info && has_vary(p) && !vary_is_default(p.vary)) try {
        p.vary_plan =
            std::make_shared<const VaryPlan>(p.vary, *p.info, set.file, p.field + ".vary");
      } catch (const InputError&) {
      }
  }
  return out;
}

}  // namespace

std::vector<Diagnostic> stale_text_errors(const ProblemSet& set, bool vary_all) {
  std::vector<Diagnostic> out;
  for (const ProblemSpec& base : set.problems) {
    if (!drawn_anew(set, base, vary_all)) continue;
    ProblemSpec p = base;
    if (std::optional<Diagnostic> e = template_texts(p, set.file)) out.push_back(std::move(*e));
  }
  return out;
}

namespace {

// `avoid` (when given) holds, per problem, the givens (emit_flow text) of earlier variants;
// `givens` (when given) receives the variant's own (VariantGivens).
ProblemSet make_variant(const ProblemSet& set, const std::string& who, const std::string& student,
                        bool vary_all, const std::vector<GivenTexts>* avoid,
                        VariantGivens* givens = nullptr) {
  ProblemSet out = set;
  out.per_student = false;
  const std::uint64_t seed = variant_seed(set_key(set), who);
  out.variant = VariantInfo{student, seed};
  out.problems.clear();
  if (givens)
    *givens = {std::vector<std::optional<std::string>>(set.problems.size()),
               std::vector<std::vector<std::string>>(set.problems.size()), true};
  static const GivenTexts kNone;
  for (std::size_t i = 0; i < set.problems.size(); ++i) {
    const ProblemSpec& base = set.problems[i];
    if (!drawn_anew(set, base, vary_all)) {
      out.problems.push_back(base);
      continue;
    }
    std::string text;
    out.problems.push_back(draw_problem(base, set.file, problem_seed(seed, base.id),
                                        avoid ? (*avoid)[i] : kNone, &text,
                                        givens ? &givens->repeated[i] : nullptr));
    if (!givens) continue;
    if (!out.problems.back().error)
      givens->given[i] = std::move(text);
    else if (!base.error)
      givens->complete = false;
  }
  return out;
}

std::string seed_who(std::uint64_t seed, int i) {
  return "seed:" + std::to_string(seed) + ":" + std::to_string(i);
}

}  // namespace

ProblemSet variant_for_student(const ProblemSet& source, const std::string& student,
                               bool vary_all) {
  return make_variant(prepare_for_drawing(source, vary_all), "student:" + student, student,
                      vary_all, nullptr);
}

ClassVariants::ClassVariants(const ProblemSet& set, bool vary_all, bool allow_repeats)
    : set_(prepare_for_drawing(set, vary_all)),
      vary_all_(vary_all),
      allow_repeats_(allow_repeats),
      taken_(set.problems.size()),
      exhausted_(set.problems.size(), false) {}

ProblemSet ClassVariants::first_draw(const std::string& student, VariantGivens* givens) const {
  return make_variant(set_, "student:" + student, student, vary_all_, nullptr, givens);
}

std::vector<std::size_t> ClassVariants::repeated(const VariantGivens& givens) const {
  // An empty text is no given to compare (as variants_for_class always had it).
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < givens.given.size() && i < taken_.size(); ++i)
    if (givens.given[i] && !givens.given[i]->empty() && taken_[i].count(*givens.given[i]) &&
        !(allow_repeats_ && exhausted_[i]))
      out.push_back(i);
  return out;
}

void ClassVariants::hold(const VariantGivens& givens) {
  for (std::size_t i = 0; i < givens.given.size() && i < taken_.size(); ++i)
    if (givens.given[i] && !givens.given[i]->empty()) taken_[i].insert(*givens.given[i]);
}

bool ClassVariants::take(const VariantGivens& givens) {
  if (!repeated(givens).empty()) return false;
  hold(givens);
  return true;
}

std::vector<std::string> ClassVariants::exhausted() const {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < exhausted_.size(); ++i)
    if (exhausted_[i]) out.push_back(set_.problems[i].id);
  return out;
}

ProblemSet ClassVariants::draw(const std::string& student) {
  // A problem known to have run out makes every later draw fail alike: without allow_repeats
  // the student is told at once, not after kMaxDrawAttempts draws that cannot succeed.
  const bool known_out = std::find(exhausted_.begin(), exhausted_.end(), true) != exhausted_.end();
  std::vector<int> collisions(taken_.size(), 0);
  int draws = 0;
  for (int draw = 1; draw <= kMaxDrawAttempts && (allow_repeats_ || !known_out); ++draw) {
    const std::string who = "student:" + student + (draw == 1 ? "" : "#" + std::to_string(draw));
    VariantGivens givens;
    ProblemSet v = make_variant(set_, who, student, vary_all_, nullptr, &givens);
    const std::vector<std::size_t> same = repeated(givens);
    if (same.empty()) {
      hold(givens);
      v.variant->draw = draw;
      return v;
    }
    ++draws;
    for (const std::size_t p : same) ++collisions[p];
    // With allow_repeats, a problem that repeated in every one of many draws has run out: it may
    // repeat from now on, and this student is drawn again under that rule.
    if (allow_repeats_ && draw == kMaxDrawAttempts / 4)
      for (std::size_t p = 0; p < collisions.size(); ++p)
        if (collisions[p] == draws) exhausted_[p] = true;
  }
  if (allow_repeats_) {
    // Still none: the student's own first draw, its repeated problems allowed from now on.
    VariantGivens givens;
    ProblemSet v = first_draw(student, &givens);
    for (const std::size_t p : repeated(givens)) exhausted_[p] = true;
    hold(givens);
    v.variant->draw = 1;
    return v;
  }
  // Which problems ran out: those that repeated in every draw.
  std::string names;
  for (std::size_t p = 0; p < collisions.size(); ++p)
    if (draws > 0 && collisions[p] == draws) {
      exhausted_[p] = true;
      names += (names.empty() ? "'" : ", '") + set_.problems[p].id + "'";
    }
  if (names.empty())
    for (std::size_t p = 0; p < exhausted_.size(); ++p)
      if (exhausted_[p]) names += (names.empty() ? "'" : ", '") + set_.problems[p].id + "'";
  ProblemSet out = set_;
  out.per_student = false;
  out.variant = VariantInfo{student, 0, kMaxDrawAttempts};
  out.errors.push_back(Diagnostic{
      SourceLocation{set_.file, 0, 0}, "student",
      "no variant for " + student + " that differs from every earlier student's: problem " + names +
          " has fewer variants than the class (widen its vary ranges, or generate with "
          "--allow-repeats to let it repeat)"});
  return out;
}

std::vector<ProblemSet> variants_for_class(const ProblemSet& set,
                                           const std::vector<std::string>& students, bool vary_all,
                                           bool allow_repeats) {
  ClassVariants drawn(set, vary_all, allow_repeats);
  std::vector<ProblemSet> out;
  for (const std::string& student : students) out.push_back(drawn.draw(student));
  return out;
}

ProblemSet variant_for(const ProblemSet& set, const std::string& student) {
  if (!set_varies(set)) return set;
  if (student.empty()) {
    ProblemSet out = set;
    out.errors.push_back(Diagnostic{SourceLocation{set.file, 0, 0}, "student",
                                    "this set gives every student their own variant: the answers "
                                    "need `student:` to say whose variant to grade"});
    return out;
  }
  return variant_for_student(set, student, false);
}

SeedVariants::SeedVariants(const ProblemSet& set, std::uint64_t seed, int count, bool vary_all)
    : set_(prepare_for_drawing(set, vary_all)),
      seed_(seed),
      count_(count),
      vary_all_(vary_all),
      taken_(set.problems.size()) {}

ProblemSet SeedVariants::draw(int i, VariantGivens* givens) {
  VariantGivens own;
  VariantGivens& g = givens ? *givens : own;
  ProblemSet v = make_variant(set_, seed_who(seed_, i), "", vary_all_, &taken_, &g);
  // A problem that found no new variant in all its draws has (nearly) used up its ranges:
  // the later variants would each spend every draw and fail alike, so the run stops here.
  for (std::size_t p = 0; p < v.problems.size(); ++p) {
    if (g.given[p]) {
      taken_[p].insert(*g.given[p]);
    } else if (v.problems[p].error && !set_.problems[p].error) {
      v.problems[p].error->message +=
          "; stopped at variant " + std::to_string(i + 1) + " of " + std::to_string(count_) + " (" +
          std::to_string(taken_[p].size()) + " distinct variants of this problem were drawn)";
      exhausted_ = true;
    }
  }
  return v;
}

bool SeedVariants::take(const VariantGivens& givens) {
  if (!givens.complete || givens.given.size() != taken_.size()) return false;
  for (std::size_t p = 0; p < taken_.size(); ++p) {
    if (givens.given[p] && taken_[p].count(*givens.given[p])) return false;
    for (const std::string& text : givens.repeated[p])
      if (!taken_[p].count(text)) return false;
  }
  for (std::size_t p = 0; p < taken_.size(); ++p)
    if (givens.given[p]) taken_[p].insert(*givens.given[p]);
  return true;
}

void for_each_variant_from_seed(const ProblemSet& set, std::uint64_t seed, int count, bool vary_all,
                                const std::function<void(int, ProblemSet&&)>& take) {
  // Each variant is checked against the givens drawn so far in O(log n) (rebuilding them from
  // every earlier variant made --count quadratic).
  SeedVariants drawn(set, seed, count, vary_all);
  for (int i = 0; i < count && !drawn.exhausted(); ++i) take(i, drawn.draw(i));
}

std::vector<ProblemSet> variants_from_seed(const ProblemSet& set, std::uint64_t seed, int count,
                                           bool vary_all) {
  std::vector<ProblemSet> out;
  for_each_variant_from_seed(set, seed, count, vary_all,
                             [&](int, ProblemSet&& v) { out.push_back(std::move(v)); });
  return out;
}

YAML::Node answer_node(const Value& v) {
  auto number = [&](std::size_t i) {
    return i < v.exact.size() ? format_exact(canonical(v.exact[i]), MathStyle::Plain)
                              : format_double(v.numbers[i]);
  };
  // Items are made in place in their list's memory (a node pushed is merged into it).
  YAML::Node n;
  switch (v.shape) {
    case Value::Shape::Null:
      return YAML::Node("none");
    case Value::Shape::Scalar:
      return YAML::Node(number(0));
    case Value::Shape::Vector:
      n = YAML::Node(YAML::NodeType::Sequence);
      for (std::size_t i = 0; i < v.numbers.size(); ++i) n[i] = number(i);
      return n;
    case Value::Shape::Matrix:
      n = YAML::Node(YAML::NodeType::Sequence);
      for (int r = 0; r < v.rows; ++r) {
        YAML::Node row(YAML::NodeType::Sequence);
        for (int c = 0; c < v.cols; ++c)
          row[static_cast<std::size_t>(c)] = number(static_cast<std::size_t>(r * v.cols + c));
        n.push_back(row);
      }
      return n;
    case Value::Shape::Bool:
      return YAML::Node(v.flag ? "true" : "false");
    case Value::Shape::Word:
      return string_node(v.word);  // a bit string 0010 stays a string
    case Value::Shape::WordMap:
      n = YAML::Node(YAML::NodeType::Map);
      for (const auto& [k, w] : v.entries) n[k] = string_node(w);
      return n;
    case Value::Shape::WordList:
      n = YAML::Node(YAML::NodeType::Sequence);
      for (const std::string& w : v.words) n.push_back(string_node(w));
      return n;
  }
  return n;
}

std::string comment_lines(const std::string& header) {
  std::string out;
  std::size_t start = 0;
  while (start < header.size()) {
    const std::size_t end = header.find('\n', start);
    const std::string line =
        header.substr(start, end == std::string::npos ? std::string::npos : end - start);
    out += line.empty() ? "#\n" : "# " + line + "\n";
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

namespace {

// A clip window or box {xmin, xmax, ymin, ymax[, zmin, zmax]} as students read it:
// [xmin, xmax] × [ymin, ymax] (× [zmin, zmax]); nullopt for any other mapping.
std::optional<std::string> box_text(const YAML::Node& at) {
  std::string out;
  std::size_t fields = 0;
  for (const std::string axis : {"x", "y", "z"}) {
    const YAML::Node low = at[axis + "min"], high = at[axis + "max"];
    if (!low.IsDefined() && !high.IsDefined() && axis == "z") break;
    if (!low.IsDefined() || !high.IsDefined() || !low.IsScalar() || !high.IsScalar())
      return std::nullopt;
    out += (out.empty() ? "[" : " × [") + low.Scalar() + ", " + high.Scalar() + "]";
    fields += 2;
  }
  if (fields != at.size()) return std::nullopt;
  return out;
}

// A value's minus signs (at its start, or after "(" or ", " in a point) as U+2212, for a text
// whose author writes them so: a variant's values then read like the rest of its text.
std::string typographic_minus(const std::string& v) {
  std::string out;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const bool starts = k == 0 || v[k - 1] == '(' || (k >= 2 && v.compare(k - 2, 2, ", ") == 0);
    out += v[k] == '-' && starts ? std::string("\u2212") : std::string(1, v[k]);
  }
  return out;
}

// `degrees` in radians as a multiple of `pi` (PI or π): 60 → PI/3, 120 → 2*PI/3 (2π/3).
std::string radians_text(long degrees, const std::string& pi) {
  if (degrees == 0) return "0";
  const long g = std::gcd(std::abs(degrees), 180L);
  const long p = degrees / g, q = 180 / g;
  const std::string times = pi == "PI" ? "*" : "";
  std::string out = p == 1 ? pi : p == -1 ? "-" + pi : std::to_string(p) + times + pi;
  return q == 1 ? out : out + "/" + std::to_string(q);
}

// The value a placeholder names ({eye}, {perspective.fovy}, {points.0}), as students read it:
// a number as written, a list of numbers as a point (1, 2, 3), a window as [0, 4] × [0, 3];
// nullopt with `why` otherwise.
std::optional<std::string> placeholder_value(const std::string& name, const YAML::Node& given,
                                             std::string& why) {
  // {field|−}: the value with its minus signs as U+2212 (a literal its author wrote so).
  if (const std::string minus = "|\u2212"; name.size() > minus.size() && name.ends_with(minus)) {
    std::optional<std::string> v =
        placeholder_value(name.substr(0, name.size() - minus.size()), given, why);
    if (v) v = typographic_minus(*v);
    return v;
  }
  // {field|PI}, {field|π}: a whole number of degrees written as a multiple of π in radians, as
  // Processing's perspective(PI/3, …) writes a field of view of 60°.
  for (const char* sym : {"PI", "\u03c0"})
    if (const std::string suffix = std::string("|") + sym;
        name.size() > suffix.size() && name.ends_with(suffix)) {
      const std::optional<std::string> degrees =
          placeholder_value(name.substr(0, name.size() - suffix.size()), given, why);
      if (!degrees) return std::nullopt;
      const std::string& d = *degrees;
      const bool whole =
          !d.empty() && d.size() < 10 &&
          d.find_first_not_of("0123456789", d[0] == '-' ? 1 : 0) == std::string::npos && d != "-";
      if (!whole) {
        why =
            "is not a whole number of degrees, to be written as a multiple of " + std::string(sym);
        return std::nullopt;
      }
      return radians_text(std::stol(d), sym);
    }
  // Walked by reset() and const look-ups: assigning a node would write through to the given,
  // and cloning it for every placeholder made filling a text cost a copy of the given each.
  YAML::Node at;
  at.reset(given);
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = name.find('.', start);
    const std::string part =
        name.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    const YAML::Node& here = at;
    if (here.IsMap() && !part.empty() && here[part].IsDefined()) {
      at.reset(here[part]);
    } else if (here.IsSequence() && !part.empty() &&
               part.find_first_not_of("0123456789") == std::string::npos && part.size() < 6 &&
               std::stoul(part) < here.size()) {
      at.reset(here[std::stoul(part)]);
    } else {
      why = "names no field of the given";
      return std::nullopt;
    }
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (at.IsScalar()) return at.Scalar();
  if (at.IsSequence() && at.size() > 0) {
    std::string out = "(";
    for (std::size_t i = 0; i < at.size(); ++i) {
      if (!at[i].IsScalar()) {
        why = "is a nested list, not a number or a point";
        return std::nullopt;
      }
      out += (i ? ", " : "") + at[i].Scalar();
    }
    return out + ")";
  }
  if (at.IsMap())
    if (std::optional<std::string> box = box_text(at)) return box;
  why = at.IsMap() ? "is a mapping: name one of its fields ({" + name + ".…})" : "has no value";
  return std::nullopt;
}

// Each `{name}` of a text, with its position; text without a closing brace is left alone.
template <typename F>
void for_each_placeholder(const std::string& text, F f) {
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t open = text.find('{', i);
    if (open == std::string::npos) return;
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) return;
    f(open, close, text.substr(open + 1, close - open - 1));
    i = close + 1;
  }
}

}  // namespace

std::string fill_text(const std::string& text, const YAML::Node& given) {
  std::string out;
  std::size_t i = 0;
  const bool unicode_minus = text.find("\u2212") != std::string::npos;
  for_each_placeholder(text, [&](std::size_t open, std::size_t close, const std::string& name) {
    std::string why;
    std::optional<std::string> v = placeholder_value(name, given, why);
    if (v && unicode_minus) v = typographic_minus(*v);
    out += text.substr(i, open - i) + (v ? *v : text.substr(open, close - open + 1));
    i = close + 1;
  });
  return out + text.substr(std::min(i, text.size()));
}

std::optional<std::string> placeholder_error(const std::string& text, const YAML::Node& given) {
  std::optional<std::string> error;
  for_each_placeholder(text, [&](std::size_t, std::size_t, const std::string& name) {
    std::string why;
    if (!error && !placeholder_value(name, given, why))
      error = "the placeholder {" + name + "} " + why;
  });
  return error;
}

std::string set_fingerprint(const YAML::Node& root) {
  if (!root.IsMap()) return fmt::format("{:016x}", fnv1a64(emit_flow(root)));
  YAML::Node copy(YAML::NodeType::Map);
  for (auto it = root.begin(); it != root.end(); ++it)
    if (it->first.as<std::string>() != "drawn_from") copy[it->first] = it->second;
  return fmt::format("{:016x}", fnv1a64(emit_flow(copy)));
}

std::string drawn_from_line(const DrawnFrom& d) {
  std::string out =
      "drawn_from: {set: " + emit_scalar(d.set) + ", fingerprint: \"" + d.fingerprint + "\"";
  if (!d.student.empty()) out += ", student: " + emit_scalar(d.student);
  return out + fmt::format(", draw: {}}}\n", d.draw);
}

std::string emit_variant_set(const YAML::Node& root, const ProblemSet& variant,
                             const std::string& header) {
  std::string out = comment_lines(header);
  for (auto it = root.begin(); it != root.end(); ++it) {
    const std::string key = it->first.as<std::string>();
    if (key == "variants") continue;
    if (key != "problems") {
      out += emit_scalar(key) + ": " + emit_flow(it->second) + "\n";
      continue;
    }
    out += "problems:\n";
    const YAML::Node problems = it->second;
    for (std::size_t i = 0; i < problems.size(); ++i) {
      const YAML::Node p = problems[i];
      const ProblemSpec* spec = i < variant.problems.size() ? &variant.problems[i] : nullptr;
      const YAML::Node given = spec ? spec->given_node : p["given"];
      bool first = true;
      for (auto f = p.begin(); f != p.end(); ++f) {
        const std::string name = f->first.as<std::string>();
        if (name == "vary" || name == "nice" || name == "difficulty" || name == "samples")
          continue;  // samples answer the set as written, not a variant
        out += first ? "  - " : "    ";
        first = false;
        if (name == "given" && given.IsMap()) {
          out += "given:\n";
          for (auto g = given.begin(); g != given.end(); ++g)
            out += "      " + emit_flow(g->first) + ": " + emit_flow(g->second) + "\n";
        } else if (name == "text" && f->second.IsScalar()) {
          const std::string& text = spec ? spec->text.text : f->second.Scalar();
          out += "text: " + emit_scalar(fill_text(text, given), true) + "\n";
        } else if (name == "text" && f->second.IsMap()) {
          // Every language the set gives, each with the drawn values (the variant's text: its
          // literal values turned into placeholders when it was drawn).
          out += "text:\n";
          for (auto l = f->second.begin(); l != f->second.end(); ++l) {
            const std::optional<Lang> lang = parse_lang(l->first.as<std::string>());
            const std::string text = spec && lang           ? spec->text.in(*lang)
                                     : l->second.IsScalar() ? l->second.Scalar()
                                                            : "";
            out += "      " + emit_flow(l->first) + ": " +
                   emit_scalar(fill_text(text, given), true) + "\n";
          }
        } else {
          out += emit_scalar(name) + ": " + emit_flow(f->second) + "\n";
        }
      }
    }
  }
  return out;
}

std::string emit_answer_key(const ProblemSet& variant, const std::string& student,
                            const std::string& header, std::vector<Diagnostic>* errors) {
  std::string out = comment_lines(header);
  out += "student: " + emit_scalar(student) + "\nanswers:\n";
  for (const ProblemSpec& p : variant.problems) {
    const ProblemResult r = solve_problem(p, variant.file, false);
    if (r.error) {
      if (errors) errors->push_back(*r.error);
      continue;
    }
    out += "  " + emit_scalar(p.id) + ":\n";
    for (const std::string& name : p.ask)
      if (const Value* v = r.answers.find(name))
        out += "    " + emit_scalar(name) + ": " + emit_flow(answer_node(*v)) + "\n";
  }
  return out;
}

}  // namespace frustum
