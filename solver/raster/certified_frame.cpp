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

FrameCertifier::FrameCertifier(const Scene& scene, Mat4<Exact> clip_from_world)
    : scene_(scene),
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
  if (const std::optional<Outcome<R>> ranged =
          window_polygon<R>(clip, scene_, R(kClipEpsilon, 0))) {
    take(*ranged, out);
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
  for_each_world_triangle(
      scene,
      [&](const WorldTriangle& world) {
        window.clear();
        stage.add(world, source++, window);
        for (std::size_t fan = 0; fan < window.size(); ++fan) {
          const WindowTriangle& w = window[fan];
          FrameCertifier::Piece piece{world.object, world.face, static_cast<int>(fan), {}};
          setup_triangle({Vec2<double>(w.v[0](0), w.v[0](1)), Vec2<double>(w.v[1](0), w.v[1](1)),
                          Vec2<double>(w.v[2](0), w.v[2](1))},
                         piece.setup);
          const TriangleSetup& s = piece.setup;
          if (s.degenerate) continue;
          const std::array<R, 3> z{R(w.v[0](2), w.depth_error), R(w.v[1](2), w.depth_error),
                                   R(w.v[2](2), w.depth_error)};
          const int j0 = std::max(s.j_min, 0),
                    j1 = std::min(s.j_max, static_cast<int>(rows.size()) - 1);
          for (int j = j0; j <= j1; ++j) {
            std::vector<Pixel>& row = rows[static_cast<std::size_t>(j)];
            auto p = std::lower_bound(row.begin(), row.end(), s.i_min,
                                      [](const Pixel& q, int i) { return q.i < i; });
            for (; p != row.end() && p->i <= s.i_max; ++p) {
              if (!covers(s, p->i, j)) continue;
              // Written when z < stored: the ranged difference, else the exact depths.
              const R depth = depth_at_centre<R>(s, z, p->i, j);
              const SignDecision d = decide_sign(R(depth - p->z), [&] {
                return certifier.exact_depth_sign(piece, p->piece, p->i, j);
              });
              p->exact = p->exact || d.exact;
              if (d.sign < 0) {
                p->z = depth;
                p->piece = piece;
                p->color = w.color;
              }
            }
          }
        }
      },
      true);
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
