// The translation catalogue (solver/derivation/phrases_*.cpp) checked as data: every phrase has
// its Japanese and Russian, a pattern's slots are all placed in each translation and none is
// invented, and no English text is listed twice (the second entry would never be used: a
// translation that silently never applies).
#include "solver/derivation/phrases.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

namespace frustum {
namespace {

// The slots {0}…{9} a text uses.
std::multiset<char> slots(std::string_view text) {
  std::multiset<char> out;
  for (std::size_t i = 0; i + 2 < text.size(); ++i)
    if (text[i] == '{' && text[i + 1] >= '0' && text[i + 1] <= '9' && text[i + 2] == '}')
      out.insert(text[i + 1]);
  return out;
}

std::set<char> distinct(const std::multiset<char>& s) { return {s.begin(), s.end()}; }

TEST(Phrases, EveryPhraseHasBothTranslationsWithTheSameSlots) {
  std::map<std::string_view, std::pair<std::string_view, std::string_view>> seen;
  int count = 0;
  for (const auto& table : {step_phrases(), note_phrases(), grading_phrases()})
    for (const Phrase& p : table) {
      ++count;
      EXPECT_FALSE(p.ja.empty()) << "no Japanese for: " << p.en;
      EXPECT_FALSE(p.ru.empty()) << "no Russian for: " << p.en;
      const std::set<char> en = distinct(slots(p.en));
      EXPECT_EQ(distinct(slots(p.ja)), en) << "Japanese slots differ: " << p.en << " → " << p.ja;
      EXPECT_EQ(distinct(slots(p.ru)), en) << "Russian slots differ: " << p.en << " → " << p.ru;
      const auto [it, fresh] = seen.emplace(p.en, std::pair{p.ja, p.ru});
      EXPECT_TRUE(fresh || (it->second == std::pair{p.ja, p.ru}))
          << "listed twice with different translations (one is never used): " << p.en;
    }
  EXPECT_GT(count, 500);
  for (const CountForms& f : count_forms()) {
    EXPECT_FALSE(f.one.empty() || f.few.empty() || f.many.empty()) << f.en;
  }
}

}  // namespace
}  // namespace frustum
