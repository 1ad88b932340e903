// The problem sets a command line names: a file, or every *.yaml directly inside a directory.
#pragma once

#include <string>
#include <vector>

namespace frustum::app {

// A problem-set path, or every *.yaml directly inside a directory (answer files live in
// subdirectories), in name order.
std::vector<std::string> set_files(const std::string& path);

}  // namespace frustum::app
