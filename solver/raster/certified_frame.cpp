#include "solver/raster/certified_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/geometry/predicates.hpp"
#include "solver/viewing/projection.hpp"

namespace frustum {

namespace {

using R = Ranged<double>;

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr double kEta = std::numeric_limits<double>::denorm_min();

Mat4<Exact> exact_product(const Mat4<Exact>& a, const Mat4<Exact>& b) {
  Mat4<Exact> m = a * b;
  for (Exact& e : m.reshaped()) e = canonical(e);
  return m;
}

// Objects in one copy of o: o itself and every copy of its descendants (flatten's numbering).
long subtree_objects(const SceneObject& o) {
  long n = 1;
  for (const SceneObject& c : o.children)
    n += (c.repeat ? c.repeat->count() : 1) * subtree_objects(c);
  return n;
}

// The object numbered `index` among `children` and their descendants (0: the first child's first
// copy), with `world` (the parents' world_from_object on entry) its own, exactly: flatten's walk
// without visiting the objects before it.
const SceneObject* locate(const std::vector<SceneObject>& children, long index,
                          Mat4<Exact>& world) {
  for (const SceneObject& c : children) {
    const long size = subtree_objects(c), copies = c.repeat ? c.repeat->count() : 1;
    if (index >= size * copies) {
      index -= size * copies;
      continue;
    }
    const long copy = index / size, within = index % size;
    if (c.repeat) {
      // Copies in index order, the last axis fastest: world · T(index · step).
      const SceneObject::Repeat& r = *c.repeat;
      const long nj = r.to[1] - r.from[1] + 1, nl = r.to[2] - r.from[2] + 1;
      const long at[3] = {r.from[0] + copy / (nj * nl), r.from[1] + (copy / nl) % nj,
                          r.from[2] + copy % nl};
      Mat4<Exact> move = Mat4<Exact>::Identity();
      for (int a = 0; a < 3; ++a) move(a, 3) = canonical(at[a] * c.exact_step(a));
      world = exact_product(world, move);
    }
    world = exact_product(world, c.exact_transform);
    return within == 0 ? &c : locate(c.children, within - 1, world);
  }
  return nullptr;
}

// The raster vertices of a decided polygon: x and y the grid points' own doubles (the fill's
// set-up snaps them to themselves), z the depths' values.
template <typename T>
void take(const Outcome<T>& o, CertifiedWindow& out) {
  out.outside = o.outside;
  out.clipped = o.clipped;
  out.front = o.front;
  out.raster.clear();
  out.depth_error = 0;
  if (o.outside) return;
  const auto scale = static_cast<double>(kSubpixelScale);
  for (std::size_t k = 0; k < o.snapped.size(); ++k) {
    double z = 0, error = 0;
    if constexpr (kIsExact<T>) {
      z = to_double(o.z[k]);
      error = 2 * kU * std::abs(z) + kEta;  // rounded once (within an ulp)
    } else {
      z = o.z[k].v;
      error = o.z[k].r;
    }
    out.raster.emplace_back(static_cast<double>(o.snapped[k].x) / scale,
                            static_cast<double>(o.snapped[k].y) / scale, z);
    out.depth_error = std::max(out.depth_error, error);
  }
  if (!std::isfinite(out.depth_error)) out.depth_error = std::numeric_limits<double>::infinity();
}

}  // namespace

void FrameCertifier::keep(std::vector<KeptWindow>&& part) {
  if (kept_.empty())
    kept_ = std::move(part);
  else
    kept_.insert(kept_.end(), part.begin(), part.end());
}

FrameCertifier::FrameCertifier(const Scene& scene, Mat4<Exact> clip_from_world)
    : keeps_(world_triangle_count(scene) <= kBandedTriangles),
      scene_(scene),
      clip_from_world_(frustum::clip_from_world(scene)),
      exact_clip_from_world_(std::move(clip_from_world)) {
  // The camera in ranged doubles from the exact inputs rounded once, the projection's entries
  // rounded once (and at most once more by --size): |C − C_exact| ≤ |C − C_R| + radius(C_R).
  const Camera& cam = scene.camera;
  auto input = [](const Vec3d& v) {
    return Vec3<R>(R::input(v(0)), R::input(v(1)), R::input(v(2)));
  };
  const MatX<R> eye_from_world = look_at<R>(input(cam.eye), input(cam.center), input(cam.up),
                                            scene.left_handed ? Api::DirectX : scene.api);
  MatX<R> clip_from_eye(4, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double v = scene.clip_from_eye(i, j);
      clip_from_eye(i, j) = R(v, 8 * kU * std::abs(v) + kEta);
    }
  const MatX<R> ranged = clip_from_eye * eye_from_world;
  constexpr double kGamma4 = 4 * kU * (1 + 8 * kU);
  for (int i = 0; i < 4; ++i) {
    // Row i times (w, 1): the first three columns scale with w, the fourth with 1.
    double rows = 0, errors = 0;
    for (int j = 0; j < 3; ++j) {
      const double c = clip_from_world_(i, j);
      rows += std::abs(c);
      errors += std::abs(c - ranged(i, j).v) + ranged(i, j).r;
    }
    const double c = clip_from_world_(i, 3);
    const auto k = static_cast<std::size_t>(i);
    alpha_[k] = (kGamma4 * rows + errors) * (1 + 8 * kU);
    beta_[k] = (rows + errors) * (1 + 8 * kU);
    gamma_[k] =
        (kGamma4 * std::abs(c) + std::abs(c - ranged(i, 3).v) + ranged(i, 3).r) * (1 + 8 * kU);
  }
}

const Outcome<Exact>& FrameCertifier::exact_outcome(int object, int face) {
  const auto key = std::make_pair(object, face);
  if (auto it = outcomes_.find(key); it != outcomes_.end()) return it->second;
  auto m = clip_from_object_.find(object);
  if (m == clip_from_object_.end()) {
    Mat4<Exact> world = Mat4<Exact>::Identity();
    const SceneObject* o = locate(scene_.objects, object - 1, world);
    if (!o || o->exact_vertices.size() != o->vertices.size())
      throw std::logic_error("FrameCertifier: the scene was read without its exact inputs");
    m = clip_from_object_
            .emplace(object, std::make_pair(o, exact_product(exact_clip_from_world_, world)))
            .first;
  }
  const auto& [o, clip_from_object] = m->second;
  std::array<Vec4<Exact>, 3> clip;
  for (std::size_t v = 0; v < 3; ++v) {
    const Vec3<Exact>& p = o->exact_vertices[static_cast<std::size_t>(
        o->triangles[static_cast<std::size_t>(face)][v])];
    clip[v] = clip_from_object * Vec4<Exact>(p(0), p(1), p(2), 1);
    for (int a = 0; a < 4; ++a) clip[v](a) = canonical(clip[v](a));
  }
  return outcomes_
      .emplace(key, *window_polygon<Exact>(clip, scene_, exact_from_double(kClipEpsilon)))
      .first->second;
}

bool FrameCertifier::inside_window(const std::array<Vec4<R>, 3>& clip, bool facing,
                                   CertifiedWindow& out) const {
  // Every vertex proven within every plane (w ≥ ε, −w ≤ x, y ≤ w, −w ≤ z ≤ w or 0 ≤ z ≤ w).
  const R eps(kClipEpsilon, 0);
  const bool zero = scene_.api == Api::DirectX;
  for (const Vec4<R>& c : clip) {
    const R& w = c(3);
    if (R(w - eps).proven_sign() <= 0 || R(c(0) + w).proven_sign() <= 0 ||
        R(w - c(0)).proven_sign() <= 0 || R(c(1) + w).proven_sign() <= 0 ||
        R(w - c(1)).proven_sign() <= 0 || R(w - c(2)).proven_sign() <= 0 ||
        (zero ? c(2).proven_sign() <= 0 : R(c(2) + w).proven_sign() <= 0))
      return false;
  }
  // window_polygon's divide, viewport and snap on the three vertices, and its facing.
  const auto scale = static_cast<double>(kSubpixelScale);
  std::array<Vec3<R>, 3> r;
  out.raster.clear();
  out.depth_error = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec4<R>& c = clip[k];
    const Vec3<R> ndc(R(c(0) / c(3)), R(c(1) / c(3)), R(c(2) / c(3)));
    r[k] = viewport<R>(ndc, R(scene_.width), R(scene_.height), scene_.api);
    if (window_y_down(scene_.api)) r[k](1) = R(R(scene_.height) - r[k](1));
    const std::optional<std::int64_t> x = decided_snap(r[k](0)), y = decided_snap(r[k](1));
    if (!x || !y || !std::isfinite(r[k](2).r)) return false;
    out.raster.emplace_back(static_cast<double>(*x) / scale, static_cast<double>(*y) / scale,
                            r[k](2).v);
    out.depth_error = std::max(out.depth_error, r[k](2).r);
  }
  const R area = R(R(r[1](0) - r[0](0)) * R(r[2](1) - r[0](1))) -
                 R(R(r[1](1) - r[0](1)) * R(r[2](0) - r[0](0)));
  const int sign = facing ? area.proven_sign() : 1;
  if (sign == 0) return false;
  out.outside = out.clipped = out.exact = false;
  out.front = scene_.api == Api::OpenGL ? sign > 0 : sign < 0;
  return true;
}

