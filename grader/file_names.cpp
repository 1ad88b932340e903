#include "grader/file_names.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <set>

#include "solver/util/words.hpp"

namespace frustum {

namespace {

constexpr std::size_t kMaxNameBytes = 120;  // file systems allow 255; room for suffixes

}  // namespace

std::string file_name_for(const std::string& id) {
  std::string out;
  for (std::size_t i = 0; i < id.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(id[i]);
    // Not first: a '.' (a hidden file, ".."), a '-' (read as an option by a shell command, and
    // guarded as a formula in the gradebook's `file` column, which then named no file).
    const bool keep = std::isalnum(c) || c == '_' || ((c == '.' || c == '-') && i > 0);
    out += keep ? std::string(1, static_cast<char>(c)) : fmt::format("%{:02X}", c);
  }
  if (out.empty()) return "%";
  if (out.size() > kMaxNameBytes) {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a of the whole id
    for (const char c : id) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    std::size_t cut = kMaxNameBytes - 18;
    if (out[cut - 1] == '%')
      cut -= 1;  // never split a %HH
    else if (out[cut - 2] == '%')
      cut -= 2;
    out = out.substr(0, cut) + fmt::format("~{:016x}", h);
  }
  return out;
}

std::vector<std::string> unique_file_names(const std::vector<std::string>& ids) {
  std::vector<std::string> out;
  std::set<std::string> taken;  // lower-cased
  for (const std::string& id : ids) {
    const std::string base = file_name_for(id);
    std::string name = base;
    for (int n = 2; !taken.insert(ascii_lower(name)).second; ++n)
      name = fmt::format("{}~{}", base, n);
    out.push_back(name);
  }
  return out;
}

}  // namespace frustum
