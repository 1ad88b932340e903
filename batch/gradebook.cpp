#include "batch/gradebook.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <utility>

#include "batch/csv.hpp"
#include "grader/visible_text.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

namespace {

std::string number_text(double v) { return format_approx(v, 6); }

// Written to the run's file in pieces of about this size.
constexpr std::size_t kFlushBytes = 64u << 10;

}  // namespace

std::string gradebook_header(const ProblemSet& set) {
  std::vector<std::string> header = {"student", "score", "max_score", "percent", "status"};
  for (const ProblemSpec& p : set.problems) header.push_back(p.id);
  header.insert(header.end(), {"source", "message", "file"});
  return csv_row(visible_cells(std::move(header)));
}

std::string gradebook_line(const ProblemSet& set, const BatchRow& r) {
  std::vector<std::string> f = {
      r.student, number_text(r.score), number_text(r.max_score),
      r.max_score > 0 ? fmt::format("{:.1f}", 100.0 * r.score / r.max_score) : "", r.status};
  for (std::size_t i = 0; i < set.problems.size(); ++i)
    f.push_back(i < r.problem_scores.size() ? number_text(r.problem_scores[i]) : "");
  f.push_back(r.source);
  f.push_back(r.message);
  f.push_back(r.feedback_stem);
  // Ids, file names and messages as visible text: `cat gradebook.csv` shows every row as it is.
  return csv_row(visible_cells(std::move(f)));
}

std::string gradebook_csv(const ProblemSet& set, const std::vector<BatchRow>& rows) {
  std::string out = gradebook_header(set);
  for (const BatchRow& r : rows) out += gradebook_line(set, r);
  return out;
}

GradebookStream::GradebookStream(const ProblemSet& set, OutputTransaction& out,
                                 std::string relative, std::function<void(BatchRow&&)> written)
    : set_(set), out_(out), relative_(std::move(relative)), written_(std::move(written)) {
  buffer_ = gradebook_header(set_);
  out_.write(relative_, "");  // the file exists from the start, even for a class of none
}

void GradebookStream::add(std::size_t index, BatchRow row) {
  if (index != next_) {
    waiting_.emplace(index, std::move(row));
    return;
  }
  put(std::move(row));
  for (auto it = waiting_.begin(); it != waiting_.end() && it->first == next_;
       it = waiting_.erase(it))
    put(std::move(it->second));
}

void GradebookStream::put(BatchRow&& row) {
  buffer_ += gradebook_line(set_, row);
  ++next_;
  if (written_) written_(std::move(row));
  if (buffer_.size() >= kFlushBytes) flush();
}

void GradebookStream::flush() {
  out_.append(relative_, buffer_);
  buffer_.clear();
}

void GradebookStream::finish() {
  if (!waiting_.empty()) throw std::logic_error(fmt::format("gradebook: row {} never came", next_));
  flush();
}

}  // namespace frustum
