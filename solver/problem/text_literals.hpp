// A problem's text may state its given's values literally ("the triangle A(0,0,6), B(3,0,9),
// C(0,3,9)"); a drawn variant has other values, so before a problem is drawn those literals are
// turned into the placeholders they state (A({A.0},{A.1},{A.2})), and each variant prints its
// own values. The author's brackets, spacing and separators are kept.
//
// Recognised literals (numbers: integers, decimals, 1e-3, fractions 1/2, ½ and 4½, signs - − +):
// - a run of two or more numbers separated by commas or ×, bracketed or not — (0,0,6), [1, 2],
//   200×200, ortho(−100, 100, …) — states the numbers of one list or mapping of the given in
//   order (or of consecutive whole ones: camera(eye, center, up)), or a part of a mapping's
//   fields in order (x ∈ [−100, 100] for left, right);
// - a number after "=" (near = 1), tied by its name when a field has that name, and a number
//   with a degree sign (90°): a scalar field of the given.
// A literal that states several values alike (two fields with the same value) is tied in order
// when it is mentioned as often as there are such values (R_x(30°), R_y(30°), R_z(30°)) and is
// refused otherwise; a run whose every number is a given value but that ties to no field (a
// corner computed from a window) is refused too, except the origin. A number standing alone is
// left as written (numbering, constants), and so is every literal that no given value explains.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

namespace frustum {

struct TemplatedText {
  std::string text;                  // with each recognised literal's numbers as placeholders
  std::optional<std::string> error;  // a literal that cannot be tied: why, naming it
  int tied = 0;                      // literals turned into placeholders
};

// `text` with its literal mentions of `given`'s values turned into placeholders.
TemplatedText template_literals(const std::string& text, const YAML::Node& given);

}  // namespace frustum
