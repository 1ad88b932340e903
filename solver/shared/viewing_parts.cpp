#include "solver/shared/viewing_parts.hpp"

#include <fmt/format.h>

#include "solver/input/given_reader.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr Phrase kViewport{"Viewport", "ビューポート変換", "Преобразование в область просмотра"};
constexpr Phrase kViewingDirection{"Viewing direction", "視線方向", "Направление взгляда"};
constexpr Phrase kSideAxis{"Side axis", "横方向の軸", "Боковая ось"};
constexpr Phrase kTranslations{"Translations", "平行移動", "Переносы"};
constexpr Phrase kViewMatrix{"View matrix", "視野変換行列", "Матрица вида"};
constexpr Phrase kDepthGoesIntoW{"Homogeneous coordinates: the depth goes into w′",
                                 "同次座標: 奥行きを w′ に入れる",
                                 "Однородные координаты: глубина уходит в w′"};
constexpr Phrase kPerspectiveWithNoArguments{
    "perspective() with no arguments", "引数なしの perspective()", "perspective() без аргументов"};
constexpr Phrase kFrustumOfHorizontalFov{"The frustum of a horizontal field of view",
                                         "水平方向の画角による視体積",
                                         "Усечённая пирамида по горизонтальному углу обзора"};
constexpr Phrase kSameFrustumFromVerticalAngle{"The same frustum from the vertical angle",
                                               "垂直方向の画角から見た同じ視体積",
                                               "Та же пирамида через вертикальный угол"};
constexpr Phrase kFrustumOfPerspective{
    "The frustum of perspective(fovy, aspect, near, far)",
    "perspective(fovy, aspect, near, far) の視体積",
    "Усечённая пирамида видимости perspective(fovy, aspect, near, far)"};
constexpr Phrase kOpenGlWindowOrigin{"OpenGL's window origin is bottom-left, y up.",
                                     "OpenGL のウィンドウの原点は左下で y は上向き.",
                                     "В OpenGL начало окна внизу слева, y вверх."};
constexpr Phrase kDirectXWindowOrigin{
    "DirectX's window origin is top-left, y down; NDC z is already in [0, 1].",
    "DirectX のウィンドウの原点は左上で y は下向き. 正規化座標の z はすでに [0, 1] にある.",
    "В DirectX начало окна вверху слева, y вниз; z в NDC уже в [0, 1]."};
constexpr Phrase kProcessingWindowOrigin{
    "Processing's window origin is top-left with y down (its screenY); its projection negated y "
    "for its y-down world, so world y and window y both point down.",
    "Processing のウィンドウの原点は左上で y は下向き (screenY). その投影は y "
    "が下向きのワールドに合わせて y を反転するので, ワールドの y もウィンドウの y も下を向く.",
    "В Processing начало окна вверху слева, y вниз (его screenY); его проекция меняет знак y для "
    "мира с осью y вниз, так что y мира и y окна направлены вниз."};
constexpr Phrase kDirectXRowVectors{
    "DirectX multiplies row vectors, p′ = p·M: the matrix is printed in that form (the transpose "
    "of the column-vector matrix).",
    "DirectX は行ベクトルを掛ける (p′ = p·M). 行列はその形 (列ベクトルの行列の転置) で示す.",
    "DirectX умножает строки-векторы, p′ = p·M: матрица записана в этой форме (транспонированная "
    "матрица для столбцов)."};
constexpr Phrase kColumnVectors{"Column vectors, p′ = M·p.", "列ベクトル: p′ = M·p.",
                                "Столбцы-векторы: p′ = M·p."};
constexpr Phrase kEyeCenterUp{
    "eye = the camera's position, center = the point it looks at, up = the up vector.",
    "eye = カメラの位置, center = 注視点, up = 上方向ベクトル.",
    "eye — положение камеры, center — точка, на которую она смотрит, up — вектор «вверх»."};
constexpr Phrase kLeftHandedCameraLooksDownPlusZ{"Left-handed, the camera looks down +z.",
                                                 "左手系では, カメラは +z 方向を見る.",
                                                 "В левой системе камера смотрит вдоль +z."};
constexpr Phrase kRightHandedCameraRowsNegated{
    "A right-handed camera at the same place (gluLookAt, looking down −z) has the x and z rows "
    "negated: V_right = diag(−1, 1, −1, 1)·V.",
    "同じ位置の右手系のカメラ (gluLookAt, −z 方向を見る) では x と z の行の符号が逆になる: V_right "
    "= diag(−1, 1, −1, 1)·V.",
    "У камеры правой системы в том же месте (gluLookAt, взгляд вдоль −z) строки x и z меняют знак: "
    "V_right = diag(−1, 1, −1, 1)·V."};
constexpr Phrase kEachRowOfVDotsAPoint{
    "Each row of V dots a point with one camera axis after moving the eye to the origin: s·(p − "
    "eye) = s·p − s·eye.",
    "V の各行は, 視点を原点に移した後の点とカメラの軸 1 本との内積: s·(p − eye) = s·p − s·eye.",
    "Каждая строка V — скалярное произведение точки на одну ось камеры после переноса глаза в "
    "начало координат: s·(p − eye) = s·p − s·eye."};
constexpr Phrase kPointMeetsNearPlanePlusZ{
    "A point (x, y, z) in front of the eye (z > 0) meets the near plane z = n at (x_n, y_n): the "
    "projection divides by the depth z.",
    "視点の前方 (z > 0) の点 (x, y, z) は前方クリッピング面 z = n と (x_n, y_n) で交わる: "
    "投影は奥行き z で割る.",
    "Точка (x, y, z) перед глазом (z > 0) попадает на ближнюю плоскость z = n в (x_n, y_n): "
    "проекция делит на глубину z."};
constexpr Phrase kPointMeetsNearPlaneMinusZ{
    "A point (x, y, z) in front of the eye (z < 0, so −z is its depth) meets the near plane z = −n "
    "at (x_n, y_n): the projection divides by −z.",
    "視点の前方 (z < 0 なので −z が奥行き) の点 (x, y, z) は前方クリッピング面 z = −n と (x_n, "
    "y_n) で交わる (三角形の相似より). 投影は −z で割る.",
    "Точка (x, y, z) перед глазом (z < 0, так что −z — её глубина) попадает на ближнюю плоскость z "
    "= −n в (x_n, y_n): проекция делит на −z."};
