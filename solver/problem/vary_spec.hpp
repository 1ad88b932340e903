// A problem's `vary:` block: which `given` values vary and over what. Per field:
//   {range: [lo, hi], step: s}   a number lo + k·s, k uniform in 0..⌊(hi − lo)/s⌋ (step default 1;
//                                exact: "1/2", "sqrt(2)" allowed)
//   {choices: [v1, v2, ...]}     one of the listed values (any YAML: numbers, lists, mappings)
//   {each: SPEC, count: n}       a list whose every item varies by SPEC (count defaults to the
//                                length of the list in `given`)
//   [SPEC, SPEC, ...]            a list item by item; plain items stay as written
//   {field: SPEC, ...}           a nested mapping (perspective: {fovy: {choices: [60, 90]}})
//   a plain value                that value
// `vary: default` uses the kind's default generator instead of the given's values.
#pragma once

#include <yaml-cpp/yaml.h>

#include <memory>
#include <string>

#include "solver/problem/kind.hpp"
#include "solver/problem/rng.hpp"

namespace frustum {

// Checks a `vary` block against the kind's given fields; throws InputError located in `file`
// at the offending entry (field path `field`, e.g. "problems[0].vary.eye").
void check_vary(const YAML::Node& vary, const KindInfo& kind, const std::string& file,
                const std::string& field);

// Whether the block is `vary: default`.
bool vary_is_default(const YAML::Node& vary);

// A new given: `base` with the varied fields drawn from `rng` (base is not modified).
YAML::Node apply_vary(const YAML::Node& vary, const YAML::Node& base, Rng& rng,
                      const std::string& file, const std::string& field);

// A `vary` block read once (check_vary's checks, its ranges as numbers), then drawn from for
// every variant: draw() gives what apply_vary gives for the same block, given and generator
// state, and leaves the generator in the same state, without reading the block again.
class VaryPlan {
 public:
  struct Spec;  // one entry of the block (vary_spec.cpp)
  // Throws InputError as check_vary does.
  VaryPlan(const YAML::Node& vary, const KindInfo& kind, const std::string& file,
           const std::string& field);
  ~VaryPlan();
  VaryPlan(const VaryPlan&) = delete;
  VaryPlan& operator=(const VaryPlan&) = delete;
  YAML::Node draw(const YAML::Node& base, Rng& rng) const;

 private:
  std::string file_;
  std::unique_ptr<const Spec> root_;
};

// Deep copy of a YAML node (yaml-cpp nodes share by reference).
YAML::Node clone_node(const YAML::Node& n);

}  // namespace frustum
