// The course a running `frustum serve` serves: its sets as their files are now. Loaded at start;
// a set whose file changed on disk (saved from the authoring page, edited for the command line,
// saved by another instance's instructor) is read again by the first request after the change,
// at most one look at the files a second. A file that no longer loads leaves its set as it was
// served, its errors printed once. New set files and roster.csv/instructors.csv are read at start
// only.
//
// A request holds the course it started with (a snapshot) to its end, so a reload never changes
// a page half-way. GiNaC's numbers in the sets are not thread-safe: copying, loading and freeing
// sets happen under `exact_math`, and a replaced course is freed only there, once no request
// holds it.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "server/course.hpp"
#include "server/store.hpp"

namespace frustum::server {

class LiveCourse {
 public:
  // `report` receives the errors of a file that no longer loads (the server prints them).
  LiveCourse(Course course, std::mutex& exact_math, Millis look_every_ms = 1000,
             std::function<void(const std::vector<Diagnostic>&)> report = {});
  ~LiveCourse();
  LiveCourse(const LiveCourse&) = delete;
  LiveCourse& operator=(const LiveCourse&) = delete;

  // The course as of `now` (its files looked at when a second has passed since the last look).
  std::shared_ptr<const Course> at(Millis now);
  // The course as it is, without looking at the files.
  std::shared_ptr<const Course> current() const;
  // Looks at the files now (after a save, so that the next request serves what was saved).
  void refresh(Millis now);

 private:
  struct Stamp {  // a file's stat: a rename (an atomic save) changes its inode
    std::int64_t modified_ns = 0;
    std::int64_t size = 0;
    std::uint64_t inode = 0;
    bool operator==(const Stamp&) const = default;
  };
  void look(Millis now, bool wait);

  std::mutex& exact_math_;
  const Millis look_every_ms_;
  std::function<void(const std::vector<Diagnostic>&)> report_;
  mutable std::mutex mutex_;  // current_, stamps_, tried_, retired_, next_look_
  std::shared_ptr<const Course> current_;
  std::map<std::string, Stamp> stamps_;       // by file; none yet: the first look reads each file
  std::map<std::string, std::string> tried_;  // by file: the SHA-256 of the bytes last read
  std::vector<std::shared_ptr<const Course>>
      retired_;  // replaced, freed when no request holds them
  Millis next_look_ = 0;
};

}  // namespace frustum::server