constexpr Phrase kNoMatrixDividesByACoordinate{
    "No 4 × 4 matrix divides by a coordinate, but the perspective divide by w′ does: the matrix "
    "only has to put the depth into w′ and scale x_n, y_n from the window [l, r] × [b, t] to [−1, "
    "1].",
    "4 × 4 行列は座標で割ることはできないが, w′ による透視除算ならできる: 行列は奥行きを w′ "
    "に入れ, x_n, y_n を窓 [l, r] × [b, t] から [−1, 1] に拡大縮小すればよい.",
    "Никакая матрица 4 × 4 не делит на координату, а перспективное деление на w′ делит: матрице "
    "остаётся поместить глубину в w′ и перевести x_n, y_n из окна [l, r] × [b, t] в [−1, 1]."};
constexpr Phrase kProcessingDefaults{
    "Processing's defaults: without arguments perspective() uses a 60° vertical field of view and "
    "puts the eye where the window's height exactly fills it.",
    "Processing の既定値: 引数なしの perspective() は垂直方向の画角 60° を使い, "
    "ウィンドウの高さがちょうどその画角を満たす位置に視点を置く.",
    "Значения Processing по умолчанию: без аргументов perspective() берёт вертикальный угол обзора "
    "60° и ставит глаз туда, где высота окна ровно заполняет этот угол."};
constexpr Phrase kFovxSpansTheWidth{
    "Here the field of view spans the width (fovx): it sets the right edge r, and the top is r "
    "divided by the aspect ratio. perspective() takes the vertical angle fovy; both give the same "
    "frustum and the same matrix.",
    "ここでは画角は横方向 (fovx) に広がる: 右端 r を決め, 上端は r をアスペクト比で割ったもの. "
    "perspective() は縦方向の画角 fovy を取る. どちらも同じ視体積, 同じ行列を与える.",
    "Здесь угол обзора охватывает ширину (fovx): он задаёт правый край r, а верх равен r, "
    "делённому на соотношение сторон. perspective() принимает вертикальный угол fovy; оба дают "
    "один и тот же объём и одну и ту же матрицу."};
constexpr Phrase kFovyIsVertical{
    "fovy is the vertical field of view: it sets the top t, and the aspect ratio width/height "
    "widens the right edge r.",
    "fovy は垂直方向の画角: これが上端 t を決め, アスペクト比 width/height が右端 r を広げる.",
    "fovy — вертикальный угол обзора: он задаёт верх t, а соотношение сторон width/height "
    "расширяет правый край r."};
constexpr Phrase kReadAsHorizontalAngle{
    "Read as a horizontal angle, θ would give −l = r = n·tan(θ/2) and t = r·h/w = "
    "n·(h/w)·tan(θ/2).",
    "θ を水平方向の画角と読むと −l = r = n·tan(θ/2), t = r·h/w = n·(h/w)·tan(θ/2) となる.",
    "Если читать θ как горизонтальный угол, то −l = r = n·tan(θ/2) и t = r·h/w = "
    "n·(h/w)·tan(θ/2)."};
constexpr Phrase kSomeNotesWriteAspectOnTop{
    "Some notes write −b = t = n·(w/h)·tan(θ/2) beside r = n·tan(θ/2): for w ≠ h that matches "
    "neither reading of θ.",
    "r = n·tan(θ/2) と並べて −b = t = n·(w/h)·tan(θ/2) と書く資料もあるが, w ≠ h "
    "のときこれはどちらの読み方にも合わない.",
    "В некоторых материалах рядом с r = n·tan(θ/2) пишут −b = t = n·(w/h)·tan(θ/2): при w ≠ h это "
    "не соответствует ни одному прочтению θ."};
constexpr Phrase kProcessingNegatesYRow{
    "Processing negates the y row because its window's y axis points down.",
    "Processing ではウィンドウの y 軸が下向きなので, y の行の符号を反転する.",
    "Processing меняет знак строки y, потому что ось y его окна направлена вниз."};
constexpr Phrase kLeftHandedNearFarAreCoordinates{
    "Left-handed, looking down +z: z = n maps to z_ndc = −1 and z = f to +1, so near and far are "
    "also the z coordinates of their planes.",
    "左手系で +z 方向を見る: z = n は z_ndc = −1 に, z = f は +1 に写るので, near と far "
    "はそれぞれの平面の z 座標でもある.",
    "Левая система, взгляд вдоль +z: z = n переходит в z_ndc = −1, а z = f — в +1, так что near и "
    "far — это и z-координаты их плоскостей."};
constexpr Phrase kRightHandedMatrixThirdColumn{
    "The right-handed matrix (looking down −z) is this one with its third column negated: the same "
    "view volume with the z axis reversed.",
    "右手系の行列 (−z 方向を見る) はこの行列の第 3 列の符号を変えたもの: 同じ視体積で z "
    "軸の向きだけが逆である.",
    "Матрица правой системы (взгляд вдоль −z) — эта же матрица с третьим столбцом с обратным "
    "знаком: тот же видимый объём с обращённой осью z."};
constexpr Phrase kColumnVectorsNearFarToNdc{
    "Column vectors, p′ = M·p. z = −n maps to z_ndc = −1 and z = −f to +1.",
    "列ベクトル: p′ = M·p. z = −n は z_ndc = −1 に, z = −f は +1 に移る.",
    "Столбцы-векторы: p′ = M·p. z = −n переходит в z_ndc = −1, а z = −f — в +1."};
constexpr Phrase kSentenceContradictsMatrix{
    "(A sentence stating z = −n ↦ +1 contradicts this matrix; the matrix decides.)",
    "(z = −n ↦ +1 とする記述はこの行列と矛盾します. 行列の方が正しい.)",
    "(Утверждение z = −n ↦ +1 противоречит этой матрице; верна матрица.)"};
constexpr Phrase kLookingDownPlusZNdc{
    "Looking down +z, z_ndc runs from 0 at near to 1 at far.",
    "+z 方向を見るので, z_ndc は near で 0, far で 1 になる.",
    "При взгляде вдоль +z z_ndc меняется от 0 на near до 1 на far."};
constexpr Phrase kNearFarAsZCoordinates{
    "Here near and far are the z coordinates z_min = n and z_max = f, mapped to −1 and +1: the z "
    "row is +2/(z_max − z_min).",
    "ここでは near と far は z 座標 z_min = n, z_max = f で, それぞれ −1 と +1 に写る: z の行は "
    "+2/(z_max − z_min).",
    "Здесь near и far — z-координаты z_min = n и z_max = f, переходящие в −1 и +1: строка z равна "
    "+2/(z_max − z_min)."};
constexpr Phrase kGlOrthoReadsDistances{
    "OpenGL's glOrtho reads them as distances in front of an eye looking down −z (the planes z = "
    "−n and z = −f), which gives −2/(f − n) there; the two matrices differ only in the direction "
    "of the z axis.",
    "OpenGL の glOrtho はこれらを −z 方向を見る視点の前方への距離 (平面 z = −n と z = −f) "
    "として読むので, そこは −2/(f − n) になる. 二つの行列の違いは z 軸の向きだけである.",
    "glOrtho в OpenGL читает их как расстояния перед глазом, смотрящим вдоль −z (плоскости z = −n "
    "и z = −f), и даёт там −2/(f − n); две матрицы различаются только направлением оси z."};

