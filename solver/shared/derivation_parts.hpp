// Derivation pieces several kinds share: a polygon's normal with its warnings, a plane scaled to
// the form written on paper, and a student's earlier answers carried forward.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "solver/core/matrix.hpp"
#include "solver/derivation/derivation.hpp"
#include "solver/derivation/value.hpp"
#include "solver/problem/kind.hpp"

namespace frustum {

// Step titles several kinds write.
inline constexpr Phrase kWindingLeftHanded{
    "Winding in a left-handed frame", "左手系での頂点の回り順", "Порядок обхода в левой системе"};
inline constexpr Phrase kRightHandedReading{"The right-handed reading", "右手系で読むと",
                                            "Прочтение в правой системе"};
inline constexpr Phrase kIllConditionedNormal{"Ill-conditioned normal", "条件の悪い法線",
                                              "Плохо обусловленная нормаль"};

// Phrases of the normal's steps and of its mistakes that several of these files say (the
// grader names a mistake's step by the title the derivation gives it). In a namespace of their
// own, said qualified (kind_words::kNormalTitle), so no kind's own phrase of the same name clashes.
namespace kind_words {
inline constexpr Phrase kNormalTitle{"Normal", "法線", "Нормаль"};
inline constexpr Phrase kNormalLeftHandedTitle{
    "Normal (left-handed: n = e₁ × e₀, counter-clockwise = front)",
    "法線 (左手系: n = e₁ × e₀, 反時計回り = 表)",
    "Нормаль (левая система: n = e₁ × e₀, против часовой стрелки = лицевая)"};
inline constexpr Phrase kNormalRightHandedTitle{
    "Normal (n = e₀ × e₁, counter-clockwise = front)", "法線 (n = e₀ × e₁, 反時計回り = 表)",
    "Нормаль (n = e₀ × e₁, против часовой стрелки = лицевая)"};
inline constexpr Phrase kUnitNormalTitle{"Unit normal", "単位法線", "Единичная нормаль"};
inline constexpr Phrase kReversedCrossProduct{"reversed cross product", "外積の順序が逆",
                                              "обратный порядок векторного произведения"};
inline constexpr Phrase kYouTook{"You took {0}.", "{0} を計算しています.", "Вы взяли {0}."};
}  // namespace kind_words

// Normal of a polygon, counter-clockwise = front: e_0 × e_1 for a triangle (seed 003),
// Newell's method for more vertices. Records the steps and warnings (degenerate, nearly
// parallel or zero edges, non-planar) when `steps` is set. Throws DomainError on a
// degenerate polygon, naming `field`.
// The polygon listed the other way round from p₀ (p₀, pₙ₋₁, …, p₁): its right-handed normal is
// the left-handed front normal of the original (the numeric paths compute it so).
Polygon3<Exact> reversed_winding(const Polygon3<Exact>& p);

// `left_handed`: the coordinates are left-handed, so the front (counter-clockwise) side's
// normal is e₁ × e₀ (Newell's sum negated), and the step says how it relates to e₀ × e₁.
Vec3<Exact> polygon_normal_with_steps(const Polygon3<Exact>& p, const std::string& field,
                                      Derivation* steps, bool left_handed = false);

// Whether the pixel is inside the closed triangle, from the x, y of its vertices: the signs of
// the edge functions E_AB, E_BC, E_CA at the pixel agree (0 = on an edge). Records the step
// when `steps` is set (depth_at_pixel, barycentric); `z_from` names what still gives an outside
// pixel its z in the note (the plane, or the interpolation).
enum class ZFrom { Plane, Interpolation };
bool inside_triangle_with_steps(const std::array<Vec3<Exact>, 3>& triangle,
                                const Vec2<Exact>& pixel, Derivation* steps,
                                ZFrom z_from = ZFrom::Plane);

// The plane n·p = d scaled the way a teacher writes it: integer coefficients without a common
// factor when possible (x + y − z = −6), the orientation of n kept. by_quotients: the plain
// reading, canonical() of every coefficient over the first (the reference of its fast path).
std::array<Exact, 4> paper_plane(const Vec3<Exact>& n, const Exact& d, bool by_quotients = false);

// A plane as an answer: [a, b, c, d] of ax + by + cz = d, shown as its equation.
Value plane_answer(const std::array<Exact, 4>& plane);

// Error carried forward of the plane method: the plane with the student's normal n through
// whichever of `points` the student's own plane (`student`, [a, b, c, d], if any) passes
// through — any vertex is the method — else through the first.
std::array<Exact, 4> carried_plane(const Vec3<Exact>& n, const std::vector<Vec3<Exact>>& points,
                                   const std::optional<std::vector<Exact>>& student);

// The named mistake of a plane's constant on the wrong side (the form ax + by + cz + d = 0 taken
// for ax + by + cz = d, or a list [a, b, c, d] written in it): the plane n·p = −d, scaled as on
// paper. Nothing when d = 0, where both forms are the same plane. `point` names the point the
// plane passes through (d = n·A); `step` is the title of the derivation step where it goes wrong
// (as that step says it).
std::optional<Misconception> constant_sign_mistake(const Vec3<Exact>& n, const Exact& d,
                                                   const std::string& point, const Said& step);

// Unit vector n/|n| (exact, canonical).
Vec3<Exact> unit(const Vec3<Exact>& n);

// n̂ = n / ‖n‖ with its step (‖n‖ shown exactly, 9√3 ≈ 15.59), yielding "unit_normal".
Vec3<Exact> unit_normal_with_steps(const Vec3<Exact>& n, Derivation* steps);

// The same step for a unit normal u = n/‖n‖ computed by the caller.
void record_unit_normal(const Vec3<Exact>& n, const Vec3<Exact>& u, Derivation* steps);

// A student's earlier answer usable for error carried forward: present, exact, of the given
// number of components, and not all zero (a zero normal makes later parts trivial).
// Error carried forward of a transform's points: the given points moved by the student's own
// `matrix` (n × n, as printed in the set's API), nothing when there is none or a point goes to
// infinity under it.
std::optional<Value> carried_points(const Answers& student,
                                    const std::vector<std::vector<Exact>>& points, std::size_t n,
                                    Api api);

std::optional<std::vector<Exact>> carried(const Answers& student, const std::string& name,
                                          std::size_t size);

// Error carried forward of an inverse: the inverse of the student's own n × n `name` as written
// (in either API's form the inverse of the written matrix is the written inverse); nothing when
// there is none or it is singular. Exact when every entry is rational; otherwise by LU in double
// precision, within the grader's tolerance of the exact inverse (the student's radicals are not
// inverted exactly: their size is the student's to choose).
std::optional<Value> carried_inverse(const Answers& student, const std::string& name,
                                     std::size_t n);

// A warning that an answer is ill-conditioned (κ above kIllConditioned in condition.hpp):
// `sentence` ("The normal's direction is ill-conditioned ({0}).") with the condition estimate
// and the digits float, double and long double would keep in its slot.
void warn_condition(Derivation* steps, double kappa, const Said& title, const Phrase& sentence);

// "p0, p1, p2" style names.
std::string point_name(const std::string& stem, std::size_t i);

}  // namespace frustum

