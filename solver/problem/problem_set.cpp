#include "solver/problem/problem_set.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "solver/input/given_reader.hpp"
#include "solver/input/text_reader.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/samples.hpp"
#include "solver/problem/serve_policy.hpp"
#include "solver/util/suggest.hpp"

namespace frustum {

namespace {

const std::vector<std::string> kSetFields = {"title",      "lang",     "source",      "conventions",
                                             "tolerance",  "problems", "description", "grading",
                                             "variants",   "feedback", "attempts",    "deadline",
                                             "drawn_from", "penalty",  "extensions"};
const std::vector<std::string> kProblemFields = {
    "id",          "kind",      "text", "given",      "ask",     "points", "vary",
    "conventions", "tolerance", "nice", "difficulty", "grading", "samples"};

[[noreturn]] void fail_at(const YAML::Node& n, const std::string& file, const std::string& field,
                          const std::string& message) {
  throw InputError(Diagnostic{location_of(n, file), field, message});
}

std::string read_string(const YAML::Node& n, const std::string& file, const std::string& field) {
  if (!n.IsScalar()) fail_at(n, file, field, "expected text");
  return n.Scalar();
}

// `drawn_from: {set: NAME, fingerprint: HEX, student: ID, draw: N}` of a variant file.
DrawnFrom read_drawn_from(const YAML::Node& n, const std::string& file) {
  if (!n.IsMap())
    fail_at(n, file, "drawn_from", "expected a mapping {set, fingerprint, student, draw}");
  check_keys(n, {"set", "fingerprint", "student", "draw"}, file, "drawn_from");
  DrawnFrom d;
  d.set = n["set"].IsDefined() ? read_string(n["set"], file, "drawn_from.set") : "";
  if (!n["fingerprint"].IsDefined())
    fail_at(n, file, "drawn_from.fingerprint", "missing required field");
  d.fingerprint = read_string(n["fingerprint"], file, "drawn_from.fingerprint");
  if (n["student"].IsDefined()) d.student = read_string(n["student"], file, "drawn_from.student");
  if (n["draw"].IsDefined()) {
    const std::string draw = read_string(n["draw"], file, "drawn_from.draw");
    if (draw.empty() || draw.size() > 6 ||
        draw.find_first_not_of("0123456789") != std::string::npos || std::stoi(draw) < 1)
      fail_at(n["draw"], file, "drawn_from.draw", "expected a whole number from 1");
    d.draw = std::stoi(draw);
  }
  return d;
}

double read_nonnegative(const YAML::Node& n, const std::string& file, const std::string& field) {
  const double v = to_double(read_number(n, file, field));
  if (!(v >= 0)) fail_at(n, file, field, "must be a non-negative number");
  return v;
}

// A score weight: finite and at most kMaxPoints, so that a whole set's total (and every
// gradebook sum and percentage) is a finite number (`points: 1e400` once aborted a batch).
double read_points(const YAML::Node& n, const std::string& file, const std::string& field) {
  const double v = read_nonnegative(n, file, field);
  if (!(v <= kMaxPoints))
    fail_at(n, file, field, "at most " + std::to_string(static_cast<long>(kMaxPoints)) + " points");
  return v;
}

void load_problem(const YAML::Node& p, ProblemSpec& spec, const ProblemSet& set,
                  std::set<std::string>& ids) {
  const std::string& file = set.file;
  if (!p.IsMap())
    fail_at(p, file, spec.field, "expected a problem (a mapping with id, kind, given)");
  check_keys(p, kProblemFields, file, spec.field);
  if (!p["id"].IsDefined()) fail_at(p, file, spec.field + ".id", "missing required field");
  spec.id = read_string(p["id"], file, spec.field + ".id");
  if (spec.id.empty()) fail_at(p["id"], file, spec.field + ".id", "must not be empty");
  if (!ids.insert(spec.id).second)
    fail_at(p["id"], file, spec.field + ".id", "duplicate id '" + spec.id + "'");
  if (!p["kind"].IsDefined()) fail_at(p, file, spec.field + ".kind", "missing required field");
  spec.kind = read_string(p["kind"], file, spec.field + ".kind");
  spec.info = builtin_kinds().find(spec.kind);
  if (!spec.info)
    fail_at(p["kind"], file, spec.field + ".kind",
            "unknown kind '" + spec.kind + "'" + did_you_mean(spec.kind, builtin_kinds().names()));
  spec.text.lang = set.lang;
  if (p["text"].IsDefined()) {
    spec.text = read_local_text(p["text"], file, spec.field + ".text", set.lang);
    spec.text_node = p["text"];
  }
  spec.conventions =
      read_conventions(p["conventions"], file, spec.field + ".conventions", set.conventions);
  spec.tolerance = read_tolerance(p["tolerance"], file, spec.field + ".tolerance", set.tolerance);
  spec.grading = read_grading(p["grading"], file, spec.field + ".grading", set.grading);

  // ask: a list of the kind's answer names (default: all of them that the given makes
  // sense of — no transformed points where no points are given).
  std::vector<std::string> answer_names, applicable;
  const YAML::Node given_node = p["given"];
  const auto gives = [&](const std::string& field) {
    return field.empty() ||
           (given_node.IsMap() && given_node[field].IsDefined() && !given_node[field].IsNull());
  };
  for (const AnswerSpec& a : spec.info->answers) {
    answer_names.push_back(a.name);
    if (gives(a.needs_given)) applicable.push_back(a.name);
  }
  const YAML::Node ask = p["ask"];
  if (ask.IsDefined() && !ask.IsNull()) {
    const std::string f = spec.field + ".ask";
    if (ask.IsScalar()) {
      spec.ask.push_back(ask.Scalar());
    } else if (ask.IsSequence()) {
      for (std::size_t i = 0; i < ask.size(); ++i)
        spec.ask.push_back(read_string(ask[i], file, f + "[" + std::to_string(i) + "]"));
    } else {
      fail_at(ask, file, f, "expected a list of answer names");
    }
    for (std::size_t i = 0; i < spec.ask.size(); ++i) {
      const AnswerSpec* a = spec.info->answer(spec.ask[i]);
      if (!a)
        fail_at(ask.IsSequence() ? ask[i] : ask, file, f,
                "'" + spec.ask[i] + "' is not an answer of " + spec.kind +
                    did_you_mean(spec.ask[i], answer_names));
      else if (!gives(a->needs_given))
        fail_at(ask.IsSequence() ? ask[i] : ask, file, f,
                "'" + spec.ask[i] + "' needs given." + a->needs_given +
                    ", which this problem does not give");
    }
    if (spec.ask.empty()) fail_at(ask, file, f, "asks for nothing");
  } else {
    spec.ask = applicable;
  }
  const YAML::Node points = p["points"];
  if (points.IsDefined() && points.IsMap()) {
    for (auto it = points.begin(); it != points.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      const std::string f = spec.field + ".points." + k;
      if (std::find(spec.ask.begin(), spec.ask.end(), k) == spec.ask.end())
        fail_at(it->first, file, f, "not an asked answer" + did_you_mean(k, spec.ask));
      spec.weights[k] = read_points(it->second, file, f);
    }
  } else if (points.IsDefined()) {
    spec.points = read_points(points, file, spec.field + ".points");
  }
  // Per-answer tolerances: tolerance: {answers: {z: {decimals: 1}}}.
  const YAML::Node tol = p["tolerance"];
  const YAML::Node per = tol.IsDefined() && tol.IsMap() ? tol["answers"] : YAML::Node();
  if (per.IsDefined() && per.IsMap())
    for (auto it = per.begin(); it != per.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      const std::string f = spec.field + ".tolerance.answers." + k;
      if (!spec.info->answer(k))
        fail_at(it->first, file, f,
                "not an answer of " + spec.kind + did_you_mean(k, answer_names));
      spec.answer_tolerance[k] = read_tolerance(it->second, file, f, spec.tolerance);
    }
  spec.samples = read_samples(p["samples"], spec, file);
  // Variation (generate.hpp): `vary`, `nice: true`, `difficulty: normal|hard`.
  if (p["vary"].IsDefined() && !p["vary"].IsNull()) spec.vary = p["vary"];
  if (p["vary"].IsDefined() && !p["vary"].IsNull() && spec.info->fixed)
    fail_at(p["vary"], file, spec.field + ".vary",
            spec.kind + " has nothing to vary: every variant keeps it as written");
  if (p["nice"].IsDefined()) {
    const std::string v = read_string(p["nice"], file, spec.field + ".nice");
    if (v != "true" && v != "false")
      fail_at(p["nice"], file, spec.field + ".nice", "must be true or false");
    spec.nice = v == "true";
  }
  if (p["difficulty"].IsDefined()) {
    const std::string v = read_string(p["difficulty"], file, spec.field + ".difficulty");
    if (v != "normal" && v != "hard")
      fail_at(p["difficulty"], file, spec.field + ".difficulty",
              "'" + v + "' is not one of normal, hard" + did_you_mean(v, {"normal", "hard"}));
    spec.hard = v == "hard";
  }
  if (const YAML::Node given = p["given"]; !given.IsDefined() || given.IsNull()) {
    std::string fields;
    for (const std::string& f : spec.info->given_fields) fields += (fields.empty() ? "" : ", ") + f;
    fail_at(p, file, spec.field + ".given",
            "missing: a problem gives its data under `given:` (" + spec.kind + " reads " + fields +
                ")");
  }
  spec.given_node = p["given"];
  GivenReader reader(p["given"], file, spec.field + ".given", spec.info->given_fields);
  reader.set_text_lang(set.lang);
  spec.given = spec.info->parse(reader, spec.conventions);
  reader.finish();
}

}  // namespace

void check_keys(const YAML::Node& map, const std::vector<std::string>& known,
                const std::string& file, const std::string& prefix) {
  for (auto it = map.begin(); it != map.end(); ++it) {
    const std::string k = it->first.as<std::string>();
    if (std::find(known.begin(), known.end(), k) == known.end())
      fail_at(it->first, file, prefix.empty() ? k : prefix + "." + k,
              "unknown field" + did_you_mean(k, known));
  }
}

Conventions read_conventions(const YAML::Node& n, const std::string& file, const std::string& field,
                             Conventions base) {
  if (!n.IsDefined() || n.IsNull()) return base;
  if (!n.IsMap()) fail_at(n, file, field, "expected a mapping like {api: opengl, angles: degrees}");
  check_keys(n, {"api", "angles", "z_planes", "fov", "handedness"}, file, field);
  if (n["api"].IsDefined()) {
    const std::string v = read_string(n["api"], file, field + ".api");
    const auto api = parse_api(v);
    if (!api)
      fail_at(n["api"], file, field + ".api",
              "'" + v + "' is not one of opengl, processing, directx" +
                  did_you_mean(v, {"opengl", "processing", "directx"}));
    base.api = *api;
  }
  if (n["angles"].IsDefined()) {
    const std::string v = read_string(n["angles"], file, field + ".angles");
    const auto unit = parse_angle_unit(v);
    if (!unit)
      fail_at(
          n["angles"], file, field + ".angles",
          "'" + v + "' is not one of degrees, radians" + did_you_mean(v, {"degrees", "radians"}));
    base.angles = *unit;
  }
  if (n["z_planes"].IsDefined()) {
    const std::string v = read_string(n["z_planes"], file, field + ".z_planes");
    if (v != "distances" && v != "coordinates")
      fail_at(n["z_planes"], file, field + ".z_planes",
              "'" + v + "' is not one of distances, coordinates" +
                  did_you_mean(v, {"distances", "coordinates"}));
    base.z_planes = v == "coordinates" ? ZPlanes::Coordinates : ZPlanes::Distances;
  }
  if (n["fov"].IsDefined()) {
    const std::string v = read_string(n["fov"], file, field + ".fov");
    if (v != "vertical" && v != "horizontal")
      fail_at(n["fov"], file, field + ".fov",
              "'" + v + "' is not one of vertical, horizontal" +
                  did_you_mean(v, {"vertical", "horizontal"}));
    base.fov = v == "horizontal" ? FovAxis::Horizontal : FovAxis::Vertical;
  }
  if (n["handedness"].IsDefined()) {
    const std::string v = read_string(n["handedness"], file, field + ".handedness");
    if (v != "right" && v != "left")
      fail_at(n["handedness"], file, field + ".handedness",
              "'" + v + "' is not one of right, left" + did_you_mean(v, {"right", "left"}));
    base.handedness = v == "left" ? Handedness::Left : Handedness::Right;
  }
  // DirectX's matrices here are the left-handed ones (LookAtLH, PerspectiveOffCenterLH).
  if (base.api == Api::DirectX && base.handedness == Handedness::Right)
    fail_at(n["handedness"].IsDefined() ? n["handedness"] : n, file, field + ".handedness",
            "DirectX is left-handed here (LookAtLH, PerspectiveOffCenterLH); a right-handed course "
            "uses api: opengl or processing");
  return base;
}

Tolerance read_tolerance(const YAML::Node& n, const std::string& file, const std::string& field,
                         Tolerance base) {
  if (!n.IsDefined() || n.IsNull()) return base;
  if (!n.IsMap()) fail_at(n, file, field, "expected a mapping like {rel: 1.0e-3, abs: 1.0e-6}");
  check_keys(n, {"rel", "abs", "sigfigs", "decimals", "answers"}, file, field);
  if (n["rel"].IsDefined()) base.rel = read_nonnegative(n["rel"], file, field + ".rel");
  if (n["abs"].IsDefined()) base.abs = read_nonnegative(n["abs"], file, field + ".abs");
  auto count = [&](const char* key) -> std::optional<int> {
    if (!n[key].IsDefined()) return std::nullopt;
    const double v = read_nonnegative(n[key], file, field + "." + key);
    if (v != std::floor(v) || v > 17 || (std::string(key) == "sigfigs" && v < 1))
      fail_at(n[key], file, field + "." + key,
              std::string("must be a whole number ") +
                  (std::string(key) == "sigfigs" ? "from 1 to 17" : "from 0 to 17"));
    return static_cast<int>(v);
  };
  if (auto s = count("sigfigs")) base.sigfigs = s;
  if (auto d = count("decimals")) base.decimals = d;
  if (base.sigfigs && base.decimals)
    fail_at(n, file, field, "give either sigfigs or decimals, not both");
  return base;
}

Grading read_grading(const YAML::Node& n, const std::string& file, const std::string& field,
                     Grading base) {
  if (!n.IsDefined() || n.IsNull()) return base;
  if (!n.IsMap()) fail_at(n, file, field, "expected a mapping like {ecf: 0.5, partial: true}");
  check_keys(n, {"ecf", "partial", "linear_matrix"}, file, field);
  if (n["ecf"].IsDefined()) {
    base.ecf = read_nonnegative(n["ecf"], file, field + ".ecf");
    // A wrong answer never earns full points: carried credit is a part of them.
    if (base.ecf >= 1)
      fail_at(n["ecf"], file, field + ".ecf",
              "is a fraction of the points, at least 0 and below 1 (an answer that is wrong "
              "against the key never earns full points)");
  }
  const auto flag = [&](const char* key, bool& out) {
    if (!n[key].IsDefined()) return;
    const std::string f = field + "." + key;
    const std::string v = read_string(n[key], file, f);
    if (v != "true" && v != "false") fail_at(n[key], file, f, "must be true or false");
    out = v == "true";
  };
  flag("partial", base.partial);
  flag("linear_matrix", base.linear_matrix);
  return base;
}

double ProblemSpec::answer_points(const std::string& name) const {
  if (!weights.empty()) {
    const auto it = weights.find(name);
    return it == weights.end() ? 0.0 : it->second;
  }
  if (points) return ask.empty() ? 0.0 : *points / static_cast<double>(ask.size());
  return 1.0;
}

double ProblemSpec::max_score() const {
  double total = 0;
  for (const std::string& a : ask) total += answer_points(a);
  return total;
}

const Tolerance& ProblemSpec::tolerance_for(const std::string& name) const {
  const auto it = answer_tolerance.find(name);
  return it == answer_tolerance.end() ? tolerance : it->second;
}

const ProblemSpec* ProblemSet::find(const std::string& id) const {
  for (const ProblemSpec& p : problems)
    if (p.id == id) return &p;
  return nullptr;
}

std::vector<Diagnostic> ProblemSet::all_errors() const {
  std::vector<Diagnostic> out = errors;
  for (const ProblemSpec& p : problems)
    if (p.error) out.push_back(*p.error);
  return out;
}

ProblemSet load_problem_set(const YamlDocument& doc, const std::string& name) {
  ProblemSet set;
  set.file = name;
  if (doc.error) {
    set.errors.push_back(*doc.error);
    return set;
  }
  if (doc.invalid_utf8) set.errors.push_back(*doc.invalid_utf8);
  const YAML::Node& root = doc.root;
  try {
    if (root.IsNull() && root.Mark().line < 0)
      throw InputError(Diagnostic{SourceLocation{name, 1, 1}, "",
                                  "the file is empty: expected a mapping with a 'problems' list"});
    if (!root.IsMap())
      fail_at(root, name, "", "expected a problem set: a mapping with a 'problems' list");
    check_keys(root, kSetFields, name, "");
    if (root["lang"].IsDefined()) {
      const std::string v = read_string(root["lang"], name, "lang");
      const std::optional<Lang> lang = parse_lang(v);
      if (!lang)
        fail_at(root["lang"], name, "lang",
                "'" + v + "' is not one of en, ja, ru" + did_you_mean(v, {"en", "ja", "ru"}));
      set.lang = *lang;
    }
    set.title.lang = set.lang;
    if (root["title"].IsDefined())
      set.title = read_local_text(root["title"], name, "title", set.lang);
    if (root["source"].IsDefined()) set.source = read_string(root["source"], name, "source");
    if (root["variants"].IsDefined()) {
      const std::string v = read_string(root["variants"], name, "variants");
      if (v != "per_student" && v != "fixed")
        fail_at(root["variants"], name, "variants",
                "'" + v + "' is not one of per_student, fixed" +
                    did_you_mean(v, {"per_student", "fixed"}));
      set.per_student = v == "per_student";
    }
    if (root["drawn_from"].IsDefined()) set.drawn_from = read_drawn_from(root["drawn_from"], name);
    set.conventions = read_conventions(root["conventions"], name, "conventions", {});
    set.tolerance = read_tolerance(root["tolerance"], name, "tolerance", {});
    set.grading = read_grading(root["grading"], name, "grading", {});
    read_serve_policy(root, name);  // checked here; `frustum serve` reads it (serve_policy.hpp)
    if (!root["problems"].IsDefined()) fail_at(root, name, "problems", "missing required field");
    if (!root["problems"].IsSequence())
      fail_at(root["problems"], name, "problems", "expected a list of problems");
    if (root["problems"].size() > kMaxSetProblems)
      fail_at(root["problems"], name, "problems",
              fmt::format("{} problems (the limit is {} problems a set): split the set",
                          root["problems"].size(), kMaxSetProblems));
  } catch (const InputError& e) {
    set.errors.push_back(e.diagnostic());
    return set;
  }
  const YAML::Node problems = root["problems"];
  std::set<std::string> ids;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    ProblemSpec spec;
    spec.field = "problems[" + std::to_string(i) + "]";
    spec.where = location_of(problems[i], name);
    try {
      load_problem(problems[i], spec, set, ids);
    } catch (const InputError& e) {
      spec.error = e.diagnostic();
    } catch (const DomainError& e) {
      GivenReader reader(spec.given_node, name, spec.field + ".given", {});
      spec.error = reader.locate(e.field(), e.what());
    } catch (const std::exception& e) {
      spec.error = Diagnostic{spec.where, spec.field, std::string("internal error: ") + e.what()};
    }
    if (spec.id.empty()) spec.id = spec.field;
    set.problems.push_back(std::move(spec));
  }
  if (problems.size() == 0)
    set.errors.push_back(Diagnostic{location_of(problems, name), "problems", "the list is empty"});
  return set;
}

ProblemSet load_problem_set_from_string(const std::string& yaml, const std::string& name) {
  return load_problem_set(parse_yaml(yaml, name), name);
}

ProblemSet load_problem_set(const std::string& path) {
  return load_problem_set(load_yaml_file(path), path);
}

}  // namespace frustum
