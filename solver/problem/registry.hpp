// The registry of problem kinds: one place that lists every kind, built explicitly (no
// static-initialisation tricks that a linker may drop).
#pragma once

#include <string>
#include <vector>

#include "solver/problem/kind.hpp"

namespace frustum {

class Registry {
 public:
  void add(KindInfo kind);
  const KindInfo* find(const std::string& name) const;
  std::vector<std::string> names() const;
  const std::vector<KindInfo>& all() const { return kinds_; }

 private:
  std::vector<KindInfo> kinds_;
};

// Every built-in kind.
const Registry& builtin_kinds();

// Every solver/kinds/<name>.cpp defines `KindInfo <name>_kind()`; registry.cpp declares and
// calls them all from the list CMake makes of those files (kinds_list.inc in the build tree),
// in the order of KindInfo::order. A kind file without its function fails to link.

// The kinds table of docs/kinds.md (Markdown), one row per kind from
// KindInfo::doc_given/doc_answers.
std::string kinds_table_markdown(const Registry& registry);

}  // namespace frustum
