// The pictures of `frustum draw`, as SVG documents (solver/derivation/svg.hpp):
// - hidden lines of a mesh: every edge projected from the eye, visible spans solid,
//   silhouette edges bold, covered spans (hidden edges, and parts of edges that other faces
//   cover) dashed, vertex numbers beside the vertices;
// - the painter's result next to the z-buffer's, pixels where they differ outlined in red.
#pragma once

#include <cstdint>
#include <string>

#include "solver/util/said.hpp"
#include "solver/viewing/conventions.hpp"
#include "solver/visibility/drawable.hpp"
#include "solver/visibility/hidden_lines.hpp"

namespace frustum {

struct PictureOptions {
  Api api = Api::OpenGL;
  std::string title;  // first caption line (e.g. the problem's id)
  int raster = 48;    // painter vs z-buffer: window size in pixels
  std::int64_t max_hidden_line_pairs = kMaxHiddenLinePairs;  // hidden_lines.hpp
  Lang lang = Lang::En;  // the captions, the <title> and the summary (the title above as given)
};

struct Picture {
  std::string svg;
  std::string summary;  // one line: what was drawn (counts), in the options' language
};

// Throws DomainError("eye") when a vertex is not in front of the eye, or as depth_sort does.
Picture draw_picture(const Drawable& d, const PictureOptions& o);

}  // namespace frustum
