// docs/kinds.md's kinds table is generated from the registry (each kind file's doc_given and
// doc_answers, in the registry's order): this fails when the two differ and prints the table
// to paste into docs/kinds.md (`frustum kinds --format markdown` prints it too).
#include "solver/problem/registry.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "test_util.hpp"

namespace frustum {
namespace {

// The table that starts with the kinds table's header row, up to its first non-table line.
std::string docs_kinds_table() {
  std::ifstream in(test::source_path("docs/kinds.md"));
  std::string line, table;
  while (std::getline(in, line) && line != "| kind | given | answers |") {
  }
  if (!in) return table;
  table = line + "\n";
  while (std::getline(in, line) && line.rfind("|", 0) == 0) table += line + "\n";
  return table;
}

TEST(KindsTable, DocsMatchTheRegistry) {
  const std::string generated = kinds_table_markdown(builtin_kinds());
  EXPECT_EQ(docs_kinds_table(), generated)
      << "docs/kinds.md's kinds table differs from the kinds' doc_given/doc_answers; the table "
         "to paste:\n\n"
      << generated;
}

TEST(KindsTable, KindsKeepTheirOrder) {
  // KindInfo::order decides every listing; two kinds at one position would depend on the file
  // names instead.
  const std::vector<KindInfo>& all = builtin_kinds().all();
  for (std::size_t i = 1; i < all.size(); ++i)
    EXPECT_LT(all[i - 1].order, all[i].order) << all[i - 1].name << " and " << all[i].name;
}

}  // namespace
}  // namespace frustum
