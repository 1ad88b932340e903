// Text from outside — student ids, file names, answers as written, messages quoting them — as
// every output shows it: valid UTF-8 without control characters, so that no id or file name can
// move a terminal's cursor, end a CSV row, hide a row, break a CSV reader (NUL) or make an
// output that is not UTF-8. A byte that is not part of UTF-8 is shown as \xNN (a file named in
// CP932 stays recognisable: \x93\xFA…), a control character as \uXXXX: C0, DEL and C1
// (category Cc), the line and paragraph separators (Zl, Zp) and the bidirectional embeddings,
// overrides and isolates, which reorder the text around them. Everything else is kept.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frustum {

// Whether LF and TAB are shown as themselves (a page's text) or escaped (a CSV cell, a
// terminal line: one line).
enum class Breaks { Escaped, Kept };

std::string visible_text(std::string_view text, Breaks breaks = Breaks::Escaped);

// Each cell through visible_text: the cells of a CSV that Frustum writes (gradebooks and their
// Canvas and Moodle imports), before csv_row.
std::vector<std::string> visible_cells(std::vector<std::string> cells);

// The first character of `text` that visible_text escapes, if any: at byte `offset`, the code
// point `code` (or, when `byte`, a byte that is not UTF-8, with its value in `code`).
struct Hidden {
  std::size_t offset = 0;
  long code = 0;
  bool byte = false;
};
std::optional<Hidden> first_hidden(std::string_view text, Breaks breaks = Breaks::Escaped);

// "U+001B (a control character)", "the byte 0x93 (not UTF-8 text)": for messages.
std::string describe(const Hidden& h);

}  // namespace frustum
