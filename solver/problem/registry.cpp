#include "solver/problem/registry.hpp"

#include <stdexcept>

namespace frustum {

const AnswerSpec* KindInfo::answer(const std::string& n) const {
  for (const AnswerSpec& a : answers)
    if (a.name == n) return &a;
  return nullptr;
}

void Registry::add(KindInfo kind) {
  if (find(kind.name)) throw std::logic_error("kind registered twice: " + kind.name);
  kinds_.push_back(std::move(kind));
}

const KindInfo* Registry::find(const std::string& name) const {
  for (const KindInfo& k : kinds_)
    if (k.name == name) return &k;
  return nullptr;
}

std::vector<std::string> Registry::names() const {
  std::vector<std::string> out;
  for (const KindInfo& k : kinds_) out.push_back(k.name);
  return out;
}

const Registry& builtin_kinds() {
  static const Registry registry = [] {
    Registry r;
    r.add(vectors_kind());
    r.add(normal_kind());
    r.add(plane_kind());
    r.add(depth_at_pixel_kind());
    r.add(backface_kind());
    r.add(transform_kind());
    r.add(look_at_kind());
    r.add(projection_matrix_kind());
    r.add(project_point_kind());
    r.add(projection_plane_kind());
    r.add(view_volume_kind());
    r.add(viewport_kind());
    r.add(clip_line_kind());
    r.add(clip_polygon_kind());
    r.add(scan_convert_kind());
    r.add(zbuffer_kind());
    r.add(edge_visibility_kind());
    r.add(depth_sort_kind());
    r.add(render_kind());
    r.add(statements_kind());
    return r;
  }();
  return registry;
}

}  // namespace frustum
