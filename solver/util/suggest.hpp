// "Did you mean …?" for misspelled names.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace frustum {

std::size_t edit_distance(std::string_view a, std::string_view b);

// The closest candidate within a small distance, or "" when none is close.
std::string closest_name(std::string_view name, const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" or "".
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace frustum