// The mistakes of projection_mistakes: each one's name and feedback.
constexpr Phrase kFovyForFovx{"fovy for fovx", "fovx の代わりに fovy", "fovy вместо fovx"};
constexpr Phrase kUsedTheAngleAsVertical{
    "You used the angle as the vertical field of view; here it is the horizontal one (fovx).",
    "画角を縦方向として使っています. ここでは横方向の画角 (fovx) です.",
    "Вы взяли угол как вертикальный угол обзора; здесь он горизонтальный (fovx)."};
constexpr Phrase kNumbersFromDegreesAsRadians{
    "Your numbers come from using the angle in degrees as if it were radians.",
    "度で与えられた角度をラジアンとして使った値になっています.",
    "Ваши числа получены, если угол в градусах взять как радианы."};
constexpr Phrase kFovxForFovy{"fovx for fovy", "fovy の代わりに fovx", "fovx вместо fovy"};
constexpr Phrase kUsedTheAngleAsHorizontal{
    "You used the angle as the horizontal field of view; perspective() takes the vertical one "
    "(fovy).",
    "角度を水平方向の画角として使っています. perspective() が受け取るのは垂直方向の画角 (fovy) "
    "です.",
    "Вы взяли угол как горизонтальный угол обзора; perspective() принимает вертикальный (fovy)."};
constexpr Phrase kAspectRatioOnTheTop{"aspect ratio on the top", "アスペクト比を上端に掛けた",
                                      "соотношение сторон умножено на верх"};
constexpr Phrase kAspectRatioMultipliesTheTop{
    "You used −l = r = n·tan(θ/2) and −b = t = n·(w/h)·tan(θ/2): the aspect ratio multiplies the "
    "top. With r = n·tan(θ/2) the angle is horizontal and t = r·h/w; with θ vertical, t = "
    "n·tan(θ/2) and r = t·w/h.",
    "−l = r = n·tan(θ/2), −b = t = n·(w/h)·tan(θ/2) を使っています: "
    "アスペクト比が上端に掛かっています. r = n·tan(θ/2) なら画角は水平方向で t = r·h/w, θ "
    "が垂直方向なら t = n·tan(θ/2), r = t·w/h です.",
    "Вы взяли −l = r = n·tan(θ/2) и −b = t = n·(w/h)·tan(θ/2): соотношение сторон умножает верх. "
    "При r = n·tan(θ/2) угол горизонтальный и t = r·h/w; при вертикальном θ t = n·tan(θ/2) и r = "
    "t·w/h."};
constexpr Phrase kRightHandedMatrix{"right-handed matrix", "右手系の行列",
                                    "матрица правой системы"};
constexpr Phrase kUsedTheRightHandedMatrix{
    "You used the right-handed matrix (the eye looking down −z); in this course's left-handed "
    "coordinates the eye looks down +z, so the third column has the opposite sign (w′ = z).",
    "右手系の行列 (視点は −z 方向を見る) を使っています. このコースの左手系の座標では視点は +z "
    "方向を見るので, 第 3 列の符号が逆になります (w′ = z).",
    "Вы использовали матрицу правой системы (глаз смотрит вдоль −z); в левой системе координат "
    "этого курса глаз смотрит вдоль +z, поэтому третий столбец имеет обратный знак (w′ = z)."};
constexpr Phrase kZMinZMaxReadAsCoordinates{"z_min, z_max read as coordinates",
                                            "z_min, z_max を座標として読んだ",
                                            "z_min, z_max прочитаны как координаты"};
constexpr Phrase kZRowReadsCoordinates{
    "Your z row is +2/(f − n), −(f + n)/(f − n): it maps z = n to −1 and z = f to +1, reading near "
    "and far as z coordinates. Here they are distances in front of an eye looking down −z "
    "(glOrtho), so the z row is −2/(f − n), −(f + n)/(f − n).",
    "あなたの z の行は +2/(f − n), −(f + n)/(f − n) で, z = n を −1 に, z = f を +1 に写します. "
    "これは near と far を z 座標として読んだ形です. ここでは両者は −z "
    "方向を向く視点の前方への距離 (glOrtho) なので, z の行は −2/(f − n), −(f + n)/(f − n) です.",
    "Ваша строка z — +2/(f − n), −(f + n)/(f − n): она переводит z = n в −1 и z = f в +1, то есть "
    "читает near и far как координаты z. Здесь это расстояния перед глазом, смотрящим вдоль −z "
    "(glOrtho), поэтому строка z — −2/(f − n), −(f + n)/(f − n)."};
constexpr Phrase kNearFarReadAsDistances{"near, far read as distances",
                                         "near, far を距離として読んだ",
                                         "near, far прочитаны как расстояния"};
constexpr Phrase kZRowReadsDistances{
    "Your z row is glOrtho's −2/(f − n), −(f + n)/(f − n), which reads near and far as distances "
    "in front of an eye looking down −z. Here z_min = n and z_max = f are z coordinates mapped to "
    "−1 and +1, so the z row is +2/(f − n), −(f + n)/(f − n).",
    "あなたの z の行は glOrtho の −2/(f − n), −(f + n)/(f − n) で, near と far を −z "
    "方向を向く視点の前方への距離として読んでいます. ここでは z_min = n, z_max = f は −1 と +1 "
    "に写る z 座標なので, z の行は +2/(f − n), −(f + n)/(f − n) です.",
    "Ваша строка z — это −2/(f − n), −(f + n)/(f − n) из glOrtho: она читает near и far как "
    "расстояния перед глазом, смотрящим вдоль −z. Здесь z_min = n и z_max = f — координаты z, "
    "переходящие в −1 и +1, поэтому строка z — +2/(f − n), −(f + n)/(f − n)."};
constexpr Phrase kNearFarSign{"near/far sign", "near/far の符号", "знак near/far"};
constexpr Phrase kNearFarArePositiveDistances{
    "near and far are distances in front of the eye (positive); you used the planes' z coordinates "
    "−n and −f.",
    "near と far は視点の前方への距離 (正の値) です. あなたは平面の z 座標 −n と −f "
    "を使っています.",
    "near и far — расстояния перед глазом (положительные); вы взяли z-координаты плоскостей −n и "
    "−f."};

}  // namespace

Exact read_angle(GivenReader& r, const std::string& key, AngleUnit unit) {
  const Exact a = r.number(key);
  return canonical(unit == AngleUnit::Degrees ? a * GiNaC::Pi / 180 : a);
}

