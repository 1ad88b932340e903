// Words many kinds write inside formulas and answers (yes/no, front/back, visible/hidden …),
// each once, in the three languages. A kind's own phrases stay in the kind's file.
#pragma once

#include <span>
#include <string_view>

#include "solver/util/said.hpp"

namespace frustum::words {

inline constexpr Phrase kYes{"yes", "はい", "да"};
inline constexpr Phrase kNo{"no", "いいえ", "нет"};
inline constexpr Phrase kNone{"none", "なし", "нет"};
inline constexpr Phrase kTrue{"true", "真", "истина"};
inline constexpr Phrase kFalse{"false", "偽", "ложь"};
inline constexpr Phrase kFront{"front", "表", "лицевая"};
inline constexpr Phrase kBack{"back", "裏", "обратная"};
inline constexpr Phrase kEdgeOn{"edge-on", "真横", "с ребра"};
inline constexpr Phrase kEdgeOnKey{"edge_on", "真横", "с ребра"};
inline constexpr Phrase kVisible{"visible", "可視", "видимое"};
inline constexpr Phrase kHidden{"hidden", "不可視", "невидимое"};
inline constexpr Phrase kSilhouette{"silhouette", "輪郭線", "силуэт"};
inline constexpr Phrase kInside{"inside", "内側", "внутри"};
inline constexpr Phrase kOutside{"outside", "外側", "снаружи"};
inline constexpr Phrase kConvex{"convex", "凸", "выпуклый"};
inline constexpr Phrase kNotConvex{"not convex", "凸でない", "невыпуклый"};
inline constexpr Phrase kBackground{"background", "背景", "фон"};
inline constexpr Phrase kDepth{"depth", "奥行き", "глубина"};
inline constexpr Phrase kPlane{"plane", "平面", "плоскость"};
inline constexpr Phrase kPolygon{"polygon", "多角形", "многоугольник"};
inline constexpr Phrase kDegrees{"degrees", "度", "градусах"};
inline constexpr Phrase kRadians{"radians", "ラジアン", "радианах"};
// Counted in a summary ("3 triangles: 1 clipped, 0 back faces culled").
inline constexpr Phrase kTriangles{"triangles", "三角形", "треугольники"};
inline constexpr Phrase kWindowTriangles{"window triangles", "ウィンドウ上の三角形",
                                         "треугольники в окне"};
inline constexpr Phrase kClipped{"clipped", "クリップされた", "отсечено"};
inline constexpr Phrase kBackFacesCulled{"back faces culled", "背面を除去",
                                         "нелицевые грани отброшены"};
inline constexpr Phrase kOutsideViewVolume{"outside the view volume", "視体積の外側",
                                           "вне видимого объёма"};
inline constexpr Phrase kPixelsCovered{"pixel(s) covered", "画素を覆う", "пикс. покрыто"};
inline constexpr Phrase kNearerAndWritten{"nearer than Z(i, j) and written",
                                          "Z(i, j) より手前なので書き込む",
                                          "ближе, чем Z(i, j), и записано"};

// The label of an answer that several kinds have, on an exam sheet where the answer has no
// symbol (AnswerSpec::label; its English is the answer's name). kDepth and kPlane above label
// the answers depth and plane as well.
inline constexpr Phrase kClippingResult{"clipped", "クリッピングの結果", "результат отсечения"};
inline constexpr Phrase kInsideQuestion{"inside", "内側か", "внутри ли"};
inline constexpr Phrase kPixels{"pixels", "画素", "пиксели"};
inline constexpr Phrase kPoints{"points", "点", "точки"};
inline constexpr Phrase kWindowCoordinates{"window", "ウィンドウ座標", "оконные координаты"};
inline constexpr Phrase kEdges{"edges", "稜線", "рёбра"};
inline constexpr Phrase kMatrix{"matrix", "行列", "матрица"};

// A word counted by a number in a formula ("3 front" → "3 лицевые"): its English plural and
// singular (for 1), and the three forms Russian agreement takes: one (1, 21, 31 …), few
// (2–4, 22–24 …) and many (0, 5–20, 25–30 …).
struct CountForms {
  std::string_view en, en_one, one, few, many;
};
std::span<const CountForms> count_forms();

// A word that is data rather than a phrase of the code: an answer's category ("front", "edge_on",
// "visible"), true/false, or a counted word. The word among the ones above with exactly that
// English, or the word as written (a name, a label, an outcode) when none has it.
Said vocabulary_word(std::string_view english);

}  // namespace frustum::words
