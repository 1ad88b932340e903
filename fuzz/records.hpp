// The fuzz targets that build a directory from their bytes read them as records separated by a
// NUL byte.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace frustum::fuzz {

// The records of `data`, at most `most` of them.
inline std::vector<std::string> records(const std::uint8_t* data, std::size_t size,
                                        std::size_t most) {
  std::vector<std::string> out(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0)
      out.emplace_back();
    else
      out.back() += static_cast<char>(data[i]);
  }
  if (out.size() > most) out.resize(most);
  return out;
}

}  // namespace frustum::fuzz
