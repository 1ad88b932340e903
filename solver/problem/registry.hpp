// The registry of problem kinds: one place that lists every kind, built explicitly (no
// static-initialisation tricks that a linker may drop).
#pragma once

#include <string>
#include <vector>

#include "solver/problem/kind.hpp"

namespace frustum {

class Registry {
 public:
  void add(KindInfo kind);
  const KindInfo* find(const std::string& name) const;
  std::vector<std::string> names() const;
  const std::vector<KindInfo>& all() const { return kinds_; }

 private:
  std::vector<KindInfo> kinds_;
};

// Every built-in kind.
const Registry& builtin_kinds();

// One function per kind file, called by builtin_kinds().
KindInfo vectors_kind();
KindInfo normal_kind();
KindInfo plane_kind();
KindInfo depth_at_pixel_kind();
KindInfo backface_kind();
KindInfo transform_kind();
KindInfo look_at_kind();
KindInfo projection_matrix_kind();
KindInfo project_point_kind();
KindInfo projection_plane_kind();
KindInfo view_volume_kind();
KindInfo viewport_kind();
KindInfo clip_line_kind();
KindInfo clip_polygon_kind();
KindInfo scan_convert_kind();
KindInfo zbuffer_kind();
KindInfo edge_visibility_kind();
KindInfo depth_sort_kind();
KindInfo render_kind();
KindInfo statements_kind();

}  // namespace frustum