namespace frustum {

class GivenReader;

// Which edge vectors a normal is the cross product of, as in seed 001's AC × AB.
struct CrossOrder {
  std::string first = "AB";
  std::string second = "AC";
};

// Reads `cross: [AC, AB]` (each an ordered pair of distinct vertex names A, B, C).
CrossOrder read_cross(GivenReader& r, const std::string& key, CrossOrder fallback);

// The normal computed with the cross product's factors swapped (−n, and its unit normal), for a
// triangle's normal by e₀ × e₁ (e₁ × e₀ in left-handed coordinates) or by a named `order`
// (AB × AC): what it says and where. Nothing for a normal the problem gives or a polygon of more
// vertices (Newell's sum, no one cross product to swap).
std::optional<Misconception> reversed_normal_mistake(const Vec3<Exact>& n, std::size_t vertices,
                                                     bool left_handed,
                                                     const std::optional<CrossOrder>& order);

// The edge vector XY = Y − X of triangle ABC.
Vec3<Exact> named_edge(const std::string& name, const std::array<Vec3<Exact>, 3>& abc);

// The vertex indices {X₀, Y₀, X₁, Y₁} of a cross order first = X₀Y₀, second = X₁Y₁.
std::array<int, 4> cross_indices(const CrossOrder& order);

// n = first × second of triangle ABC (first = Y₀ − X₀, second = Y₁ − X₁) in any scalar: the one
// formula of the exact solve (cross_normal_with_steps) and of the numeric paths.
template <typename T, typename Points>
Vec3<T> cross_order_normal(const Points& abc, const std::array<int, 4>& o) {
  const Vec3<T> first = abc[o[1]] - abc[o[0]], second = abc[o[3]] - abc[o[2]];
  return first.cross(second);
}

// n = first × second with its steps ("AC = C − A = (0, 3, 3)" ...).
// Refuses a triangle whose plane is parallel to the z axis (c = 0 in ax + by + cz = d): no single
// depth above a pixel. Shared by the exact and numeric solves of depth_at_pixel.
[[noreturn]] void refuse_edge_on_triangle(const std::string& field);

Vec3<Exact> cross_normal_with_steps(const std::array<Vec3<Exact>, 3>& abc, const CrossOrder& order,
                                    const std::string& field, Derivation* steps);

}  // namespace frustum
