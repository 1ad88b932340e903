#include "solver/problem/conventions_note.hpp"

#include "solver/derivation/vocabulary.hpp"

namespace frustum {

namespace {

constexpr Phrase kOpenGl{
    "OpenGL: right-handed eye space looking down −z, column vectors (p′ = M·p), NDC cube [−1, 1]³ "
    "with near → −1, window origin bottom-left",
    "OpenGL: 視点座標系は右手系で −z 方向を見る, 列ベクトル (p′ = M·p), 正規化視体積は立方体 [−1, "
    "1]³ (near → −1), ウィンドウの原点は左下",
    "OpenGL: правая система координат вида, взгляд вдоль −z, столбцы-векторы (p′ = M·p), куб NDC "
    "[−1, 1]³ (near → −1), начало окна внизу слева"};
constexpr Phrase kOpenGlAngles{
    "OpenGL: right-handed eye space looking down −z, column vectors (p′ = M·p), NDC cube [−1, 1]³ "
    "with near → −1, window origin bottom-left; angles in {0}",
    "OpenGL: 視点座標系は右手系で −z 方向を見る, 列ベクトル (p′ = M·p), 正規化視体積は立方体 [−1, "
    "1]³ (near → −1), ウィンドウの原点は左下; 角度の単位は{0}",
    "OpenGL: правая система координат вида, взгляд вдоль −z, столбцы-векторы (p′ = M·p), куб NDC "
    "[−1, 1]³ (near → −1), начало окна внизу слева; углы в {0}"};
constexpr Phrase kOpenGlLeft{
    "OpenGL, left-handed: eye space looking down +z, column vectors (p′ = M·p), NDC cube [−1, 1]³ "
    "with near → −1, window origin bottom-left",
    "OpenGL, 左手系: 視点座標系は +z 方向を見る, 列ベクトル (p′ = M·p), 正規化視体積は立方体 [−1, "
    "1]³ (near → −1), ウィンドウの原点は左下",
    "OpenGL, левая система: система координат вида с взглядом вдоль +z, столбцы-векторы (p′ = "
    "M·p), куб NDC [−1, 1]³ (near → −1), начало окна внизу слева"};
constexpr Phrase kOpenGlLeftAngles{
    "OpenGL, left-handed: eye space looking down +z, column vectors (p′ = M·p), NDC cube [−1, 1]³ "
    "with near → −1, window origin bottom-left; angles in {0}",
    "OpenGL, 左手系: 視点座標系は +z 方向を見る, 列ベクトル (p′ = M·p), 正規化視体積は立方体 [−1, "
    "1]³ (near → −1), ウィンドウの原点は左下; 角度の単位は{0}",
    "OpenGL, левая система: система координат вида с взглядом вдоль +z, столбцы-векторы (p′ = "
    "M·p), куб NDC [−1, 1]³ (near → −1), начало окна внизу слева; углы в {0}"};
constexpr Phrase kProcessing{
    "Processing: OpenGL's matrices and NDC cube [−1, 1]³, column vectors, window origin top-left "
    "with y pointing down",
    "Processing: OpenGL の行列と正規化視体積 [−1, 1]³, 列ベクトル, ウィンドウの原点は左上で y "
    "は下向き",
    "Processing: матрицы и куб NDC [−1, 1]³ как в OpenGL, столбцы-векторы, начало окна вверху "
    "слева, y направлена вниз"};
constexpr Phrase kProcessingAngles{
    "Processing: OpenGL's matrices and NDC cube [−1, 1]³, column vectors, window origin top-left "
    "with y pointing down; angles in {0}",
    "Processing: OpenGL の行列と正規化視体積 [−1, 1]³, 列ベクトル, ウィンドウの原点は左上で y "
    "は下向き; 角度の単位は{0}",
    "Processing: матрицы и куб NDC [−1, 1]³ как в OpenGL, столбцы-векторы, начало окна вверху "
    "слева, y направлена вниз; углы в {0}"};
constexpr Phrase kProcessingLeft{
    "Processing, left-handed: eye space looking down +z, OpenGL's NDC cube [−1, 1]³, column "
    "vectors, window origin top-left with y pointing down",
    "Processing, 左手系: 視点座標系は +z 方向を見る, OpenGL の正規化視体積 [−1, 1]³, 列ベクトル, "
    "ウィンドウの原点は左上で y は下向き",
    "Processing, левая система: система координат вида с взглядом вдоль +z, куб NDC [−1, 1]³ как в "
    "OpenGL, столбцы-векторы, начало окна вверху слева, y направлена вниз"};
constexpr Phrase kProcessingLeftAngles{
    "Processing, left-handed: eye space looking down +z, OpenGL's NDC cube [−1, 1]³, column "
    "vectors, window origin top-left with y pointing down; angles in {0}",
    "Processing, 左手系: 視点座標系は +z 方向を見る, OpenGL の正規化視体積 [−1, 1]³, 列ベクトル, "
    "ウィンドウの原点は左上で y は下向き; 角度の単位は{0}",
    "Processing, левая система: система координат вида с взглядом вдоль +z, куб NDC [−1, 1]³ как в "
    "OpenGL, столбцы-векторы, начало окна вверху слева, y направлена вниз; углы в {0}"};
constexpr Phrase kDirectX{
    "DirectX: left-handed eye space looking down +z, row vectors (p′ = p·M), NDC z in [0, 1], "
    "window origin top-left with y pointing down",
    "DirectX: 視点座標系は左手系で +z 方向を見る, 行ベクトル (p′ = p·M), 正規化座標の z は [0, 1], "
    "ウィンドウの原点は左上で y は下向き",
    "DirectX: левая система координат вида, взгляд вдоль +z, строки-векторы (p′ = p·M), z в NDC из "
    "[0, 1], начало окна вверху слева, y направлена вниз"};
constexpr Phrase kDirectXAngles{
    "DirectX: left-handed eye space looking down +z, row vectors (p′ = p·M), NDC z in [0, 1], "
    "window origin top-left with y pointing down; angles in {0}",
    "DirectX: 視点座標系は左手系で +z 方向を見る, 行ベクトル (p′ = p·M), 正規化座標の z は [0, 1], "
    "ウィンドウの原点は左上で y は下向き; 角度の単位は{0}",
    "DirectX: левая система координат вида, взгляд вдоль +z, строки-векторы (p′ = p·M), z в NDC из "
    "[0, 1], начало окна вверху слева, y направлена вниз; углы в {0}"};
constexpr Phrase kZCoordinates{"{0}; ortho's near and far are the z coordinates z_min, z_max",
                               "{0}; ortho の near, far は z 座標 z_min, z_max",
                               "{0}; near и far в ortho — z-координаты z_min, z_max"};
constexpr Phrase kZCoordinatesAngles{
    "{0}; ortho's near and far are the z coordinates z_min, z_max; angles in {1}",
    "{0}; ortho の near, far は z 座標 z_min, z_max; 角度の単位は{1}",
    "{0}; near и far в ortho — z-координаты z_min, z_max; углы в {1}"};
constexpr Phrase kHorizontalFov{"{0}; the field of view is horizontal (fovx)",
                                "{0}; 画角は水平方向 (fovx)",
                                "{0}; угол обзора горизонтальный (fovx)"};
constexpr Phrase kHorizontalFovAngles{"{0}; the field of view is horizontal (fovx); angles in {1}",
                                      "{0}; 画角は水平方向 (fovx); 角度の単位は{1}",
                                      "{0}; угол обзора горизонтальный (fovx); углы в {1}"};
constexpr Phrase kLeftHandedCoordinates{"Left-handed coordinates", "左手系の座標",
                                        "Левая система координат"};
constexpr Phrase kLeftHandedCoordinatesAngles{"Left-handed coordinates; angles in {0}",
                                              "左手系の座標; 角度の単位は{0}",
                                              "Левая система координат; углы в {0}"};
constexpr Phrase kAnglesIn{"Angles in {0}", "角度の単位は{0}", "Углы в {0}"};

}  // namespace

Said conventions_note(const Conventions& c, ConventionUse use) {
  const Phrase& unit = c.angles == AngleUnit::Degrees ? words::kDegrees : words::kRadians;
  if (!use.api) {
    // Kinds with no eye space state a left-handed course's frame (the front normal flips).
    if (use.handedness && left_handed_columns(c))
      return use.angles ? say(kLeftHandedCoordinatesAngles, unit) : say(kLeftHandedCoordinates);
    return use.angles ? say(kAnglesIn, unit) : Said();
  }
  const bool left = left_handed_columns(c);
  // The API's clause, and the same with the angle unit after it.
  const Phrase* api = &kDirectX;
  const Phrase* api_angles = &kDirectXAngles;
  if (c.api == Api::OpenGL) {
    api = left ? &kOpenGlLeft : &kOpenGl;
    api_angles = left ? &kOpenGlLeftAngles : &kOpenGlAngles;
  } else if (c.api == Api::Processing) {
    api = left ? &kProcessingLeft : &kProcessing;
    api_angles = left ? &kProcessingLeftAngles : &kProcessingAngles;
  }
  const bool coordinates = c.z_planes == ZPlanes::Coordinates;
  const bool horizontal = c.fov == FovAxis::Horizontal;
  if (!coordinates && !horizontal) return use.angles ? say(*api_angles, unit) : say(*api);
  // Each further clause after the ones before it; the angle unit after the last.
  Said s = say(*api);
  if (coordinates)
    s = use.angles && !horizontal ? say(kZCoordinatesAngles, s, unit) : say(kZCoordinates, s);
  if (horizontal) s = use.angles ? say(kHorizontalFovAngles, s, unit) : say(kHorizontalFov, s);
  return s;
}

}  // namespace frustum
