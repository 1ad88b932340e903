#include "solver/derivation/vocabulary.hpp"

namespace frustum::words {

Said vocabulary_word(std::string_view english) {
  // Categories and counted words only: a name that happens to be an English word (an object
  // called "plane") is not translated.
  static constexpr const Phrase* kData[] = {
      &kYes, &kNo, &kNone, &kTrue, &kFalse, &kFront, &kBack, &kEdgeOn, &kEdgeOnKey, &kVisible,
      &kHidden, &kSilhouette, &kInside, &kOutside, &kBackground,
      // counted
      &kTriangles, &kWindowTriangles, &kClipped, &kBackFacesCulled, &kOutsideViewVolume,
      &kPixelsCovered, &kNearerAndWritten};
  for (const Phrase* p : kData)
    if (p->en == english) return Said(*p);
  return Said::verbatim(english);
}

}  // namespace frustum::words