MathText angle_text(const Exact& radians, AngleUnit unit) {
  if (unit == AngleUnit::Degrees)
    return exact(canonical(radians * 180 / GiNaC::Pi)) + tex("{}^\\circ");
  return exact(radians) + tex("\\,\\text{rad}");
}

bool has_projection(const GivenReader& r) {
  return r.has("perspective") || r.has("frustum") || r.has("ortho");
}

namespace {

void require_positive(GivenReader& r, const std::string& key, const Exact& v,
                      const std::string& why) {
  if (exact_sign(v) <= 0) r.fail(key, "must be positive: " + why);
}

// perspective() with no arguments (Processing): fovy = π/3, aspect = width/height,
// cameraZ = (height/2)/tan(fovy/2), near = cameraZ/10, far = 10·cameraZ. The sketch's size
// defaults to Processing's size(100, 100); any of perspective()'s own arguments with it is refused
// (Processing takes all four or none).
void processing_default_perspective(GivenReader& g, ProjectionSpec& p) {
  for (const char* key : {"fovy", "fovx", "fov", "aspect", "near", "far"})
    if (g.has(key))
      g.fail(key,
             "perspective() takes all of fovy, aspect, near and far or none of them; with width "
             "and height it is Processing's perspective() with no arguments");
  const Exact w = g.has("width") ? g.number("width") : Exact(100);
  const Exact h = g.has("height") ? g.number("height") : Exact(100);
  require_positive(g, "width", w, "the sketch's width in pixels");
  require_positive(g, "height", h, "the sketch's height in pixels");
  g.finish();
  const Exact camera_z = processing_camera_z(h);
  const ProjectionSpec d =
      perspective_projection(canonical(GiNaC::Pi / 3), canonical(w / h), canonical(camera_z / 10),
                             canonical(camera_z * 10));
  p.fovy = d.fovy;
  p.aspect = d.aspect;
  p.volume = d.volume;
  p.sketch = std::make_pair(w, h);
}

}  // namespace

ProjectionSpec perspective_projection(const Exact& fovy, const Exact& aspect, const Exact& near,
                                      const Exact& far) {
  ProjectionSpec p;
  p.fovy = fovy;
  p.aspect = aspect;
  p.volume = perspective_volume(fovy, aspect, near, far);
  for (Exact* e : {&p.volume.left, &p.volume.right, &p.volume.bottom, &p.volume.top, &p.volume.near,
                   &p.volume.far})
    *e = canonical(*e);
  return p;
}

Exact processing_camera_z(const Exact& height) {
  const Exact fovy = canonical(GiNaC::Pi / 3);
  return canonical(height / 2 / GiNaC::tan(fovy / 2));
}

ProjectionSpec read_projection(GivenReader& r, const Conventions& c) {
  const int count = r.has("perspective") + r.has("frustum") + r.has("ortho");
  if (count == 0)
    r.fail("perspective", "missing required field: give perspective, frustum or ortho");
  if (count > 1)
    r.fail(r.has("perspective") ? "perspective" : "frustum",
           "give only one of perspective, frustum and ortho");
  ProjectionSpec p;
  p.unit = c.angles;
  p.left_handed = left_handed_columns(c);
  if (r.has("perspective")) {
    GivenReader g =
        r.child("perspective", {"fovy", "fovx", "fov", "aspect", "near", "far", "width", "height"});
    p.type = ProjectionSpec::Type::Perspective;
    if (g.has("width") || g.has("height") ||
        !(g.has("fovy") || g.has("fovx") || g.has("fov") || g.has("aspect") || g.has("near") ||
          g.has("far"))) {
      processing_default_perspective(g, p);
      return p;
    }
    // fovy and fovx name their axis; fov is read in the course's convention (default vertical).
    if (g.has("fovy") + g.has("fovx") + g.has("fov") != 1)
      g.fail(g.has("fovx") ? "fovx" : "fovy", "give exactly one of fovy, fovx and fov");
    const std::string key = g.has("fovy") ? "fovy" : g.has("fovx") ? "fovx" : "fov";
    const bool horizontal = key == "fovx" || (key == "fov" && c.fov == FovAxis::Horizontal);
    const Exact angle = read_angle(g, key, c.angles);
    if (exact_sign(angle) <= 0 || exact_sign(angle - GiNaC::Pi) >= 0)
      g.fail(key, c.angles == AngleUnit::Degrees ? "must be between 0° and 180° (exclusive)"
                                                 : "must be between 0 and π (exclusive)");
    p.aspect = g.number("aspect");
    require_positive(g, "aspect", *p.aspect, "the aspect ratio is width / height");
    const Exact n = g.number("near"), f = g.number("far");
    require_positive(g, "near", n, "a perspective needs the near plane in front of the eye");
    if (canonical(f - n).is_zero()) g.fail("far", "near = far: the view volume has no depth");
    require_positive(g, "far", f, "the far plane is in front of the eye");
    g.finish();
    if (horizontal) {
      // The angle spans the width: r = n·tan(fovx/2), t = r/aspect.
      p.fovx = angle;
      const Exact r = canonical(n * GiNaC::tan(angle / 2));
      p.volume = {-r, r, -r / *p.aspect, r / *p.aspect, n, f};
      p.fovy = canonical(2 * GiNaC::atan(GiNaC::tan(angle / 2) / *p.aspect));
    } else {
      p.fovy = angle;
      p.volume = perspective_volume(*p.fovy, *p.aspect, n, f);
    }
    for (Exact* e : {&p.volume.left, &p.volume.right, &p.volume.bottom, &p.volume.top})
      *e = canonical(*e);
    return p;
  }
  const bool frustum = r.has("frustum");
  p.type = frustum ? ProjectionSpec::Type::Frustum : ProjectionSpec::Type::Ortho;
  GivenReader g =
      r.child(frustum ? "frustum" : "ortho", {"left", "right", "bottom", "top", "near", "far"});
  p.volume = {g.number("left"), g.number("right"), g.number("bottom"),
              g.number("top"),  g.number("near"),  g.number("far")};
  // Looking down +z, near and far are the planes' z coordinates already.
  p.z_coordinates =
      !frustum && c.z_planes == ZPlanes::Coordinates && c.api != Api::DirectX && !p.left_handed;
  if (canonical(p.volume.right - p.volume.left).is_zero())
    g.fail("right", "left = right: the view volume has no width");
  if (canonical(p.volume.top - p.volume.bottom).is_zero())
    g.fail("top", "bottom = top: the view volume has no height");
  if (canonical(p.volume.far - p.volume.near).is_zero())
    g.fail("far", "near = far: the view volume has no depth");
  if (frustum) {
    require_positive(g, "near", p.volume.near,
                     "a perspective needs the near plane in front of the eye");
    require_positive(g, "far", p.volume.far, "the far plane is in front of the eye");
  }
  g.finish();
  return p;
}

