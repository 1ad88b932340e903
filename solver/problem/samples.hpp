// Sample answers with the verdict their author expects (`samples:` on a problem): an author's
// own regression test of the grading policy. The loader reads them here; grader/samples.hpp
// grades them against the problem's key.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "solver/util/diagnostic.hpp"

namespace frustum {

struct ProblemSpec;

// A problem's samples: enough for every case an author checks by hand, few enough that `check`
// grading them stays quick.
inline constexpr std::size_t kMaxSamples = 100;

// What a sample's answers, taken together, should be graded: every one right; none earning
// credit; some credit but not all; at least one that cannot be read.
enum class SampleVerdict { Right, Wrong, Partly, Unparseable };

const char* to_string(SampleVerdict v);

struct Sample {
  YAML::Node answers;                   // {answer name: value}, as an answers file writes them
  std::optional<SampleVerdict> expect;  // `expect:`
  std::optional<double> credit;         // `credit:` 0..1, the fraction of these answers' points
  std::string note;                     // why the author expects it
  SourceLocation where;                 // the sample's mapping
  std::string field;                    // "problems[0].samples[1]"
};

// `samples:` of a problem whose `ask` is known: a list of {answers, expect | credit, note}.
// Throws InputError at the offending field.
std::vector<Sample> read_samples(const YAML::Node& samples, const ProblemSpec& spec,
                                 const std::string& file);

}  // namespace frustum
