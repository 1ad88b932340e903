#include "app/number_options.hpp"

#include <fmt/format.h>

#include <charconv>

#include "solver/shared/scene_reader.hpp"

namespace frustum::app {

std::variant<std::uint64_t, std::string> parse_whole_number(std::string_view text, std::uint64_t lo,
                                                            std::uint64_t hi) {
  const std::string range = fmt::format("a whole number from {} to {}", lo, hi);
  std::uint64_t value = 0;
  const char* const end = text.data() + text.size();
  // from_chars takes no sign, no spaces and no "0x"; it reports a value beyond 2⁶⁴ − 1.
  const auto [stop, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || stop != end || (ec != std::errc() && ec != std::errc::result_out_of_range))
    return fmt::format("expected {}, got '{}'", range, text);
  if (ec == std::errc::result_out_of_range || value < lo || value > hi)
    return fmt::format("{} is out of range: expected {}", text, range);
  return value;
}

std::variant<std::pair<int, int>, std::string> parse_size(std::string_view text) {
  const int max_side = kMaxViewport;
  const std::string expected = fmt::format("expected WxH with 1 ≤ W, H ≤ {}, got '{}'", max_side,
                                           text.substr(0, std::min<std::size_t>(text.size(), 40)));
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos) return expected;
  const auto side = [&](std::string_view digits) {
    return parse_whole_number(digits, 1, static_cast<std::uint64_t>(max_side));
  };
  const auto w = side(text.substr(0, x)), h = side(text.substr(x + 1));
  if (!std::holds_alternative<std::uint64_t>(w) || !std::holds_alternative<std::uint64_t>(h))
    return expected;
  return std::pair{static_cast<int>(std::get<std::uint64_t>(w)),
                   static_cast<int>(std::get<std::uint64_t>(h))};
}

}  // namespace frustum::app