MatX<Exact> canonical(const MatX<Exact>& m) {
  MatX<Exact> out(m.rows(), m.cols());
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) out(i, j) = canonical(m(i, j));
  return out;
}

std::vector<std::vector<Exact>> rows_of(const MatX<Exact>& m) {
  std::vector<std::vector<Exact>> rows(static_cast<std::size_t>(m.rows()));
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) rows[static_cast<std::size_t>(i)].push_back(m(i, j));
  return rows;
}

Value transform_points_with_steps(const MatX<Exact>& m,
                                  const std::vector<std::vector<Exact>>& points, const Said& title,
                                  const std::string& name, Derivation* steps, Api api) {
  if (points.empty()) return Value::null();
  std::vector<std::vector<Exact>> moved;
  for (const std::vector<Exact>& p : points) {
    moved.push_back(transform_point(m, p));
    for (Exact& x : moved.back()) x = canonical(x);
    if (steps)
      steps->add(
          title,
          api == Api::DirectX ? tex(name + "' = " + name + "\\,M") : tex(name + "' = M\\," + name),
          math(name + " = ") + vec(p), tex(name + "' = ") + vec(moved.back(), true));
  }
  if (steps) steps->yields("points");
  return Value::matrix(moved);
}

Value matrix_value(const MatX<Exact>& m) { return Value::matrix(rows_of(canonical(m))); }

MathText matrix_text(const MatX<Exact>& m) { return matrix(rows_of(canonical(m))); }

void viewport_step(Derivation* steps, Api api, const Exact& width, const Exact& height,
                   const Vec3<Exact>& window, const Vec3<Exact>* ndc) {
  if (!steps) return;
  const bool y_up = api == Api::OpenGL;
  const MathText formula =
      tex("x_w = \\frac{x + 1}{2}\\cdot\\text{width},\\; ") +
      (y_up ? tex("y_w = \\frac{y + 1}{2}\\cdot\\text{height},\\; ")
            : tex("y_w = \\frac{1 - y}{2}\\cdot\\text{height},\\; ")) +
      (api == Api::DirectX ? tex("\\text{depth} = z") : tex("\\text{depth} = \\frac{z + 1}{2}"));
  MathText given = ndc ? tex("\\text{ndc} = ") + vec(*ndc) + tex(",\\; ") : MathText{};
  given += tex("\\text{width} = ") + exact(width) + tex(",\\; \\text{height} = ") + exact(height);
  steps
      ->add(say(kViewport), formula, given, tex("(x_w, y_w, \\text{depth}) = ") + vec(window, true))
      .yields("window")
      .note = say(api == Api::OpenGL    ? kOpenGlWindowOrigin
                  : api == Api::DirectX ? kDirectXWindowOrigin
                                        : kProcessingWindowOrigin);
}

Said multiply_note(Api api) {
  return say(api == Api::DirectX ? kDirectXRowVectors : kColumnVectors);
}

void check_camera(const Vec3<Exact>& eye, const Vec3<Exact>& center, const Vec3<Exact>& up,
                  const std::string& field) {
  const Vec3<Exact> forward = center - eye;
  if (canonical(forward.dot(forward)).is_zero())
    throw DomainError(field + "center", "center = eye: the camera looks nowhere");
  const Vec3<Exact> side = forward.cross(up);
  if (canonical(side.dot(side)).is_zero())
    throw DomainError(
        field + "up",
        "up is parallel to the view direction (or zero): the camera's roll is undefined");
}

