// The inputs of the fuzz targets that build several things from one input: records separated
// by NUL bytes, at most `max` of them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace frustum::fuzz {

inline std::vector<std::string> records(const std::uint8_t* data, std::size_t size,
                                        std::size_t max) {
  std::vector<std::string> out(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0)
      out.emplace_back();
    else
      out.back() += static_cast<char>(data[i]);
  }
  if (out.size() > max) out.resize(max);
  return out;
}

}  // namespace frustum::fuzz
