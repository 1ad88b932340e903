// Running one piece of work in a child process with a time limit, so that a submission that is
// slow, or that crashes the grader, costs only its own result. The work returns a string (the
// child's whole output), which is handed back through a pipe.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace frustum {

struct IsolatedResult {
  enum class Status { Ok, Timeout, Crashed, Failed };
  Status status = Status::Failed;
  std::string output;  // what the work returned (Ok only)
  std::string
      error;  // why there is no output: "time limit of 10 s exceeded", "killed by signal 11"
};

// Forks; the child runs `work` and writes its result to the parent, which waits at most
// `seconds` (then kills the child). Without fork (a failure to create the process), runs `work`
// in this process instead. `max_output` bounds what the parent accepts.
IsolatedResult run_isolated(const std::function<std::string()>& work, double seconds,
                            std::size_t max_output = 64u << 20);

// How run_isolated_each hands items to its `jobs` children.
enum class Shares {
  // Cut into `jobs` contiguous shares, one per child: item i lands in the same child for a given
  // count and jobs (a caller that relies on each child seeing only its own share's items).
  Contiguous,
  // Each child takes the next item nobody has taken yet: the children finish together however
  // uneven the items or the machine's load (a caller whose items are independent).
  Dynamic,
};

// Child processes that ended their work and are still exiting (the kernel unmapping what they
// used takes milliseconds): the destructor waits for them, so that whoever made them goes on
// with its own work meanwhile (grade_batch publishes the class while its children end).
class Reaper {
 public:
  Reaper() = default;
  ~Reaper();
  Reaper(const Reaper&) = delete;
  Reaper& operator=(const Reaper&) = delete;
  void adopt(int pid) { pids_.push_back(pid); }

 private:
  std::vector<int> pids_;
};

// Runs work(0) … work(count − 1) in child processes, each item under its own time limit, and
// returns one result per item in order. `jobs` children share the items (`shares` says how) and
// stream each result back as it finishes (so a class costs one fork per child, not one per
// student); when an item times out or crashes its child, that item alone is marked and a fresh
// child carries on.
// `on_result` (optional) is called in this process after each item: in each share's order
// (shares interleave) when Contiguous, in the order items finish when Dynamic; what it moves out
// of the result (the output) is not kept.
// `stop` (optional) is asked after each on_result: once it says true, each child finishes the
// item it is on (its result is handed over as usual) and starts no other; the items never
// started are left Failed ("not run") without an on_result call.
// `reaper` (optional) is handed the children that end with nothing owed, instead of waiting
// here for each to exit; without one, every child has exited when this returns.
std::vector<IsolatedResult> run_isolated_each(
    std::size_t count, const std::function<std::string(std::size_t)>& work, double seconds,
    const std::function<void(std::size_t index, IsolatedResult&)>& on_result = {},
    std::size_t max_output = 64u << 20, std::size_t jobs = 1,
    const std::function<bool()>& stop = {}, Shares shares = Shares::Contiguous,
    Reaper* reaper = nullptr);

}  // namespace frustum