MatX<Exact> look_at_with_steps(const Vec3<Exact>& eye, const Vec3<Exact>& center,
                               const Vec3<Exact>& up, Api api, const std::string& field,
                               Derivation* steps, bool left_handed) {
  check_camera(eye, center, up, field);
  const Vec3<Exact> forward = center - eye;
  // A left-handed course takes LookAtLH's basis (DirectX's, in column form).
  const bool plus_z = api == Api::DirectX || left_handed;
  const MatX<Exact> m = canonical(look_at(eye, center, up, plus_z ? Api::DirectX : api));
  if (steps) {
    const auto row = [&](int i) { return Vec3<Exact>(m(i, 0), m(i, 1), m(i, 2)); };
    const Vec3<Exact> f = unit(forward);
    Vec3<Exact> side = plus_z ? Vec3<Exact>(up.cross(f)) : Vec3<Exact>(f.cross(up));
    for (int i = 0; i < 3; ++i) side(i) = canonical(side(i));
    // Forward, side and up, as gluLookAt (or LookAtLH) computes them, then the translations.
    steps
        ->add(
            say(kViewingDirection),
            tex("\\mathbf{f} = \\frac{\\mathbf{center} - \\mathbf{eye}}{\\lVert\\mathbf{center} - "
                "\\mathbf{eye}\\rVert}"),
            tex("\\mathbf{center} - \\mathbf{eye} = ") + vec(forward) +
                tex(",\\; \\lVert\\mathbf{center} - \\mathbf{eye}\\rVert = ") +
                exact(norm(forward), true),
            tex("\\mathbf{f} = ") + vec(f, true))
        .note = say(kEyeCenterUp);
    if (plus_z) {
      steps->add(say(kCameraAxesLeftHanded),
                 tex("\\mathbf{z} = \\mathbf{f},\\; \\mathbf{x} = "
                     "\\frac{\\mathbf{up}\\times\\mathbf{z}}{\\lVert\\mathbf{up}\\times\\mathbf{z}"
                     "\\rVert},\\; \\mathbf{y} = \\mathbf{z}\\times\\mathbf{x}"),
                 tex("\\mathbf{up}\\times\\mathbf{z} = ") + vec(side, true) +
                     tex(",\\; \\lVert\\mathbf{up}\\times\\mathbf{z}\\rVert = ") +
                     exact(norm(side), true),
                 tex("\\mathbf{x} = ") + vec(row(0)) + tex(",\\; \\mathbf{y} = ") + vec(row(1)) +
                     tex(",\\; \\mathbf{z} = ") + vec(row(2)));
      steps->add(say(kTranslations),
                 tex("\\mathbf{t} = (-\\mathbf{x}\\cdot\\mathbf{eye},\\, "
                     "-\\mathbf{y}\\cdot\\mathbf{eye},\\, -\\mathbf{z}\\cdot\\mathbf{eye})"),
                 tex("\\mathbf{eye} = ") + vec(eye),
                 tex("\\mathbf{t} = ") + vec(std::vector<Exact>{m(0, 3), m(1, 3), m(2, 3)}, true));
      if (api == Api::DirectX)
        steps
            ->add(
                say(kViewMatrix),
                tex("V = \\begin{bmatrix} x_x & y_x & z_x & 0 \\\\ x_y & y_y & z_y & 0 \\\\ x_z & "
                    "y_z & z_z & 0 \\\\ t_x & t_y & t_z & 1 \\end{bmatrix}"),
                {}, math("V = ") + matrix_text(paper_form(m, api)))
            .note = multiply_note(api);
      else
        steps
            ->add(say(kViewMatrix),
                  tex("V = \\begin{bmatrix} x_x & x_y & x_z & t_x \\\\ y_x & y_y & y_z & t_y \\\\ "
                      "z_x & z_y & z_z & t_z \\\\ 0 & 0 & 0 & 1 \\end{bmatrix}"),
                  {}, math("V = ") + matrix_text(m))
            .note = multiply_note(api) + say(kLeftHandedCameraLooksDownPlusZ) +
                    say(kRightHandedCameraRowsNegated);
    } else {
      steps->add(say(kSideAxis),
                 tex("\\mathbf{s} = "
                     "\\frac{\\mathbf{f}\\times\\mathbf{up}}{\\lVert\\mathbf{f}\\times\\mathbf{up}"
                     "\\rVert}"),
                 tex("\\mathbf{f}\\times\\mathbf{up} = ") + vec(side, true) +
                     tex(",\\; \\lVert\\mathbf{f}\\times\\mathbf{up}\\rVert = ") +
                     exact(norm(side), true),
                 tex("\\mathbf{s} = ") + vec(row(0), true));
      steps->add(say(kCameraAxesRightHanded),
                 tex("\\mathbf{u} = \\mathbf{s}\\times\\mathbf{f},\\; \\mathbf{z}_{\\text{cam}} = "
                     "-\\mathbf{f}"),
                 {},
                 tex("\\mathbf{u} = ") + vec(row(1), true) + tex(",\\; -\\mathbf{f} = ") +
                     vec(row(2), true));
      steps
          ->add(say(kTranslations),
                tex("\\left(-\\mathbf{s}\\cdot\\mathbf{eye},\\;-\\mathbf{u}\\cdot\\mathbf{eye},\\;"
                    "\\mathbf{f}\\cdot\\mathbf{eye}\\right)"),
                tex("\\mathbf{eye} = ") + vec(eye),
                tex("\\left(-\\mathbf{s}\\cdot\\mathbf{eye},\\;-\\mathbf{u}\\cdot\\mathbf{eye},\\;"
                    "\\mathbf{f}\\cdot\\mathbf{eye}\\right) = ") +
                    vec(std::vector<Exact>{m(0, 3), m(1, 3), m(2, 3)}, true))
          .note = say(kEachRowOfVDotsAPoint);
      steps
          ->add(say(kViewMatrix),
                tex("V = \\begin{bmatrix} s_x & s_y & s_z & -\\mathbf{s}\\cdot\\mathbf{eye} \\\\ "
                    "u_x & u_y & u_z & -\\mathbf{u}\\cdot\\mathbf{eye} \\\\ "
                    "-f_x & -f_y & -f_z & \\mathbf{f}\\cdot\\mathbf{eye} \\\\ 0 & 0 & 0 & 1 "
                    "\\end{bmatrix}"),
                {}, math("V = ") + matrix_text(paper_form(m, api)))
          .note = multiply_note(api);
    }
  }
  return m;
}

namespace {

// The projection matrix in symbols, as on paper (DirectX: the row-vector form).
// The orthographic matrix with z_min, z_max as coordinates (Conventions::z_planes).
MathText ortho_coordinates_formula(Api api, const std::string& name) {
  const bool y_down = api == Api::Processing;
  const std::string sign = y_down ? "-" : "";
  return tex(name + " = \\begin{bmatrix} \\frac{2}{r-l} & 0 & 0 & -\\frac{r+l}{r-l} \\\\ 0 & " +
             sign +
             "\\frac{2}{t-b} & 0 & -\\frac{t+b}{t-b} \\\\ 0 & 0 & \\frac{2}{z_{\\max}-z_{\\min}} & "
             "-\\frac{z_{\\max}+z_{\\min}}{z_{\\max}-z_{\\min}} \\\\ 0 & 0 & 0 & 1 \\end{bmatrix}");
}

MathText projection_formula(bool ortho, Api api, bool left_handed, const std::string& name) {
  const bool y_down = api == Api::Processing;
  if (api == Api::DirectX)
    return ortho
               ? tex(name +
                     " = \\begin{bmatrix} \\frac{2}{r-l} & 0 & 0 & 0 \\\\ 0 & \\frac{2}{t-b} & "
                     "0 & 0 \\\\ 0 & 0 & \\frac{1}{f-n} & 0 \\\\ "
                     "\\frac{l+r}{l-r} & \\frac{t+b}{b-t} & \\frac{n}{n-f} & 1 \\end{bmatrix} "
                     "\\quad (\\text{OrthoOffCenterLH})")
               : tex(name +
                     " = \\begin{bmatrix} \\frac{2n}{r-l} & 0 & 0 & 0 \\\\ 0 & \\frac{2n}{t-b} "
                     "& 0 & 0 \\\\ "
                     "\\frac{l+r}{l-r} & \\frac{t+b}{b-t} & \\frac{f}{f-n} & 1 \\\\ 0 & 0 & "
                     "\\frac{nf}{n-f} & 0 \\end{bmatrix} \\quad (\\text{PerspectiveOffCenterLH})");
  // Left-handed under column vectors (glm's *LH_NO): the right-handed matrix with its third
  // column negated, w′ = z.
  const std::string sign = y_down ? "-" : "";
  const std::string minus = left_handed ? "" : "-";
  const std::string plus = left_handed ? "-" : "";
  if (ortho)
    return tex(name + " = \\begin{bmatrix} \\frac{2}{r-l} & 0 & 0 & -\\frac{r+l}{r-l} \\\\ 0 & " +
               sign + "\\frac{2}{t-b} & 0 & -\\frac{t+b}{t-b} \\\\ 0 & 0 & " + minus +
               "\\frac{2}{f-n} & -\\frac{f+n}{f-n} \\\\ 0 & 0 & 0 & 1 \\end{bmatrix}");
  return tex(name + " = \\begin{bmatrix} \\frac{2n}{r-l} & 0 & " + plus +
             "\\frac{r+l}{r-l} & 0 \\\\ 0 & " + sign + "\\frac{2n}{t-b} & " + plus +
             "\\frac{t+b}{t-b} & 0 \\\\ 0 & 0 & " + minus +
             "\\frac{f+n}{f-n} & -\\frac{2fn}{f-n} \\\\ 0 & 0 & " + minus + "1 & 0 \\end{bmatrix}");
}

// "l = −1,  r = 1, …" for the six planes of a view volume.
MathText volume_text(const Volume<Exact>& v) {
  const std::pair<const char*, const Exact*> planes[] = {{"l", &v.left},   {"r", &v.right},
                                                         {"b", &v.bottom}, {"t", &v.top},
                                                         {"n", &v.near},   {"f", &v.far}};
  MathText m;
  for (const auto& [name, value] : planes)
    m += (m.empty() ? MathText{} : tex(",\\; ")) + math(std::string(name) + " = ") + exact(*value);
  return m;
}

// Why a perspective matrix has the form it has, in the lectures' order: similar triangles put
// the projected point at n·x/(−z), a division no matrix can do; homogeneous coordinates move
// −z into w′, and the perspective divide performs it (DirectX: eye space looks down +z).
void perspective_idea_steps(Api api, bool left_handed, const std::string& name, Derivation& steps) {
  const bool plus_z = api == Api::DirectX || left_handed;
  const bool rows = api == Api::DirectX;  // w′ = z in column 4 (row vectors), else in row 4
  steps
      .add(say(kSimilarTriangles),
           plus_z ? tex("x_n : n = x : z,\\; y_n : n = y : z")
                  : tex("x_n : n = x : (-z),\\; y_n : n = y : (-z)"),
           {},
           plus_z ? tex("x_n = \\frac{n\\,x}{z},\\; y_n = \\frac{n\\,y}{z}")
                  : tex("x_n = \\frac{n\\,x}{-z},\\; y_n = \\frac{n\\,y}{-z}"))
      .note = say(plus_z ? kPointMeetsNearPlanePlusZ : kPointMeetsNearPlaneMinusZ);
  steps
      .add(say(kDepthGoesIntoW),
           rows     ? tex("w' = z \\quad (" + name + "_{*4} = (0, 0, 1, 0)^{\\mathsf{T}})")
           : plus_z ? tex("w' = z \\quad (" + name + "_{4*} = (0, 0, 1, 0))")
                    : tex("w' = -z \\quad (" + name + "_{4*} = (0, 0, -1, 0))"),
           {},
           plus_z ? tex("x_{\\mathrm{ndc}} = \\frac{x'}{w'} = \\frac{x'}{z}")
                  : tex("x_{\\mathrm{ndc}} = \\frac{x'}{w'} = \\frac{x'}{-z}"))
      .note = say(kNoMatrixDividesByACoordinate);
}

}  // namespace

