#include "grader/student_id.hpp"

#include <fmt/format.h>
#include <utf8proc.h>

#include <cstdlib>
#include <memory>

#include "grader/visible_text.hpp"
#include "solver/util/expression.hpp"

namespace frustum {

namespace {

// The length of the space separator (Zs) at `i`, or 0.
std::size_t space_at(std::string_view s, std::size_t i) {
  utf8proc_int32_t cp = 0;
  const utf8proc_ssize_t n =
      utf8proc_iterate(reinterpret_cast<const utf8proc_uint8_t*>(s.data() + i),
                       static_cast<utf8proc_ssize_t>(s.size() - i), &cp);
  return n > 0 && utf8proc_category(cp) == UTF8PROC_CATEGORY_ZS ? static_cast<std::size_t>(n) : 0;
}

// The start of the space separator that ends s[0, end), or `end`.
std::size_t space_before(std::string_view s, std::size_t end) {
  for (std::size_t back = 1; back <= 4 && back <= end; ++back)
    if (space_at(s, end - back) == back) return end - back;
  return end;
}

std::string_view trimmed(std::string_view s) {
  std::size_t start = 0, end = s.size();
  while (start < end)
    if (const std::size_t n = space_at(s, start))
      start += n;
    else
      break;
  while (end > start) {
    const std::size_t b = space_before(s, end);
    if (b == end) break;
    end = b;
  }
  return s.substr(start, end - start);
}

}  // namespace

StudentId read_student_id(std::string_view written) {
  StudentId out;
  const std::string_view id = trimmed(written);
  if (id.empty()) {
    out.problem =
        written.empty() ? "the student id is empty" : "the student id is blank (only spaces)";
    return out;
  }
  if (id.size() > kMaxStudentIdBytes) {
    out.problem = fmt::format("the student id is {} bytes long (the limit is {} bytes)", id.size(),
                              kMaxStudentIdBytes);
    return out;
  }
  std::optional<Hidden> h = first_hidden(id);
  if (!h)
    if (const std::size_t at = id.find("\xEF\xBF\xBD"); at != std::string_view::npos)
      h = Hidden{at, 0xFFFD, false};
  if (h) {
    const bool replaced = h->code == 0xFFFD && !h->byte;
    out.problem = fmt::format(
        "the student id {} holds {} at byte {}: write the id as plain text",
        quote_excerpt(visible_text(id)),
        replaced ? "U+FFFD (the replacement character, read in place of bytes that are not UTF-8 "
                   "text or of a control character)"
                 : describe(*h),
        h->offset + 1);
    return out;
  }
  out.id = std::string(id);
  return out;
}

std::string student_id_key(std::string_view id) {
  const std::string_view t = trimmed(id);
  utf8proc_uint8_t* mapped = nullptr;
  const utf8proc_ssize_t n = utf8proc_map(
      reinterpret_cast<const utf8proc_uint8_t*>(t.data()), static_cast<utf8proc_ssize_t>(t.size()),
      &mapped,
      static_cast<utf8proc_option_t>(UTF8PROC_STABLE | UTF8PROC_COMPOSE | UTF8PROC_COMPAT |
                                     UTF8PROC_CASEFOLD | UTF8PROC_IGNORE));
  // Not UTF-8 (an id that read_student_id refuses): the bytes are their own key.
  if (n < 0) return std::string(t);
  const std::unique_ptr<utf8proc_uint8_t, decltype(&std::free)> owned(mapped, &std::free);
  return std::string(reinterpret_cast<const char*>(mapped), static_cast<std::size_t>(n));
}

}  // namespace frustum
