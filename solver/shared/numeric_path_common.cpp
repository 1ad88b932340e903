#include "solver/shared/numeric_path_common.hpp"

namespace frustum {

std::vector<Eigen::Vector3d> double_points(const Polygon3<Exact>& p) {
  std::vector<Eigen::Vector3d> out;
  for (const Vec3<Exact>& v : p) out.push_back(to_double(v));
  return out;
}

NumericResult run_numeric(std::unique_ptr<NumericSolver> solver) {
  solver->run();
  return solver->result();
}

}  // namespace frustum
