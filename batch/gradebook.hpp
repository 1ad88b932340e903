// The gradebook of a class (gradebook.csv): a header, then one row per submission in the class's
// order — student, score, max_score, percent, status, one score per problem, source, message,
// file — and the stream that writes it while the class is graded.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "batch/batch.hpp"
#include "batch/output_transaction.hpp"

namespace frustum {

std::string gradebook_header(const ProblemSet& set);
std::string gradebook_line(const ProblemSet& set, const BatchRow& row);
// The whole text: the header and every row.
std::string gradebook_csv(const ProblemSet& set, const std::vector<BatchRow>& rows);

// Rows come in the order the children finish them and are written in the class's order: a row
// that arrives before its turn waits for the ones before it (with students taken in turn by the
// children, a few; behind a slow submission, the rows graded within its time limit), so the
// memory held is that of the rows waiting and of a buffer, not the class's. Each row, once
// written, goes to `written` (in the class's order).
class GradebookStream {
 public:
  GradebookStream(const ProblemSet& set, OutputTransaction& out, std::string relative,
                  std::function<void(BatchRow&&)> written);
  // Row `index` (0, 1, 2, …: each once).
  void add(std::size_t index, BatchRow row);
  // Writes what is buffered. Every row must have been added.
  void finish();

 private:
  void put(BatchRow&& row);
  void flush();
  const ProblemSet& set_;
  OutputTransaction& out_;
  std::string relative_;
  std::function<void(BatchRow&&)> written_;
  std::map<std::size_t, BatchRow> waiting_;
  std::size_t next_ = 0;
  std::string buffer_;
};

}  // namespace frustum
