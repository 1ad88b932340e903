#include "app/set_files.hpp"

#include <algorithm>
#include <filesystem>

namespace frustum::app {

std::vector<std::string> set_files(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return {path};
  std::vector<std::string> files;
  std::error_code type_ec;  // a symlink loop is listed, and then reported as unreadable
  for (const auto& entry : fs::directory_iterator(path, ec))
    if (!entry.is_directory(type_ec) && entry.path().extension() == ".yaml")
      files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace frustum::app
