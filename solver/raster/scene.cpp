#include "solver/raster/scene.hpp"

namespace frustum {

SceneObject box_object(double w, double h, double d) {
  SceneObject o;
  o.vertices = box_corners(w, h, d);
  const int quads[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {1, 5, 6, 2},
                           {0, 3, 7, 4}, {0, 4, 5, 1}, {3, 2, 6, 7}};
  for (const auto& q : quads) {
    o.triangles.push_back({q[0], q[1], q[2]});
    o.triangles.push_back({q[0], q[2], q[3]});
  }
  return o;
}

}  // namespace frustum
