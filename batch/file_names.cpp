#include "batch/file_names.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <map>
#include <set>

#include "grader/student_id.hpp"
#include "solver/util/expression.hpp"
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

std::vector<Diagnostic> look_alike_problem_ids(const ProblemSet& set) {
  std::vector<Diagnostic> out;
  std::map<std::string, const ProblemSpec*> first;  // look → the first problem with it
  for (const ProblemSpec& p : set.problems) {
    std::string look = student_id_key(p.id);
    for (char& c : look)
      if (static_cast<unsigned char>(c) < 0x80 && !std::isalnum(static_cast<unsigned char>(c)))
        c = '_';
    const auto [it, fresh] = first.emplace(look, &p);
    if (!fresh)
      out.push_back(Diagnostic{
          p.where, p.field + ".id",
          fmt::format("warning: problem id {} differs from {} ({}) only in case, spaces or "
                      "signs: each export keeps both, but a student may answer one for the other",
                      quote_excerpt(p.id), quote_excerpt(it->second->id), it->second->field)});
  }
  return out;
}

}  // namespace frustum
