// What a student reads, in each language Frustum speaks. A phrase is written once, where it is
// used (the kind or module that says it), in English, Japanese and Russian together; `say`
// fills its slots and keeps the text in all three, so a renderer picks the reader's language
// and nothing is looked up by its English at run time. A phrase without a translation, or whose
// translations do not place exactly the English slots, does not compile.
#pragma once

#include <array>
#include <concepts>
#include <string>
#include <string_view>
#include <type_traits>

namespace frustum {

enum class Lang { En, Ja, Ru };
inline constexpr std::array<Lang, 3> kLangs = {Lang::En, Lang::Ja, Lang::Ru};

namespace said_detail {
// Called only when a phrase is incomplete: a call to it is not a constant expression, so the
// phrase's definition fails to compile with this name in the message.
void phrase_lacks_a_translation_or_a_slot();

// The slots {0}…{9} a text places, as a bit set; each at most once.
consteval unsigned slots(std::string_view text) {
  unsigned out = 0;
  for (std::size_t i = 0; i + 2 < text.size(); ++i)
    if (text[i] == '{' && text[i + 1] >= '0' && text[i + 1] <= '9' && text[i + 2] == '}') {
      const unsigned bit = 1U << (text[i + 1] - '0');
      if (out & bit) phrase_lacks_a_translation_or_a_slot();
      out |= bit;
    }
  return out;
}
}  // namespace said_detail

// A student-facing phrase in English, Japanese and Russian; {0}, {1} … stand for a value or a
// name that each language places where its grammar wants it. Checked when compiled: both
// translations present, each placing exactly the English slots.
struct Phrase {
  std::string_view en, ja, ru;

  consteval Phrase(const char* english, const char* japanese, const char* russian)
      : en(english), ja(japanese), ru(russian) {
    const unsigned s = said_detail::slots(en);
    if (en.empty() || ja.empty() || ru.empty() || said_detail::slots(ja) != s ||
        said_detail::slots(ru) != s || (s & (s + 1)) != 0)  // slots numbered from 0 without a gap
      said_detail::phrase_lacks_a_translation_or_a_slot();
  }
  std::string_view in(Lang lang) const {
    return lang == Lang::Ja ? ja : lang == Lang::Ru ? ru : en;
  }
};

// Text in every language: a phrase said with its slots filled, an instructor's text as the set
// gives it, or something written the same way in all (a name, a value: `verbatim`).
class Said {
 public:
  Said() = default;
  explicit Said(const Phrase& p) : text_{std::string(p.en), std::string(p.ja), std::string(p.ru)} {}
  Said(std::string en, std::string ja, std::string ru)
      : text_{std::move(en), std::move(ja), std::move(ru)} {}
  static Said verbatim(std::string_view text) {
    return {std::string(text), std::string(text), std::string(text)};
  }

  const std::string& in(Lang lang) const { return text_[static_cast<std::size_t>(lang)]; }
  const std::string& en() const { return text_[0]; }
  bool empty() const { return text_[0].empty() && text_[1].empty() && text_[2].empty(); }

  // The next sentence or clause: joined with a space (none after a line break or before one).
  Said& operator+=(const Said& next);
  friend Said operator+(Said a, const Said& b) { return a += b; }
  // Text written directly after (no space): "…" + said_of(x) + "."
  Said& append(const Said& next);
  bool operator==(const Said&) const = default;

 private:
  std::array<std::string, 3> text_;
};

namespace said_detail {
inline Said arg(const Said& s) { return s; }
inline Said arg(const Phrase& p) { return Said(p); }
inline Said arg(std::string_view s) { return Said::verbatim(s); }
inline Said arg(const std::string& s) { return Said::verbatim(s); }
inline Said arg(const char* s) { return Said::verbatim(s); }
template <std::integral I>
Said arg(I n) {
  return Said::verbatim(std::to_string(n));
}
Said fill(const Phrase& p, const Said* args, std::size_t n);
}  // namespace said_detail

// The phrase with its slots filled: {k} by the k-th argument — a Said (or Phrase) in each
// language's own words, a string or number as written.
template <typename... A>
Said say(const Phrase& p, const A&... args) {
  if constexpr (sizeof...(A) == 0) {
    return Said(p);
  } else {
    const Said filled[] = {said_detail::arg(args)...};
    return said_detail::fill(p, filled, sizeof...(A));
  }
}

}  // namespace frustum
