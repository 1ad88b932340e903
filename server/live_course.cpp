#include "server/live_course.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <ctime>

#include "server/tokens.hpp"
#include "solver/input/yaml_document.hpp"

namespace frustum::server {

LiveCourse::LiveCourse(Course course, std::mutex& exact_math, Millis look_every_ms,
                       std::function<void(const std::vector<Diagnostic>&)> report)
    : exact_math_(exact_math),
      look_every_ms_(look_every_ms),
      report_(std::move(report)),
      current_(std::make_shared<const Course>(std::move(course))) {}

LiveCourse::~LiveCourse() {
  const std::lock_guard math(exact_math_);
  retired_.clear();
  current_.reset();
}

std::shared_ptr<const Course> LiveCourse::current() const {
  const std::lock_guard lock(mutex_);
  return current_;
}

std::shared_ptr<const Course> LiveCourse::at(Millis now) {
  {
    const std::lock_guard lock(mutex_);
    if (now < next_look_) return current_;
  }
  look(now, false);
  return current();
}

void LiveCourse::refresh(Millis now) { look(now, true); }

void LiveCourse::look(Millis now, bool wait) {
  // One look at a time; a request that finds one under way serves what is there meanwhile.
  std::unique_lock lock(mutex_, std::defer_lock);
  if (wait)
    lock.lock();
  else if (!lock.try_lock() || now < next_look_)
    return;
  next_look_ = now + look_every_ms_;
  std::vector<std::pair<std::size_t, std::string>> changed;  // (index in sets, the file's bytes)
  for (std::size_t i = 0; i < current_->sets.size(); ++i) {
    const CourseSet& set = current_->sets[i];
    struct stat st {};
    if (::stat(set.file.c_str(), &st) != 0) continue;  // removed or unreadable: served as it was
    const Stamp stamp{st.st_mtim.tv_sec * 1'000'000'000LL + st.st_mtim.tv_nsec, st.st_size,
                      st.st_ino};
    // A file written in the last two seconds is read whatever its stamp: two writes within one
    // tick of the file system's clock, in place, can leave the same stamp.
    const bool settled = st.st_mtim.tv_sec + 2 < ::time(nullptr);
    const auto known = stamps_.find(set.file);
    if (settled && known != stamps_.end() && known->second == stamp) continue;
    stamps_[set.file] = stamp;
    std::string bytes;
    if (read_text_file(set.file, kMaxYamlFileBytes, bytes)) continue;
    // Read into the course when it differs from what is served and was not tried already (a
    // file that failed to load is reported once).
    const std::string sha = sha256_hex(bytes);
    std::string& tried = tried_[set.file];
    if (sha != set.version && sha != tried) changed.emplace_back(i, std::move(bytes));
    tried = sha;
  }
  if (changed.empty()) return;
  const std::lock_guard math(exact_math_);
  auto next = std::make_shared<Course>(*current_);
  for (const auto& [i, bytes] : changed) {
    std::vector<Diagnostic> errors;
    std::optional<CourseSet> fresh = load_course_set(next->sets[i].file, next->roster, errors);
    if (fresh)
      next->sets[i] = std::move(*fresh);
    else if (report_)
      report_(errors);
  }
  retired_.push_back(std::move(current_));
  current_ = std::move(next);
  // A replaced course no request holds any more is freed here, under exact_math.
  retired_.erase(
      std::remove_if(retired_.begin(), retired_.end(),
                     [](const std::shared_ptr<const Course>& c) { return c.use_count() == 1; }),
      retired_.end());
}

}  // namespace frustum::server
