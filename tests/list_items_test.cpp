// list_items: a list answer's items as the student meant them — split where one text separates
// them, and unordered pairs in the key's spelling.
#include "grader/list_items.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace frustum {
namespace {

using Items = std::vector<std::string>;

TEST(ListItems, OneTextSplitsAtTheSeparatorsStudentsUse) {
  const Items order = {"0", "1", "2"};
  for (const std::string text : {"0 → 1 → 2", "0 -> 1 -> 2", "0 ⇒ 1 ⇒ 2", "0/1/2", "0; 1; 2",
                                 "0 1 2", "0、1、2", "0 ，1 ，2", "  0  =>1=>  2 "})
    EXPECT_EQ(items_as_written({text}, order), order) << text;
  // Items already apart stay as they are; empty pieces go.
  EXPECT_EQ(items_as_written({"0", "1", "2"}, order), order);
  EXPECT_EQ(items_as_written({"0 → → 1"}, order), (Items{"0", "1"}));
  EXPECT_EQ(items_as_written({"012"}, order), (Items{"012"}));
}

TEST(ListItems, ASeparatorTheKeysItemsContainIsNotOne) {
  // A z-buffer step is rows joined by "/": steps are split at arrows and commas, not slashes.
  const Items steps = {"A../AA.", "A.B/AAB"};
  EXPECT_EQ(items_as_written({"A../AA. → A.B/AAB"}, steps), steps);
  EXPECT_EQ(items_as_written({"A../AA.; A.B/AAB"}, steps), steps);
  // A label with a space keeps it.
  const Items labels = {"front wall", "roof"};
  EXPECT_EQ(items_as_written({"front wall → roof"}, labels), labels);
}

TEST(ListItems, PairsStayWhole) {
  const Items edges = {"0-1", "2-3"};
  EXPECT_EQ(items_as_written({"0 - 1 2 – 3"}, edges), (Items{"0-1", "2–3"}));
  EXPECT_EQ(items_as_written({"(0, 1) (2, 3)"}, edges), (Items{"(0, 1)", "(2, 3)"}));
  EXPECT_EQ(items_as_written({"0->1"}, edges), (Items{"0", "1"}));  // an arrow is not an edge
}

TEST(ListItems, UnorderedPairsTakeTheKeysSpelling) {
  const Items key = {"0-1", "1-2", "A-b"};
  for (const std::string written : {"0-1", "1-0", "1 - 0", "1–0", "1—0", "1−0", "(1, 0)", "[0,1]"})
    EXPECT_EQ(pair_as_in_key(written, key), "0-1") << written;
  EXPECT_EQ(pair_as_in_key("2-1", key), "1-2");
  EXPECT_EQ(pair_as_in_key("b-A", key), "A-b");
  EXPECT_EQ(pair_as_in_key("B-a", key), "A-b");  // the labels' case as the key writes it
  // Not a pair of the key: its ends, joined the usual way; not a pair at all: as written.
  EXPECT_EQ(pair_as_in_key("3 – 0", key), "3-0");
  EXPECT_EQ(pair_as_in_key("0-2", key), "0-2");
  EXPECT_EQ(pair_as_in_key("7", key), "7");
  EXPECT_EQ(pair_as_in_key("-1", key), "-1");
  EXPECT_EQ(pair_as_in_key("(1, 2, 3)", key), "(1, 2, 3)");
}

// Property: any order of the key's items, each pair either way round, joined by any one
// separator, reads back as the key's items in that order.
TEST(ListItems, EveryJoinOfTheKeyReadsBack) {
  std::mt19937 rng(7);
  const Items key = {"0-1", "0-2", "1-3", "2-3", "4-5", "10-11"};
  const std::vector<std::string> joins = {", ", " → ", " -> ", "/", "; ", " ", "、"};
  for (int round = 0; round < 500; ++round) {
    Items shuffled = key;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const std::string& join = joins[rng() % joins.size()];
    std::string text;
    Items expected;
    for (const std::string& item : shuffled) {
      std::string written = item;
      if (rng() % 2) {
        const std::size_t dash = item.find('-');
        written = item.substr(dash + 1) + (rng() % 2 ? " - " : "–") + item.substr(0, dash);
      }
      text += (text.empty() ? "" : join) + written;
      expected.push_back(item);
    }
    Items read = items_as_written({text}, key);
    for (std::string& item : read) item = pair_as_in_key(item, key);
    EXPECT_EQ(read, expected) << text;
  }
}

}  // namespace
}  // namespace frustum
