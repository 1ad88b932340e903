// Reading the given of the clipping kinds: points of 2 or 3 components, and the `window`
// {xmin, xmax, ymin, ymax} of 2D problems or the `volume` {xmin, …, zmax} of 3D ones (the
// API's NDC volume when absent: [−1, 1]³, or z ∈ [0, 1] under DirectX).
#pragma once

#include <string>
#include <vector>

#include "solver/clipping/clip_box.hpp"
#include "solver/derivation/math_text.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/util/said.hpp"

namespace frustum::clip_given {

// The titles of the step that states the region.
inline constexpr Phrase kRegionClipWindow{"Clip window", "クリップウィンドウ", "Окно отсечения"};
inline constexpr Phrase kRegionClipVolume{"Clip volume", "クリップ領域", "Объём отсечения"};
inline constexpr Phrase kRegionDefaultVolumeDirectX{
    "Clip volume (default: DirectX's NDC volume, z in [0, 1])",
    "クリップ領域 (既定: DirectX の正規化視体積, z は [0, 1])",
    "Объём отсечения (по умолчанию: нормализованный объём DirectX, z в [0, 1])"};
inline constexpr Phrase kRegionDefaultVolumeCube{"Clip volume (default: the NDC cube)",
                                                 "クリップ領域 (既定: 正規化視体積の立方体)",
                                                 "Объём отсечения (по умолчанию: куб NDC)"};

// 2 or 3: the length of the list at `key` (a point).
inline int point_dims(GivenReader& r, const std::string& key) {
  const YAML::Node& root = r.node();
  const YAML::Node n = root[key];
  if (n.IsDefined() && n.IsSequence() && (n.size() == 2 || n.size() == 3))
    return static_cast<int>(n.size());
  if (!r.has(key)) r.numbers(key, 2);  // "missing required field"
  r.fail(key, "expected a point of 2 or 3 numbers");
}

// A box read from a mapping with fields lo/hi per axis; each lower bound below its upper one.
template <int N>
ClipBox<Exact, N> read_box(GivenReader& r, const std::string& key) {
  static const char* lo_names[3] = {"xmin", "ymin", "zmin"};
  static const char* hi_names[3] = {"xmax", "ymax", "zmax"};
  std::vector<std::string> fields;
  for (int a = 0; a < N; ++a) {
    fields.push_back(lo_names[a]);
    fields.push_back(hi_names[a]);
  }
  GivenReader b = r.child(key, fields);
  ClipBox<Exact, N> box;
  for (int a = 0; a < N; ++a) {
    box.lo(a) = b.number(lo_names[a]);
    box.hi(a) = b.number(hi_names[a]);
  }
  for (int a = 0; a < N; ++a)
    if (exact_sign(box.hi(a) - box.lo(a)) <= 0)
      b.fail(lo_names[a], std::string(lo_names[a]) + " must be less than " + hi_names[a] +
                              " (got " + exact(box.lo(a)).unicode + " ≥ " +
                              exact(box.hi(a)).unicode + ")");
  b.finish();
  return box;
}

// The region of a problem: `window` for 2D points, `volume` (default NDC cube) for 3D ones.
struct Region {
  int dims = 2;
  ClipBox<Exact, 2> window;
  ClipBox<Exact, 3> volume;
  bool default_volume = false;
  Api api = Api::OpenGL;

  // The title of the derivation's step that states the region.
  Said title() const {
    if (dims == 2) return say(kRegionClipWindow);
    if (!default_volume) return say(kRegionClipVolume);
    return say(api == Api::DirectX ? kRegionDefaultVolumeDirectX : kRegionDefaultVolumeCube);
  }
};

inline Region read_region(GivenReader& r, int dims, const std::string& points_field, Api api) {
  Region g;
  g.dims = dims;
  g.api = api;
  if (dims == 2) {
    if (r.has("volume"))
      r.fail("volume", "the " + points_field + " are 2D: give a `window` {xmin, xmax, ymin, ymax}");
    g.window = read_box<2>(r, "window");
  } else {
    if (r.has("window"))
      r.fail("window", "the " + points_field +
                           " are 3D: give a `volume` {xmin, xmax, ymin, ymax, zmin, zmax} "
                           "(default: the NDC cube)");
    g.default_volume = !r.has("volume");
    g.volume = g.default_volume ? ndc_volume<Exact>(api) : read_box<3>(r, "volume");
  }
  return g;
}

// "xmin = 0, xmax = 4, ymin = 0, ymax = 3"
template <int N>
MathText box_text(const ClipBox<Exact, N>& b) {
  MathText m;
  for (int a = 0; a < N; ++a) {
    const std::string x = axis_name(a);
    if (a) m += tex(",\\; ");
    m +=
        tex(x + "_{\\min} = ") + exact(b.lo(a)) + tex(",\\; " + x + "_{\\max} = ") + exact(b.hi(a));
  }
  return m;
}

}  // namespace frustum::clip_given
