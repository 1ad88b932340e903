// Writing outputs so that a reader never sees half of them: one file through a temporary file
// renamed over the target, and many files made durable by one sync (FileBatch). A batch's whole
// set of outputs is published by one rename: OutputTransaction (output_transaction.hpp).
#pragma once

#include <string>
#include <vector>

namespace frustum {

// Creates missing parent directories. Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::string& path, const std::string& content);

// Many files, each written atomically, made durable by one sync instead of one per file:
// stage() writes a file to a temporary name beside its target (nothing is synced);
// commit() syncs the file system once (syncfs), renames every staged file over its target and
// syncs the directories it renamed into. A reader never sees a partial file, and once commit()
// returns every file is on disk. Without commit() (an exception, a full disk) the destructor
// removes the staged files and the targets stay as they were.
class FileBatch {
 public:
  FileBatch() = default;
  ~FileBatch();
  FileBatch(const FileBatch&) = delete;
  FileBatch& operator=(const FileBatch&) = delete;

  // Creates missing parent directories. Throws std::runtime_error naming the path on failure.
  void stage(const std::string& path, const std::string& content);
  void commit();
  // stage() in two halves, so that another process can write what this one commits:
  // write_staged() writes the temporary file beside `path` and returns its name (the caller
  // owns it until it is adopted), adopt() stages it as stage() would have, and discard()
  // removes one that will not be adopted.
  static std::string write_staged(const std::string& path, const std::string& content);
  // Replaces what a temporary file from write_staged() holds (`path`: its target, for errors).
  static void rewrite_staged(const std::string& temporary, const std::string& path,
                             const std::string& content);
  void adopt(const std::string& temporary, const std::string& path);
  static void discard(const std::string& temporary);
  std::size_t staged() const { return pending_.size(); }

  // commit() of what is staged now, done by a child process while this one carries on (generate
  // keeps taking its workers' results while a group of files is synced and renamed); staging
  // starts again empty. wait_commit() waits for it and throws its error, as commit() would have.
  // One at a time: commit_in_background() first waits for the one before, and so does commit().
  // One child commits every group, made at the first (or by start_committer()): a process made
  // per group cost this one a copy-on-write fault, and a TLB flush of the other core, on each
  // page it wrote after each fork (a third of its CPU time in generate). Where no process can
  // be made, the commit is done here. The destructor waits for the last group and ends the
  // child.
  void commit_in_background();
  void wait_commit();
  // Makes the committing child now, while this process is small (commit_in_background()
  // otherwise makes it at the first group): each page this process writes after the fork is
  // copied once, so the fewer it has then, the less it copies. False where none can be made.
  bool start_committer();

 private:
  struct Pending {
    std::string temporary, target;
  };
  static void commit_pending(std::vector<Pending>& pending);
  [[noreturn]] static void serve_commits(int fd);
  void end_committer();
  std::vector<Pending> pending_;
  int committer_ = -1;       // the process committing in the background (a pid), or -1
  int committer_fd_ = -1;    // its socket: groups to it, for each group its error message back
  bool committing_ = false;  // a group was sent and its reply not yet read
};

}  // namespace frustum
