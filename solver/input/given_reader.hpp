// Reads a problem's `given` mapping into typed exact values. Every error names the file,
// line, column and field; unknown or misspelled fields are errors with a suggestion.
#pragma once

#include <yaml-cpp/yaml.h>

#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "solver/core/matrix.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

// Distinct irrational values (√2, π, 2^(1/3), cos(1), a nested root) one problem's given may
// use. Exact solving works in the field they generate: k square roots make values of up to 2^k
// terms and products of 4^k term pairs, and the kinds multiply givens together (a norm of a
// cross product is of degree 4 in them), so each further atom multiplies the time: with 4 the
// worst problem measured solves in under a second, with 6 it takes minutes. Exercises use one or
// two.
inline constexpr std::size_t kMaxGivenAtoms = 4;

// Lists in a given, checked before their items are read. Any list: far above any exercise.
inline constexpr std::size_t kMaxGivenListItems = 100'000;
// Transform steps: each is an exact 4×4 product, and rotations by angles without exact cosines
// grow with every step (a few dozen steps take a fraction of a second, hundreds over a minute).
inline constexpr std::size_t kMaxTransformSteps = 32;
// Depth-sort polygons: every pair is compared exactly, so the time grows with the square of
// their number (a hundred take about a second, 2 000 would take minutes).
inline constexpr std::size_t kMaxDepthSortPolygons = 100;

SourceLocation location_of(const YAML::Node& node, const std::string& file);

class GivenReader {
 public:
  // `field` is the path of `node` for messages ("problems[2].given").
  GivenReader(YAML::Node node, std::string file, std::string field,
              std::vector<std::string> known_fields);

  bool has(std::string_view key) const;

  Exact number(std::string_view key);
  std::vector<Exact> numbers(std::string_view key, std::size_t count);
  // Item i of a list of number lists (points of a transform), count numbers long.
  std::vector<Exact> numbers_at(std::string_view key, std::size_t i, std::size_t count);
  template <int N>
  Eigen::Matrix<Exact, N, 1> vector(std::string_view key) {
    const std::vector<Exact> v = numbers(key, N);
    return Eigen::Matrix<Exact, N, 1>(Eigen::Map<const Eigen::Matrix<Exact, N, 1>>(v.data()));
  }
  // A list of 3D points with at least min_count of them.
  std::vector<Vec3<Exact>> points(std::string_view key, std::size_t min_count,
                                  std::size_t max_count = 100000);
  std::string word(std::string_view key, const std::vector<std::string>& allowed);
  std::vector<std::string> words(std::string_view key, std::size_t count);
  // A nested mapping, read with its own known fields.
  GivenReader child(std::string_view key, std::vector<std::string> known_fields);
  // A list of mappings (transform steps): its length (refused beyond max_count before any item
  // is read), and a reader for item i.
  std::size_t list_size(std::string_view key, std::size_t min_count = 1,
                        std::size_t max_count = kMaxGivenListItems);
  GivenReader item(std::string_view key, std::size_t i, std::vector<std::string> known_fields);
  // Whether the field is a list (scale: 2 or scale: [2, 3]).
  bool is_list(std::string_view key) const;
  // Names of the fields present, in file order.
  std::vector<std::string> keys() const;

  // Errors for every field that no read asked for (misspellings, leftovers).
  void finish();

  // Throws InputError located at `key` (or at the mapping when the key is absent).
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  // Location of a field path relative to this mapping ("triangle[1]"), for domain errors.
  Diagnostic locate(const std::string& path, const std::string& message) const;

  const YAML::Node& node() const { return node_; }
  const std::string& file() const { return file_; }
  // The set's own language (`lang:`), for the instructor's texts inside a given (statements).
  void set_text_lang(Lang lang) { text_lang_ = lang; }
  Lang text_lang() const { return text_lang_; }

 private:
  YAML::Node require(std::string_view key);
  // `field()` gives the node's path; it is only called when a message needs it.
  template <typename Field>
  Exact number_at(const YAML::Node& n, Field&& field) const;
  [[noreturn]] void fail_at(const YAML::Node& n, const std::string& field,
                            const std::string& message) const;
  std::string path(std::string_view key) const;

  // What the exact numbers of one problem's given have used so far; shared with the readers
  // of its nested mappings and lists.
  struct ExactInputs;
  GivenReader(YAML::Node node, std::string file, std::string field,
              std::vector<std::string> known_fields, std::shared_ptr<ExactInputs> exact);

  YAML::Node node_;
  std::string file_;
  std::string field_;
  std::vector<std::string> known_;
  std::set<std::string, std::less<>> used_;
  std::shared_ptr<ExactInputs> exact_;
  Lang text_lang_ = Lang::En;
};

// Reads one number of a YAML scalar node: integers and decimals exactly, strings as exact
// expressions ("100*sqrt(3)", "pi/3"). Throws InputError for NaN, Inf and non-numbers, and for
// an expression too complex to simplify within a work budget (solver/core/work_budget.hpp).
Exact read_number(const YAML::Node& n, const std::string& file, const std::string& field);

}  // namespace frustum