void FrameCertifier::window(const WorldTriangle& t, CertifiedWindow& out) {
  // The clip coordinates as the stage computes them, each with its proven radius.
  std::array<Vec4<R>, 3> clip;
  for (int v = 0; v < 3; ++v) {
    const Vec3d& p = t.v[static_cast<std::size_t>(v)];
    const Vec4d c = clip_from_world_ * Vec4d(p(0), p(1), p(2), 1.0);
    const double size = std::max({std::abs(p(0)), std::abs(p(1)), std::abs(p(2))});
    for (std::size_t i = 0; i < 4; ++i)
      clip[static_cast<std::size_t>(v)](static_cast<int>(i)) =
          R(c(static_cast<int>(i)),
            (alpha_[i] * (size + t.error) + beta_[i] * t.error + gamma_[i]) * (1 + 8 * kU) + kEta);
  }
  // Facing changes the image only through culling and the light: without either, a face
  // exactly edge-on (its sign unprovable) needs no exact arithmetic.
  const bool facing = t.cull == Cull::Back || scene_.light.has_value();
  if (inside_window(clip, facing, out)) return;
  if (!out.scratch) out.scratch = std::make_shared<Outcome<R>>();
  Outcome<R>& ranged = *static_cast<Outcome<R>*>(out.scratch.get());
  if (window_polygon_into<R>(clip, scene_, R(kClipEpsilon, 0), ranged, facing)) {
    take(ranged, out);
    out.exact = false;
    return;
  }
  const std::lock_guard<std::mutex> lock(mu_);
  take(exact_outcome(t.object, t.face), out);
  out.exact = true;
}

