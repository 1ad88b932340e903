// The items of a list answer (edge lists, a drawing order, the rows of a frame buffer) as the
// student meant them: split where one text separates them, and unordered pairs ("0-3", an edge)
// spelled as the key spells them (docs/grading.md §1, §3).
#pragma once

#include <string>
#include <vector>

namespace frustum {

// The student's items, each split further at the separators a list written as one text uses —
// commas, semicolons, slashes, arrows (→, ->, ⇒, =>), the ideographic comma and spaces — except
// any separator that an item of the key itself contains (a z-buffer step is rows joined by "/").
// "0 → 1" is the items 0 and 1; "1133/1222/1222" the three rows. Spaces around a dash stay
// inside one item ("0 - 1" is the pair 0-1).
std::vector<std::string> items_as_written(const std::vector<std::string>& got,
                                          const std::vector<std::string>& key);

// An unordered pair written either way round, with any dash or as "(a, b)", in the key's
// spelling when the key has that pair ("1-0" → "0-1"); otherwise the item as written.
std::string pair_as_in_key(const std::string& item, const std::vector<std::string>& key);

// Is the item written as an unordered pair ("a-b", "(a, b)")?
bool is_pair(const std::string& item);

// The first item that cannot be an item of this list, read against the key's items: a word
// (any letter) where every item of the key is a number ("then" in "0 then 1"), or, where the
// items are unordered pairs, an item that is no pair. Empty when every item can be one.
std::string unreadable_item(const std::vector<std::string>& items,
                            const std::vector<std::string>& key, bool pairs);

}  // namespace frustum
