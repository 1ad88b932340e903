#include "solver/shared/accuracy_draws.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <vector>

#include "solver/numeric/condition.hpp"

namespace frustum::accuracy {

std::string decimal(Rng& rng, int lo, int hi) {
  const std::int64_t k = rng.integer(lo * 100, hi * 100);
  return fmt::format("{}{}.{:02d}", k < 0 ? "-" : "", std::abs(k) / 100, std::abs(k) % 100);
}

Eigen::Vector3d Point3::d() const { return {std::stod(x), std::stod(y), std::stod(z)}; }

std::string Point3::yaml() const { return "[" + x + ", " + y + ", " + z + "]"; }

Point3 point(Rng& rng, int lo, int hi) {
  return {decimal(rng, lo, hi), decimal(rng, lo, hi), decimal(rng, lo, hi)};
}

std::string triangle_yaml(const std::array<Point3, 3>& t) {
  return "[" + t[0].yaml() + ", " + t[1].yaml() + ", " + t[2].yaml() + "]";
}

std::optional<std::array<Point3, 3>> well_conditioned_triangle(Rng& rng) {
  const std::array<Point3, 3> t = {point(rng, -9, 9), point(rng, -9, 9), point(rng, -9, 9)};
  if (normal_condition({t[0].d(), t[1].d(), t[2].d()}) > kWellConditioned) return std::nullopt;
  return t;
}

TriangleAndPixel triangle_and_pixel(Rng& rng) {
  TriangleAndPixel d;
  for (Point3& q : d.triangle) q = {decimal(rng, 0, 20), decimal(rng, 0, 20), decimal(rng, 1, 20)};
  d.pixel = Eigen::Vector2d(static_cast<double>(rng.integer(0, 20)),
                            static_cast<double>(rng.integer(0, 20)));
  return d;
}

std::string TriangleAndPixel::yaml() const {
  return fmt::format("{{triangle: {}, pixel: [{}, {}]}}", triangle_yaml(triangle), pixel.x(),
                     pixel.y());
}

}  // namespace frustum::accuracy
