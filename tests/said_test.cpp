// Phrases keyed in code (solver/util/said.hpp): a phrase is checked when it is compiled
// (both translations, the same slots), `say` fills each language's slots with each language's
// words, and words that are data (answer categories) are found exactly or kept as written.
#include "solver/util/said.hpp"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>

#include "solver/derivation/derivation.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "typeset_corpus.hpp"

namespace frustum {
namespace {

// The compile-time check a Phrase's constructor makes: the slots each text places.
static_assert(said_detail::slots("no slot") == 0);
static_assert(said_detail::slots("{0} and {1}") == 3);
static_assert(said_detail::slots("{1} の {0}") == 3);
static_assert(said_detail::slots("a brace { is not a slot {x}") == 0);

constexpr Phrase kClipAgainst{"Clip against {0}", "クリップ: {0}", "Отсечение: {0}"};
constexpr Phrase kLeft{"left: {0}", "左端: {0}", "лево: {0}"};
constexpr Phrase kOrder{"{0} before {1}", "{1} より先に {0}", "{0} раньше {1}"};

TEST(Said, FillsEachLanguagesSlotsWithThatLanguagesWords) {
  const Said s = say(kClipAgainst, say(kLeft, "x ≥ −1"));
  EXPECT_EQ(s.en(), "Clip against left: x ≥ −1");
  EXPECT_EQ(s.in(Lang::Ja), "クリップ: 左端: x ≥ −1");
  EXPECT_EQ(s.in(Lang::Ru), "Отсечение: лево: x ≥ −1");
  // Slots are placed where each language's grammar wants them; numbers and strings verbatim.
  const Said o = say(kOrder, 2, std::string("B"));
  EXPECT_EQ(o.en(), "2 before B");
  EXPECT_EQ(o.in(Lang::Ja), "B より先に 2");
}

TEST(Said, SentencesJoinWithOneSpaceAndNoneAtALineBreak) {
  constexpr Phrase kA{"First.", "一.", "Первое."};
  constexpr Phrase kB{"Second.", "二.", "Второе."};
  Said s = say(kA);
  s += say(kB);
  EXPECT_EQ(s.en(), "First. Second.");
  EXPECT_EQ(s.in(Lang::Ja), "一. 二.");
  Said t = say(kA);
  t.append(Said::verbatim("\n")).append(say(kB));
  EXPECT_EQ(t.in(Lang::Ru), "Первое.\nВторое.");
  EXPECT_EQ((Said() + say(kB)).en(), "Second.");
}

TEST(Said, DataWordsAreFoundExactlyOrKeptAsWritten) {
  EXPECT_EQ(words::vocabulary_word("edge_on").in(Lang::Ja), "真横");
  EXPECT_EQ(words::vocabulary_word("visible").in(Lang::Ru), "видимое");
  // A name or label is not a word of the vocabulary, even one that looks like a word.
  EXPECT_EQ(words::vocabulary_word("plane").in(Lang::Ja), "plane");
  EXPECT_EQ(words::vocabulary_word("0110").in(Lang::Ru), "0110");
  EXPECT_EQ(words::vocabulary_word("Front").in(Lang::Ja), "Front");
}

// A Said can only be made from a phrase, from all three texts or verbatim: English alone does
// not convert to one (nothing is translated by looking its English up).
static_assert(!std::is_convertible_v<std::string, Said>);
static_assert(!std::is_convertible_v<const char*, Said>);
static_assert(!std::is_constructible_v<Said, std::string>);

// A counted word agrees with its number in Russian (1 треугольник, 2 треугольника, 5
// треугольников) and in English (1 triangle): every counted word has all its forms.
TEST(Said, EveryCountedWordHasItsForms) {
  EXPECT_FALSE(words::count_forms().empty());
  for (const words::CountForms& f : words::count_forms()) {
    EXPECT_FALSE(f.en.empty() || f.en_one.empty()) << f.en;
    EXPECT_FALSE(f.one.empty() || f.few.empty() || f.many.empty()) << f.en;
    EXPECT_EQ(words::vocabulary_word(f.en).en(), f.en) << "counted words are in the vocabulary";
  }
}

// Every step of every kind's generated problems is said in all three languages: a title or
// note with an English text has its Japanese and Russian (none left empty or equal to the
// English, except for text that is the same in every language: formulas and names).
TEST(Said, EveryStepOfEveryKindIsSaidInEveryLanguage) {
  int steps = 0, differ = 0;
  for (const ProblemResult& c : test::typeset_corpus()) {
    for (const Step& s : c.derivation.steps()) {
      ++steps;
      for (const Said* t : {&s.title, &s.note}) {
        if (t->empty()) continue;
        EXPECT_FALSE(t->in(Lang::Ja).empty()) << c.id << ": " << t->en();
        EXPECT_FALSE(t->in(Lang::Ru).empty()) << c.id << ": " << t->en();
        differ += t->in(Lang::Ja) != t->en();
      }
    }
  }
  EXPECT_GT(steps, 500);
  EXPECT_GT(differ, steps / 2);
}

}  // namespace
}  // namespace frustum