MatX<Exact> projection_with_steps(const ProjectionSpec& p, Api api, Derivation* steps,
                                  const std::string& name) {
  const Volume<Exact>& v = p.volume;
  if (steps && p.sketch) {
    // Processing's perspective() with no arguments, for a width × height sketch.
    steps
        ->add(say(kPerspectiveWithNoArguments),
              tex("\\text{fovy} = \\frac{\\pi}{3},\\; \\text{aspect} = "
                  "\\frac{\\text{width}}{\\text{height}},\\; \\text{cameraZ} = "
                  "\\frac{\\text{height}/2}{\\tan(\\text{fovy}/2)},\\; n = "
                  "\\frac{\\text{cameraZ}}{10},\\; f = 10\\,\\text{cameraZ}"),
              tex("\\text{width} = ") + exact(p.sketch->first) + tex(",\\; \\text{height} = ") +
                  exact(p.sketch->second),
              tex("\\text{aspect} = ") + exact(*p.aspect) + tex(",\\; n = ") + exact(v.near, true) +
                  tex(",\\; f = ") + exact(v.far, true))
        .note = say(kProcessingDefaults);
  }
  if (steps && p.fovx) {
    // The course's horizontal reading, and how it relates to perspective()'s vertical fovy.
    steps->add(
        say(kFrustumOfHorizontalFov),
        tex("r = n\\tan\\frac{\\text{fovx}}{2},\\; l = -r,\\; t = \\frac{r}{\\text{aspect}},\\; b "
            "= -t"),
        tex("\\text{fovx} = ") + angle_text(*p.fovx, p.unit) + tex(",\\; \\text{aspect} = ") +
            exact(*p.aspect) + tex(",\\; n = ") + exact(v.near),
        math("r = ") + exact(v.right, true) + tex(",\\; t = ") + exact(v.top, true));
    const double fovy_shown =
        to_double(p.unit == AngleUnit::Degrees ? Exact(*p.fovy * 180 / GiNaC::Pi) : *p.fovy);
    steps
        ->add(say(kSameFrustumFromVerticalAngle),
              tex("\\text{fovy} = 2\\arctan\\frac{\\tan(\\text{fovx}/2)}{\\text{aspect}}"), {},
              tex("\\text{fovy} = 2\\arctan\\left(") +
                  exact(canonical(GiNaC::tan(*p.fovx / 2) / *p.aspect)) +
                  tex(fmt::format("\\right) \\approx {:.4g}{}", fovy_shown,
                                  p.unit == AngleUnit::Degrees ? "^{\\circ}" : "")) +
                  tex(",\\; t = n\\tan\\frac{\\text{fovy}}{2} = ") + exact(v.top, true))
        .note = say(kFovxSpansTheWidth);
  } else if (steps && p.type == ProjectionSpec::Type::Perspective) {
    steps
        ->add(
            say(kFrustumOfPerspective),
            tex("t = n\\tan\\frac{\\text{fovy}}{2},\\; b = -t,\\; r = t\\cdot\\text{aspect},\\; l "
                "= -r"),
            tex("\\text{fovy} = ") + angle_text(*p.fovy, p.unit) + tex(",\\; \\text{aspect} = ") +
                exact(*p.aspect) + tex(",\\; n = ") + exact(v.near),
            math("t = ") + exact(v.top, true) + tex(",\\; r = ") + exact(v.right, true))
        .note =
        say(kFovyIsVertical) + say(kReadAsHorizontalAngle) + say(kSomeNotesWriteAspectOnTop);
  }
  MatX<Exact> m =
      p.type == ProjectionSpec::Type::Ortho ? ortho_matrix(v, api) : frustum_matrix(v, api);
  // Left-handed (the eye looks down +z): z ↦ −z before the right-handed matrix, so its third
  // column changes sign.
  if (p.left_handed)
    for (int i = 0; i < 4; ++i) m(i, 2) = -m(i, 2);
  m = canonical(m);
  if (steps && p.type != ProjectionSpec::Type::Ortho)
    perspective_idea_steps(api, p.left_handed, name, *steps);
  // The course's reading: z_min = near, z_max = far as coordinates map to −1 and +1, so the z row
  // is +2/(z_max − z_min), −(z_max + z_min)/(z_max − z_min); glOrtho's planes z = −n, −f negate
  // the first entry. Both map the same volume; only the direction of the z axis differs.
  if (p.z_coordinates) {
    m(2, 2) = canonical(2 / (v.far - v.near));
    m(2, 3) = canonical(-(v.far + v.near) / (v.far - v.near));
  }
  if (steps) {
    const bool ortho = p.type == ProjectionSpec::Type::Ortho;
    Step& s = steps
                  ->add(say(ortho ? kOrthographicProjectionMatrix : kPerspectiveProjectionMatrix),
                        p.z_coordinates ? ortho_coordinates_formula(api, name)
                                        : projection_formula(ortho, api, p.left_handed, name),
                        volume_text(v), math(name + " = ") + matrix_text(paper_form(m, api)))
                  .yields("matrix");
    // OpenGL's right-handed perspective: the column vectors and where near and far go are one
    // sentence ("… = M·p. z = −n maps to …").
    s.note = api == Api::OpenGL && !ortho && !p.left_handed
                 ? say(kColumnVectorsNearFarToNdc) + say(kSentenceContradictsMatrix)
                 : multiply_note(api);
    if (api == Api::Processing) s.note += say(kProcessingNegatesYRow);
    if (p.left_handed)
      s.note += say(kLeftHandedNearFarAreCoordinates) + say(kRightHandedMatrixThirdColumn);
    if (api == Api::DirectX) s.note += say(kLookingDownPlusZNdc);
    if (p.z_coordinates) s.note += say(kNearFarAsZCoordinates) + say(kGlOrthoReadsDistances);
  }
  return m;
}

