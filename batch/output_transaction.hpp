// A batch's whole set of outputs (gradebook, feedback pages, Gradescope results) written into a
// run directory of its own and published by one rename; grading the class again reuses the run
// before the published one instead of deleting one run and creating another.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

namespace frustum {

// A batch's outputs under `dir`, published all at once. Layout:
//   dir/.frustum/lock            held (flock) while a batch writes here
//   dir/.frustum/run-N/...       the outputs of run N
//   dir/.frustum/current         symlink to the published run-N (replaced by one rename)
//   dir/NAME                     symlink to .frustum/current/NAME, for each published NAME
// The constructor takes the lock (a second batch on the same directory is refused) and opens the
// run directory; write() puts files in it; commit() syncs them and swaps `current` in one rename.
// A kill at any moment leaves the previous complete outputs (or none), never a mix. Without
// commit() (an exception, a full disk) the destructor removes the new run and the published
// outputs stay as they were. The lock is released when the process ends, however it ends.
//
// The run before the published one is kept (dir/.frustum/run-(N−1), readable until the next
// run) and is what the next run is written into when that run names its files (`files`): what it
// holds outside them is removed first, and every file is then overwritten in place. A run that
// names its files also clears the run it replaces, once published, of the files it does not
// have itself (a student of another section graded into the same directory before). Regrading a
// class therefore deletes and creates no files: on ext4 mounted with `discard` each deletion
// waits for the disk to trim the file's blocks, and without a journal every file created within
// minutes of a deletion makes the kernel pass over the recently freed inodes.
// Without `files`, a fresh run directory is made and the kept run removed.
//
// Nothing Frustum did not write is deleted. Each published run records which files it wrote
// (dir/.frustum/files-N: their names' hashes); when a run is cleared, what it holds beyond them
// (notes put into dir/feedback/ by hand) is moved to dir/set-aside/ (same relative path, `~2`…
// when taken), and so is a real file or directory found at a published name (a gradebook.csv
// written there by hand). set_aside() lists each such move for the caller to say.
class OutputTransaction {
 public:
  // `names`: what is published (a name without an extension is a directory). `files`: every
  // file this run may write, relative to the run ("feedback/s1.md"), when it is known up front.
  // Throws std::runtime_error with a sentence for a person (not writable, locked by pid N).
  OutputTransaction(std::string dir, std::vector<std::string> names,
                    std::optional<std::unordered_set<std::string>> files = std::nullopt);
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // `relative` is under one of `names` ("feedback/s1.md", "gradebook.csv", "katex/fonts/f.woff2";
  // subdirectories are made as needed).
  void write(const std::string& relative, const std::string& content);
  // Adds `content` at the end of a file of this run (made when there is none). In a kept run the
  // file may hold the earlier run's text: write() it first (the gradebook starts empty so).
  void append(const std::string& relative, const std::string& content);
  // Takes back a file of this run (none there is fine).
  void remove(const std::string& relative);
  // Has the disk write what this run holds so far, and waits for it: called while other
  // processes go on writing (a batch's children grade while the parent waits here), it leaves
  // commit()'s sync only what came after, instead of the whole run at the end. Not a point of
  // durability: an error is kept and thrown by commit().
  void write_back();
  void commit();

  // Where a published file can be read: dir/relative.
  std::string published_path(const std::string& relative) const;
  // Whether this run is written into the kept run (files overwritten in place).
  bool reused() const { return reused_; }
  // Files and directories Frustum did not write, moved out of the way: (from, to), both under dir.
  const std::vector<std::pair<std::string, std::string>>& set_aside() const { return set_aside_; }

 private:
  std::string dir_;
  std::vector<std::string> names_;
  std::string run_;  // dir/.frustum/run-N being written
  int lock_fd_ = -1;
  // The run's directory, open from the start: every sync goes through it, so that a write error
  // the disk reports at any time after the run began reaches commit().
  int run_fd_ = -1;
  int write_back_error_ = 0;  // what write_back() met (errno), thrown by commit()
  bool committed_ = false;
  bool reused_ = false;
  // With the run's files named: their directories, and the names as sorted hashes, to clear the
  // kept run (before writing) and the replaced run (once published) of what this run does not
  // have.
  bool files_named_ = false;
  std::unordered_set<std::string> dirs_;
  std::vector<std::uint64_t> file_hashes_;
  std::vector<std::pair<std::string, std::string>> set_aside_;
  std::vector<std::uint64_t> written_;  // without `files`: the names write() and append() wrote
  bool has_file(const std::string& relative) const;
  // Moves `path` (a run's `relative`, or a published name) to dir/set-aside/relative.
  void move_aside(const std::filesystem::path& path, const std::string& relative);
  // Leaves in the run directory `run` only what `keep` says this run writes; what the run's own
  // record says Frustum wrote there is removed, anything else moved aside.
  void clear_run(const std::filesystem::path& run,
                 const std::function<bool(const std::string&)>& keep);
  void put(const std::string& relative, const std::string& content, int flags);
  int open_file(const std::string& relative, int flags) const;
  void overwrite(int fd, const std::string& relative, const std::string& content);
};

}  // namespace frustum
