#include "solver/derivation/vocabulary.hpp"

namespace frustum::words {

Said vocabulary_word(std::string_view english) {
  // Categories and counted words only: a name that happens to be an English word (an object
  // called "plane") is not translated.
  static constexpr const Phrase* kData[] = {
      &kYes, &kNo, &kNone, &kTrue, &kFalse, &kFront, &kBack, &kEdgeOn, &kEdgeOnKey, &kVisible,
      &kHidden, &kSilhouette, &kInside, &kOutside, &kBackground, &kConvex, &kNotConvex,
      // counted
      &kTriangles, &kWindowTriangles, &kClipped, &kBackFacesCulled, &kOutsideViewVolume,
      &kPixelsCovered, &kNearerAndWritten};
  for (const Phrase* p : kData)
    if (p->en == english) return Said(*p);
  return Said::verbatim(english);
}

namespace {

constexpr CountForms kCounts[] = {
    {"triangles", "triangle", "треугольник", "треугольника", "треугольников"},
    {"window triangles", "window triangle", "треугольник в окне", "треугольника в окне",
     "треугольников в окне"},
    {"clipped", "clipped", "отсечён", "отсечены", "отсечено"},
    {"back faces culled", "back face culled", "нелицевая грань отброшена",
     "нелицевые грани отброшены", "нелицевых граней отброшено"},
    {"front", "front", "лицевая", "лицевые", "лицевых"},
    {"back", "back", "обратная", "обратные", "обратных"},
    {"visible", "visible", "видимое", "видимых", "видимых"},
    {"silhouette", "silhouette", "контурное", "контурных", "контурных"},
    {"hidden", "hidden", "невидимое", "невидимых", "невидимых"},
};

}  // namespace

std::span<const CountForms> count_forms() { return kCounts; }

}  // namespace frustum::words