std::vector<ProjectionMistake> projection_mistakes(const ProjectionSpec& p) {
  std::vector<ProjectionMistake> out;
  const Said frustum_step = say(kFrustumOfPerspective);
  if (p.fovx && p.aspect) {
    // The horizontal angle read as perspective()'s vertical one.
    ProjectionSpec fovy = p;
    fovy.fovx.reset();
    fovy.fovy = p.fovx;
    fovy.volume = perspective_volume(*p.fovx, *p.aspect, p.volume.near, p.volume.far);
    for (Exact* e : {&fovy.volume.left, &fovy.volume.right, &fovy.volume.bottom, &fovy.volume.top})
      *e = canonical(*e);
    out.push_back(
        {say(kFovyForFovx), say(kUsedTheAngleAsVertical), say(kFrustumOfHorizontalFov), fovy});
  } else if (p.fovy && p.aspect) {
    const Exact as_degrees = canonical(*p.fovy * 180 / GiNaC::Pi);
    if (!canonical(GiNaC::cos(as_degrees / 2)).is_zero()) {
      ProjectionSpec radians = p;
      radians.fovy = as_degrees;
      radians.volume = perspective_volume(as_degrees, *p.aspect, p.volume.near, p.volume.far);
      out.push_back(
          {say(kDegreesTakenAsRadians), say(kNumbersFromDegreesAsRadians), frustum_step, radians});
    }
    // fovx: the angle spans the width, so r = n·tan(θ/2) and t = r / aspect.
    ProjectionSpec fovx = p;
    const Exact t = p.volume.top;
    fovx.volume.right = t;
    fovx.volume.left = canonical(-t);
    fovx.volume.top = canonical(t / *p.aspect);
    fovx.volume.bottom = canonical(-t / *p.aspect);
    out.push_back({say(kFovxForFovy), say(kUsedTheAngleAsHorizontal), frustum_step, fovx});
  }
  // −l = r = n·tan(θ/2), −b = t = n·(w/h)·tan(θ/2): the aspect ratio multiplying the top, a form
  // some notes print; it is neither reading of θ unless w = h.
  if (p.aspect && (p.fovx || p.fovy) && !canonical(*p.aspect - 1).is_zero()) {
    const Exact theta = p.fovx ? *p.fovx : *p.fovy;
    ProjectionSpec on_t = p;
    const Exact r = canonical(p.volume.near * GiNaC::tan(theta / 2));
    const Exact t = canonical(r * *p.aspect);
    on_t.volume.left = canonical(-r);
    on_t.volume.right = r;
    on_t.volume.bottom = canonical(-t);
    on_t.volume.top = t;
    out.push_back({say(kAspectRatioOnTheTop), say(kAspectRatioMultipliesTheTop),
                   p.fovx ? say(kFrustumOfHorizontalFov) : frustum_step, on_t});
  }
  // A left-handed course's projection written with the right-handed matrix (looking down −z).
  if (p.left_handed) {
    ProjectionSpec right = p;
    right.left_handed = false;
    out.push_back({say(kRightHandedMatrix), say(kUsedTheRightHandedMatrix), Said{}, right});
  }
  // near/far sign: the planes' z coordinates (−n, −f) put into the matrix instead of the
  // distances n, f.
  // For ortho, negating both is exactly the other reading of its z row (coordinates z_min = n,
  // z_max = f mapped to −1, +1 against glOrtho's distances), so that is what it is named.
  ProjectionSpec signs = p;
  signs.volume.near = canonical(-p.volume.near);
  signs.volume.far = canonical(-p.volume.far);
  const bool ortho_reading = p.type == ProjectionSpec::Type::Ortho && !p.left_handed;
  if (ortho_reading && !p.z_coordinates)
    out.push_back({say(kZMinZMaxReadAsCoordinates), say(kZRowReadsCoordinates), Said{}, signs});
  else if (ortho_reading)
    out.push_back({say(kNearFarReadAsDistances), say(kZRowReadsDistances), Said{}, signs});
  else
    out.push_back({say(kNearFarSign), say(kNearFarArePositiveDistances), Said{}, signs});
  return out;
}

AnswerScale ndc_scale(Api api) {
  AnswerScale s = uniform_scale(3, 1, {-1, 1});
  if (api == Api::DirectX) s.thresholds[2] = {0, 1};
  return s;
}

AnswerScale window_scale(const Exact& width, const Exact& height) {
  const double w = to_double(width), h = to_double(height);
  return {{w / 2, h / 2, 1}, {{0, w}, {0, h}, {0, 1}}};
}

bool ndc_inside(const Vec3<Exact>& ndc, Api api) {
  for (int i = 0; i < 3; ++i) {
    const Exact low = i == 2 && api == Api::DirectX ? Exact(0) : Exact(-1);
    if (exact_sign(ndc(i) - low) < 0 || exact_sign(1 - ndc(i)) < 0) return false;
  }
  return true;
}

}  // namespace frustum
