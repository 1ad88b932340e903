#include "solver/problem/samples.hpp"

#include <algorithm>

#include "solver/input/given_reader.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/util/suggest.hpp"

namespace frustum {

namespace {

const std::vector<std::string> kSampleFields = {"answers", "expect", "credit", "note"};
const std::vector<std::string> kVerdictNames = {"right", "wrong", "partly", "unparseable"};

[[noreturn]] void fail_at(const YAML::Node& n, const std::string& file, const std::string& field,
                          const std::string& message) {
  throw InputError(Diagnostic{location_of(n, file), field, message});
}

SampleVerdict read_expect(const YAML::Node& n, const std::string& file, const std::string& field) {
  const std::string v = n.IsScalar() ? n.Scalar() : "";
  for (std::size_t i = 0; i < kVerdictNames.size(); ++i)
    if (v == kVerdictNames[i]) return static_cast<SampleVerdict>(i);
  fail_at(n, file, field,
          "'" + v + "' is not one of right, wrong, partly, unparseable" +
              did_you_mean(v, kVerdictNames));
}

double read_credit(const YAML::Node& n, const std::string& file, const std::string& field) {
  const double v = to_double(read_number(n, file, field));
  if (!(v >= 0 && v <= 1)) fail_at(n, file, field, "a fraction of the points, from 0 to 1");
  return v;
}

Sample read_sample(const YAML::Node& s, const ProblemSpec& spec, const std::string& file,
                   const std::string& field) {
  if (!s.IsMap())
    fail_at(s, file, field, "expected a mapping {answers: {name: value}, expect: right|…}");
  check_keys(s, kSampleFields, file, field);
  Sample out;
  out.where = location_of(s, file);
  out.field = field;
  const YAML::Node answers = s["answers"];
  if (!answers.IsDefined() || !answers.IsMap() || answers.size() == 0)
    fail_at(answers.IsDefined() ? answers : s, file, field + ".answers",
            "expected a mapping of asked answers to values, like {" +
                (spec.ask.empty() ? std::string("z") : spec.ask.front()) + ": …}");
  for (auto it = answers.begin(); it != answers.end(); ++it) {
    const std::string name = it->first.as<std::string>();
    if (std::find(spec.ask.begin(), spec.ask.end(), name) == spec.ask.end())
      fail_at(it->first, file, field + ".answers." + name,
              "not an asked answer" + did_you_mean(name, spec.ask));
  }
  out.answers = answers;
  if (s["expect"].IsDefined()) out.expect = read_expect(s["expect"], file, field + ".expect");
  if (s["credit"].IsDefined()) out.credit = read_credit(s["credit"], file, field + ".credit");
  if (!out.expect && !out.credit)
    fail_at(s, file, field + ".expect",
            "missing: a sample says what it should be graded (expect: right|wrong|partly|"
            "unparseable, or credit: 0..1)");
  if (s["note"].IsDefined()) {
    if (!s["note"].IsScalar()) fail_at(s["note"], file, field + ".note", "expected text");
    out.note = s["note"].Scalar();
  }
  return out;
}

}  // namespace

const char* to_string(SampleVerdict v) {
  switch (v) {
    case SampleVerdict::Right:
      return "right";
    case SampleVerdict::Wrong:
      return "wrong";
    case SampleVerdict::Partly:
      return "partly";
    case SampleVerdict::Unparseable:
      return "unparseable";
  }
  return "?";
}

std::vector<Sample> read_samples(const YAML::Node& samples, const ProblemSpec& spec,
                                 const std::string& file) {
  const std::string field = spec.field + ".samples";
  if (!samples.IsDefined() || samples.IsNull()) return {};
  if (!samples.IsSequence())
    fail_at(samples, file, field, "expected a list of samples {answers, expect, note}");
  if (samples.size() > kMaxSamples)
    fail_at(samples, file, field, "at most " + std::to_string(kMaxSamples) + " samples");
  std::vector<Sample> out;
  for (std::size_t i = 0; i < samples.size(); ++i)
    out.push_back(read_sample(samples[i], spec, file, field + "[" + std::to_string(i) + "]"));
  return out;
}

}  // namespace frustum
