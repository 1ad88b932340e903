// Numbers of the command line read exactly: digits only, compared with their range before any
// conversion, so that a value too large for its type is refused instead of wrapping
// (`--size 4294967297x1` once rendered 1 × 1, `--seed -1` was 2⁶⁴ − 1).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace frustum::app {

// A whole number from `lo` to `hi` written in decimal digits (no sign, no spaces); otherwise the
// reason, naming the range.
std::variant<std::uint64_t, std::string> parse_whole_number(std::string_view text, std::uint64_t lo,
                                                            std::uint64_t hi);

// `--size WxH`: both sides from 1 to kMaxViewport (a scene's own limit); otherwise the reason.
// The total (kMaxScenePixels) is the render's to check, as for a scene's viewport.
std::variant<std::pair<int, int>, std::string> parse_size(std::string_view text);

}  // namespace frustum::app
