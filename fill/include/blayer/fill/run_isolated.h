// Run a fragile computation (TetGen) in a forked child process so that a crash, an
// abort or a hang becomes an exception in the caller instead of ending the program.
//
// The child runs `work` and nothing else, writes its result to a pipe and leaves with
// _exit (no atexit handlers, no stdio flush, no static destructors). It inherits a
// copy of the caller's memory, so `work` may read any data prepared before the call.
// Only the calling thread exists in the child: `work` must not wait for other threads
// (thread pools, TBB) or locks they may hold. Memory allocation is safe (glibc resets
// its allocator locks in the child).
//
// POSIX only (fork, pipe, poll, waitpid).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>

namespace blayer {

// The child did not return normally: killed by a signal (segfault, abort), exited
// without a result, timed out, or the child could not be started.
class ChildProcessError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct IsolatedOutcome {
  enum class Kind {
    kOk,              // work returned; data is its result
    kThrewInt,        // work threw an int (TetGen's error convention); thrown_int is it
    kThrewException,  // work threw something else; data is what() or a description
  };
  Kind kind = Kind::kOk;
  int thrown_int = 0;
  std::string data;
};

// Runs work() in a child process and returns what it returned or threw.
// timeout_seconds <= 0: wait indefinitely. On timeout the child is killed (SIGKILL).
// Throws ChildProcessError, with the signal number and name when there is one.
IsolatedOutcome run_isolated(const std::function<std::string()>& work, double timeout_seconds);

}  // namespace blayer
