// Writing an output file so that a reader never sees half of it: the text goes to a temporary
// file in the same directory, is flushed to disk, and is renamed over the target.
#pragma once

#include <string>

namespace frustum {

// Creates missing parent directories. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace frustum