int FrameCertifier::exact_depth_sign(const Piece& a, const Piece& b, int i, int j) {
  const std::lock_guard<std::mutex> lock(mu_);
  auto depth = [&](const Piece& p) {
    if (p.object < 0) return Exact(1);
    return depth_at_centre<Exact>(p.setup, fan_depths(exact_outcome(p.object, p.face).z, p.fan), i,
                                  j);
  };
  return exact_sign(canonical(depth(a) - depth(b)));
}

void repair_undecided(const Scene& scene, Frame& frame, FrameCertifier& certifier) {
  // The undecided pixels, row by row, each once, and their certified state.
  struct Pixel {
    int i = 0;
    R z{1, 0};
    FrameCertifier::Piece piece;  // object −1: the cleared buffer
    Rgb color;
    bool exact = false;
  };
  std::vector<std::vector<Pixel>> rows(frame.ties.size());
  long count = 0;
  for (std::size_t j = 0; j < frame.ties.size(); ++j) {
    std::vector<int>& marks = frame.ties[j];
    std::sort(marks.begin(), marks.end());
    marks.erase(std::unique(marks.begin(), marks.end()), marks.end());
    for (const int i : marks) rows[j].push_back({i, R(1, 0), {}, scene.background, false});
    count += static_cast<long>(marks.size());
    marks.clear();
  }
  certifier.check.pixels += count;
  if (count == 0) return;
  GeometryStage stage(scene, &certifier);
  std::vector<WindowTriangle> window;
  int source = 0;
  // Whether a triangle inside the view volume by its doubles can cover an undecided pixel: its
  // raster box from the doubles, widened by two pixels (its certified vertices are within
  // rounding of them and snap by at most 1/512 pixel; a clip the doubles do not see only cuts
  // it smaller).
  const Mat4d clip_from = clip_from_world(scene);
  auto may_cover = [&](const WorldTriangle& t) {
    const std::array<Vec4d, 3> clip{to_clip(clip_from, t.v[0]), to_clip(clip_from, t.v[1]),
                                    to_clip(clip_from, t.v[2])};
    if (!inside_volume(clip, scene.api)) return true;  // clipped or outside: certified below
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Vec4d& c : clip) {
      const Vec3d r = to_raster(perspective_divide(c), scene.width, scene.height, scene.api);
      x0 = std::min(x0, r(0));
      x1 = std::max(x1, r(0));
      y0 = std::min(y0, r(1));
      y1 = std::max(y1, r(1));
    }
    if (!(x0 <= x1 && y0 <= y1)) return true;  // a NaN: certified below
    const int j0 = std::max(0, static_cast<int>(std::floor(y0)) - 2),
              j1 = std::min(static_cast<int>(rows.size()) - 1, static_cast<int>(std::ceil(y1)) + 2);
    const int i0 = static_cast<int>(std::floor(x0)) - 2, i1 = static_cast<int>(std::ceil(x1)) + 2;
    for (int j = j0; j <= j1; ++j) {
      const std::vector<Pixel>& row = rows[static_cast<std::size_t>(j)];
      const auto p = std::lower_bound(row.begin(), row.end(), i0,
                                      [](const Pixel& q, int i) { return q.i < i; });
      if (p != row.end() && p->i <= i1) return true;
    }
    return false;
  };
  // One certified window triangle through the undecided pixels it covers.
  auto visit = [&](const WindowTriangle& w, const FrameCertifier::Piece& at) {
    FrameCertifier::Piece piece = at;
    setup_triangle({Vec2<double>(w.v[0](0), w.v[0](1)), Vec2<double>(w.v[1](0), w.v[1](1)),
                    Vec2<double>(w.v[2](0), w.v[2](1))},
                   piece.setup);
    const TriangleSetup& s = piece.setup;
    if (s.degenerate) return;
    const std::array<R, 3> z{R(w.v[0](2), w.depth_error), R(w.v[1](2), w.depth_error),
                             R(w.v[2](2), w.depth_error)};
    const int j0 = std::max(s.j_min, 0), j1 = std::min(s.j_max, static_cast<int>(rows.size()) - 1);
    for (int j = j0; j <= j1; ++j) {
      std::vector<Pixel>& row = rows[static_cast<std::size_t>(j)];
      auto p = std::lower_bound(row.begin(), row.end(), s.i_min,
                                [](const Pixel& q, int i) { return q.i < i; });
      for (; p != row.end() && p->i <= s.i_max; ++p) {
        if (!covers(s, p->i, j)) continue;
        // Written when z < stored: the ranged difference, else the exact depths.
        const R depth = depth_at_centre<R>(s, z, p->i, j);
        const SignDecision d = decide_sign(
            R(depth - p->z), [&] { return certifier.exact_depth_sign(piece, p->piece, p->i, j); });
        p->exact = p->exact || d.exact;
        if (d.sign < 0) {
          p->z = depth;
          p->piece = piece;
          p->color = w.color;
        }
      }
    }
  };
  if (certifier.keeps()) {
    for (const KeptWindow& k : certifier.kept()) visit(k.w, {k.object, k.face, k.fan, {}});
  } else {
    for_each_world_triangle(
        scene,
        [&](const WorldTriangle& world) {
          window.clear();
          if (!may_cover(world)) {
            ++source;
            return;
          }
          stage.add(world, source++, window);
          for (std::size_t fan = 0; fan < window.size(); ++fan)
            visit(window[fan], {world.object, world.face, static_cast<int>(fan), {}});
        },
        true);
  }
  for (std::size_t j = 0; j < rows.size(); ++j)
    for (const Pixel& p : rows[j]) {
      const std::size_t at =
          j * static_cast<std::size_t>(frame.color.width) + static_cast<std::size_t>(p.i);
      frame.color.data[at] = pack(p.color);
      if (frame.depth.data.size() == frame.color.data.size())  // a scan line's may be absent
        frame.depth.data[at] = p.piece.object < 0 ? kDepthClear : static_cast<float>(p.z.v);
      certifier.check.exact_pixels += p.exact;
    }
}

}  // namespace frustum
