#include "solver/shared/transform_steps.hpp"

#include <fmt/format.h>

#include "solver/input/given_reader.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/viewing_parts.hpp"

namespace frustum {

namespace {

constexpr Phrase kTranslate{"translate {0}", "平行移動 {0}", "перенос на {0}"};
constexpr Phrase kScale{"scale {0}", "拡大縮小 {0}", "масштабирование {0}"};
constexpr Phrase kRotateX{"rotate_x {0}", "x 軸まわりに {0} 回転", "поворот вокруг оси x на {0}"};
constexpr Phrase kRotateY{"rotate_y {0}", "y 軸まわりに {0} 回転", "поворот вокруг оси y на {0}"};
constexpr Phrase kRotateZ{"rotate_z {0}", "z 軸まわりに {0} 回転", "поворот вокруг оси z на {0}"};
constexpr Phrase kRotate{"rotate {0}", "{0} 回転", "поворот на {0}"};
constexpr Phrase kRotateAbout{"rotate {0} about {1}", "{1} を軸に {0} 回転",
                              "поворот на {0} вокруг {1}"};
constexpr Phrase kShear{"shear {0}", "せん断 {0}", "сдвиг {0}"};
constexpr Phrase kShearEntries{"shear (h_ij adds coordinate j to coordinate i)",
                               "せん断 (h_ij は座標 j を座標 i に加える)",
                               "сдвиг (h_ij прибавляет координату j к координате i)"};
constexpr Phrase kZeroScaleFactor{
    "a zero scale factor flattens space: the composite has no inverse",
    "拡大縮小の係数 0 は空間を押しつぶす: 合成変換は逆行列をもたない",
    "нулевой коэффициент масштабирования сплющивает пространство: у композиции нет обратной "
    "матрицы"};
constexpr Phrase kRodrigues{
    "Rodrigues' formula R = c·I + s·[u]ₓ + (1 − c)·u·uᵀ, written entry by entry, for the unit "
    "axis u = (x, y, z).",
    "Rodrigues の公式 R = c·I + s·[u]ₓ + (1 − c)·u·uᵀ を, 単位軸 u = (x, y, z) "
    "について成分ごとに書いたもの.",
    "Формула Родрига R = c·I + s·[u]ₓ + (1 − c)·u·uᵀ, записанная поэлементно для единичной оси u "
    "= (x, y, z)."};
constexpr Phrase kAxisNormalisedFirst{"The axis is normalised first: (x, y, z) = {0}.",
                                      "軸をまず正規化する: (x, y, z) = {0}.",
                                      "Сначала ось нормируется: (x, y, z) = {0}."};
constexpr Phrase kRowVectorsLeftmost{
    "DirectX multiplies row vectors: P′ = P·M, so the step applied first stands leftmost and "
    "every matrix is the transpose of its column-vector form (a translation in the bottom row, as "
    "XMMatrixTranslation builds it).",
    "DirectX は行ベクトルを掛ける: P′ = P·M なので, 最初に適用する変換が一番左に来て, "
    "どの行列も列ベクトルの形の転置になる (平行移動は最下行, XMMatrixTranslation と同じ).",
    "DirectX умножает строки-векторы: P′ = P·M, поэтому первое применяемое преобразование стоит "
    "слева, а каждая матрица — транспонированная форма для столбцов (перенос в нижней строке, как "
    "строит XMMatrixTranslation)."};
constexpr Phrase kColumnVectorsRightmost{
    "Column vectors: P′ = M·P, so the step applied first stands rightmost (P′ = A₃A₂A₁P).",
    "列ベクトル: P′ = M·P なので, 最初に適用する変換が一番右に来る (P′ = A₃A₂A₁P).",
    "Столбцы-векторы: P′ = M·P, поэтому первое применяемое преобразование стоит справа (P′ = "
    "A₃A₂A₁P)."};

// wrong_order_feedback's, for row vectors and for column vectors.
constexpr Phrase kMultipliedInReverseOrder{
    "You multiplied the steps in reverse order (…·A₂·A₁): with DirectX's row vectors, P′ = P·M, "
    "the step applied first stands leftmost, M = A₁·A₂·…",
    "逆の順に行列を掛けています (…·A₂·A₁). DirectX の行ベクトルでは P′ = P·M なので, "
    "最初に適用する変換が一番左に来ます: M = A₁·A₂·…",
    "Вы перемножили шаги в обратном порядке (…·A₂·A₁): для строк-векторов DirectX, P′ = P·M, "
    "первый шаг стоит слева, M = A₁·A₂·…"};
constexpr Phrase kMultipliedInTheOrderApplied{
    "You multiplied the steps in the order they are applied (A₁·A₂·…): with column vectors the "
    "step applied first stands rightmost, M = …·A₂·A₁ (as in P′ = A₃A₂A₁P).",
    "適用する順に行列を掛けています (A₁·A₂·…). 列ベクトルでは最初に適用する変換が一番右に来ます: M "
    "= …·A₂·A₁ (P′ = A₃A₂A₁P のように).",
    "Вы перемножили шаги в порядке применения (A₁·A₂·…): для столбцов-векторов первый шаг стоит "
    "справа, M = …·A₂·A₁ (как в P′ = A₃A₂A₁P)."};

// The inverse of one step from its kind: translations negate, scalings take reciprocals,
// rotations transpose; only a shear (rational entries) is inverted by elimination. The
// composite's inverse is then the product in reverse order, which never asks GiNaC to
// invert a matrix of nested radicals.
void invert_step(TransformStep& t, const std::string& kind) {
  const int size = static_cast<int>(t.matrix.rows());
  const int n = size - 1;
  if (kind == "translate") {
    t.inverse = t.matrix;
    for (int i = 0; i < n; ++i) t.inverse(i, n) = -t.matrix(i, n);
  } else if (kind == "scale") {
    t.inverse = MatX<Exact>::Identity(size, size);
    for (int i = 0; i < n; ++i) {
      t.det *= t.matrix(i, i);
      if (t.matrix(i, i).is_zero()) {
        t.inverse.resize(0, 0);
        return;
      }
      t.inverse(i, i) = 1 / t.matrix(i, i);
    }
  } else if (kind == "shear") {
    t.det = canonical(t.matrix.determinant());
    if (t.det.is_zero()) {
      t.inverse.resize(0, 0);
      return;
    }
    t.inverse = t.matrix.inverse();
  } else {  // rotations are orthogonal
    t.inverse = t.matrix.transpose();
  }
  t.inverse = canonical(t.inverse);
}

// c = cos θ and s = sin θ of a rotation, as substituted into its matrix.
MathText cos_sin(const Exact& radians, AngleUnit unit) {
  return tex("\\theta = ") + angle_text(radians, unit) + tex(",\\; c = \\cos\\theta = ") +
         exact(GiNaC::cos(radians)) + tex(",\\; s = \\sin\\theta = ") + exact(GiNaC::sin(radians));
}

// R_x, R_y or R_z in symbols (c = cos θ, s = sin θ), as in the lecture's homogeneous matrices.
MathText axis_rotation_formula(int axis) {
  static const char* const latex[] = {
      "R_x(\\theta) = \\begin{bmatrix} 1 & 0 & 0 & 0 \\\\ 0 & c & -s & 0 \\\\ 0 & s & c & 0 \\\\ 0 "
      "& 0 & 0 & 1 \\end{bmatrix}",
      "R_y(\\theta) = \\begin{bmatrix} c & 0 & s & 0 \\\\ 0 & 1 & 0 & 0 \\\\ -s & 0 & c & 0 \\\\ 0 "
      "& 0 & 0 & 1 \\end{bmatrix}",
      "R_z(\\theta) = \\begin{bmatrix} c & -s & 0 & 0 \\\\ s & c & 0 & 0 \\\\ 0 & 0 & 1 & 0 \\\\ 0 "
      "& 0 & 0 & 1 \\end{bmatrix}"};
  return tex(latex[axis]);
}

// Rotation by θ about the unit axis (x, y, z): Rodrigues' formula c·I + s·[u]ₓ + (1 − c)·u·uᵀ
// written entry by entry.
MathText axis_angle_formula() {
  return tex(
      "R = \\begin{bmatrix} x^2(1-c)+c & xy(1-c)-zs & xz(1-c)+ys & 0 \\\\ "
      "yx(1-c)+zs & y^2(1-c)+c & yz(1-c)-xs & 0 \\\\ xz(1-c)-ys & yz(1-c)+xs & z^2(1-c)+c & 0 \\\\ "
      "0 & 0 & 0 & 1 \\end{bmatrix}");
}

// The steps' keys, in the order messages list them.
std::vector<std::string> step_keys(bool with_shear) {
  std::vector<std::string> keys = {"translate", "scale",    "rotate_x",
                                   "rotate_y",  "rotate_z", "rotate"};
  if (with_shear) keys.push_back("shear");
  return keys;
}

}  // namespace

TransformStep read_transform_step(GivenReader& s, int dim, const Conventions& c, bool with_shear) {
  const std::vector<std::string> allowed = step_keys(with_shear);
  std::string listed, choices;  // "translate, …, shear" and "translate, …, rotate or shear"
  for (std::size_t i = 0; i < allowed.size(); ++i) {
    listed += (i ? ", " : "") + allowed[i];
    choices += (i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + allowed[i];
  }
  const std::vector<std::string> keys = s.keys();
  if (keys.size() != 1)
    s.fail(keys.empty() ? "translate" : keys[1], "each step is one of " + listed);
  const std::string& k = keys[0];
  TransformStep t;
  const std::size_t n = static_cast<std::size_t>(dim);
  if (k == "translate") {
    const std::vector<Exact> v = s.numbers(k, n);
    t.heading = say(kTranslate, vec(v).unicode);
    t.matrix = translate(v);
  } else if (k == "scale") {
    std::vector<Exact> v = s.is_list(k) ? s.numbers(k, n) : std::vector<Exact>(n, s.number(k));
    t.heading = say(kScale, vec(v).unicode);
    t.matrix = scale(v);
    for (const Exact& x : v)
      if (x.is_zero()) t.note = say(kZeroScaleFactor);
  } else if (k == "rotate_x" || k == "rotate_y" || k == "rotate_z") {
    if (dim != 3) s.fail(k, "rotations about x, y, z are 3D; in 2D use rotate");
    const Exact a = read_angle(s, k, c.angles);
    const Phrase& about = k[7] == 'x' ? kRotateX : k[7] == 'y' ? kRotateY : kRotateZ;
    t.heading = say(about, angle_text(a, c.angles).unicode);
    t.matrix = rotate_axis_index(k[7] - 'x', a);
    if (dim == 3) {
      t.formula = axis_rotation_formula(k[7] - 'x');
      t.substitution = cos_sin(a, c.angles);
    }
    t.angle = a;
    t.rotation = [axis = k[7] - 'x'](const Exact& b) { return rotate_axis_index(axis, b); };
  } else if (k == "rotate") {
    if (dim == 2) {
      const Exact a = read_angle(s, k, c.angles);
      t.heading = say(kRotate, angle_text(a, c.angles).unicode);
      t.matrix = rotate_2d(a);
      t.formula = tex(
          "R(\\theta) = \\begin{bmatrix} c & -s & 0 \\\\ s & c & 0 \\\\ 0 & 0 & 1 \\end{bmatrix}");
      t.substitution = cos_sin(a, c.angles);
      t.angle = a;
      t.rotation = [](const Exact& b) { return rotate_2d(b); };
    } else {
      GivenReader r = s.child(k, {"axis", "angle"});
      const Vec3<Exact> axis = r.vector<3>("axis");
      if (canonical(axis.dot(axis)).is_zero()) r.fail("axis", "the zero vector is not an axis");
      const Exact a = read_angle(r, "angle", c.angles);
      r.finish();
      const Vec3<Exact> u = unit(axis);
      t.heading = say(kRotateAbout, angle_text(a, c.angles).unicode, vec(axis).unicode);
      t.matrix = rotate_about(u, a);
      t.formula = axis_angle_formula();
      t.substitution = math("(x, y, z) = ") + vec(u, true) + tex(",\\; ") + cos_sin(a, c.angles) +
                       tex(",\\; 1 - c = ") + exact(canonical(1 - GiNaC::cos(a)));
      t.note = say(kRodrigues);
      t.angle = a;
      t.rotation = [u](const Exact& b) { return rotate_about(u, b); };
      if (!canonical(axis.dot(axis) - 1).is_zero())
        t.note += say(kAxisNormalisedFirst, vec(axis).unicode + " / " + exact(norm(axis)).unicode);
    }
  } else if (k == "shear" && with_shear) {
    MatX<Exact> h = MatX<Exact>::Zero(dim, dim);
    if (dim == 2) {
      const std::vector<Exact> v = s.numbers(k, 2);
      h(0, 1) = v[0];
      h(1, 0) = v[1];
      t.heading = say(
          kShear, "x′ = x + " + exact(v[0]).unicode + "·y, y′ = y + " + exact(v[1]).unicode + "·x");
    } else {
      GivenReader r = s.child(k, {"xy", "xz", "yx", "yz", "zx", "zy"});
      const std::string names = "xyz";
      for (const std::string f : {"xy", "xz", "yx", "yz", "zx", "zy"})
        if (r.has(f))
          h(static_cast<int>(names.find(f[0])), static_cast<int>(names.find(f[1]))) = r.number(f);
      r.finish();
      t.heading = say(kShearEntries);
    }
    t.matrix = shear(h);
  } else {
    s.fail(k, "unknown step: use " + choices);
  }
  s.finish();
  t.matrix = canonical(t.matrix);
  invert_step(t, k);
  return t;
}

Said wrong_order_feedback(Api api) {
  return say(api == Api::DirectX ? kMultipliedInReverseOrder : kMultipliedInTheOrderApplied);
}

std::vector<TransformStep> read_transform_steps(GivenReader& r, const std::string& key, int dim,
                                                const Conventions& c,
                                                const TransformStepList& list) {
  std::vector<TransformStep> out;
  const std::size_t n = r.list_size(key, list.min_count, list.max_count);
  for (std::size_t i = 0; i < n; ++i) {
    GivenReader s = r.item(key, i, step_keys(list.shear));
    out.push_back(read_transform_step(s, dim, c, list.shear));
  }
  return out;
}

namespace {

MatX<Exact> compose(const std::vector<TransformStep>& steps, int dim, Api api,
                    const std::string& name, const Said& title, Derivation* derivation) {
  const bool rows = api == Api::DirectX;
  MatX<Exact> m = MatX<Exact>::Identity(dim + 1, dim + 1);
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const TransformStep& s = steps[i];
    m = canonical(then_apply(m, s.matrix));
    if (derivation) {
      // Row vectors: the symbolic forms are the column-vector ones, so only the values show.
      Step& st = derivation->add(
          say(kStepTitle, i + 1, s.heading), rows ? MathText{} : s.formula, s.substitution,
          tex(fmt::format("A_{{{}}} = ", i + 1)) + matrix_text(paper_form(s.matrix, api)));
      st.note = s.note;
    }
  }
  if (derivation) {
    // Column vectors: M = Aₙ·…·A₁; DirectX's row vectors: M = A₁·…·Aₙ (each Aᵢ transposed).
    std::string order;  // A_3\,A_2\,A_1, read as A₃·A₂·A₁
    for (std::size_t k = 1; k <= steps.size(); ++k) {
      const std::size_t i = rows ? k : steps.size() + 1 - k;
      order += fmt::format("{}A_{{{}}}", k == 1 ? "" : "\\,", i);
    }
    derivation
        ->add(title, tex(name + " = " + order), {},
              math(name + " = ") + matrix_text(paper_form(m, api)))
        .note = say(rows ? kRowVectorsLeftmost : kColumnVectorsRightmost);
  }
  return m;
}

}  // namespace

MatX<Exact> compose_with_steps(const std::vector<TransformStep>& steps, int dim, Api api,
                               const std::string& name, const Phrase& title,
                               Derivation* derivation) {
  return compose(steps, dim, api, name, say(title), derivation);
}

}  // namespace frustum
