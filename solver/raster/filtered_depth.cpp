#include "solver/raster/filtered_depth.hpp"

#include <cmath>

namespace frustum {

DrawCount draw_triangle_filtered(const TriangleSetup& t, const std::array<Exact, 3>& z,
                                 const std::string& label, FilteredDepthBuffer& depth,
                                 FrameBuffer& frame) {
  using R = Ranged<double>;
  // The vertices' depths as nearest doubles (to_double rounds correctly): within R::input's
  // radius. A depth beyond double's range has an infinite radius and is never decided by it.
  std::array<R, 3> zr;
  for (int k = 0; k < 3; ++k) {
    const double d = to_double(z[t.order[k]]);
    zr[k] = std::isfinite(d) ? R::input(d) : R(0, std::numeric_limits<double>::infinity());
  }
  const R area2 = R::input(static_cast<double>(t.area2));
  DrawCount n;
  for (const Fragment& f : rasterize(t, frame.width, frame.height)) {
    ++n.covered;
    // z = Σ zₖ·eₖ / (2·area), as interpolate() computes it exactly.
    R zf(0, 0);
    for (int k = 0; k < 3; ++k) zf += zr[k] * R::input(static_cast<double>(f.e[k]));
    zf = zf / area2;
    std::optional<Exact>& stored = depth.exact.at(f.i, f.j);
    R& stored_r = depth.approx.at(f.i, f.j);
    if (stored) {
      const int proven = (zf - stored_r).proven_sign();
      if (proven > 0) continue;  // farther
      if (proven == 0) {
        ++depth.exact_comparisons;
        if (exact_sign(interpolate(t, f, z) - *stored) >= 0) continue;  // not nearer
      }
    }
    stored = interpolate(t, f, z);
    stored_r = zf;
    depth.written.push_back(static_cast<std::size_t>(f.j) * static_cast<std::size_t>(frame.width) +
                            static_cast<std::size_t>(f.i));
    frame.at(f.i, f.j) = label;
    ++n.written;
  }
  return n;
}

}  // namespace frustum
