#include "blayer/fill/run_isolated.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>

#include "blayer/core/stopwatch.h"

namespace blayer {
namespace {

// First byte of the child's message: which IsolatedOutcome::Kind follows.
constexpr char kTagOk = 'K';
constexpr char kTagInt = 'I';
constexpr char kTagException = 'E';

// How often the parent looks at the child's exit status while waiting for data. A
// grandchild of another thread may have inherited the pipe's write end, so end of file
// alone cannot be trusted to mean that the child is done.
constexpr int kPollMilliseconds = 50;

bool write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

[[noreturn]] void child_main(int fd, const std::function<std::string()>& work) {
  std::string message;
  int code = 0;
  try {
    std::string data = work();
    message.reserve(data.size() + 1);
    message.push_back(kTagOk);
    message += data;
  } catch (int e) {
    message.assign(1, kTagInt);
    message.append(reinterpret_cast<const char*>(&e), sizeof e);
    code = 2;
  } catch (const std::exception& e) {
    message.assign(1, kTagException);
    message += e.what();
    code = 3;
  } catch (...) {
    message.assign(1, kTagException);
    message += "unknown exception";
    code = 3;
  }
  const bool ok = write_all(fd, message.data(), message.size());
  ::close(fd);
  ::_exit(ok ? code : 4);
}

std::string describe_status(int status) {
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = ::strsignal(sig);
    return "child process killed by signal " + std::to_string(sig) + " (" +
           (name ? name : "unknown") + ")";
  }
  if (WIFEXITED(status))
    return "child process exited with status " + std::to_string(WEXITSTATUS(status)) +
           " without a complete result";
  return "child process ended abnormally";
}

// Appends what can be read from fd now, without blocking.
void drain(int fd, std::string& received) {
  char buffer[1 << 16];
  ::fcntl(fd, F_SETFL, O_NONBLOCK);
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
      received.append(buffer, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;
    }
  }
}

struct ChildEnd {
  std::string received;  // everything the child wrote
  int status = 0;        // waitpid status
  bool timed_out = false;
};

// Reads the child's message until end of file, its exit or the timeout (then it is
// killed), and reaps it.
ChildEnd wait_for_child(int fd, pid_t pid, double timeout_seconds) {
  const Stopwatch clock;
  ChildEnd end;
  char buffer[1 << 16];
  bool exited = false;
  for (bool eof = false; !eof;) {
    int wait_ms = kPollMilliseconds;
    if (timeout_seconds > 0.0)
      wait_ms = std::max(0, std::min(wait_ms, static_cast<int>((timeout_seconds - clock.seconds()) * 1000.0)));
    pollfd pfd{fd, POLLIN, 0};
    const int r = ::poll(&pfd, 1, wait_ms);
    if (r < 0 && errno != EINTR) break;
    if (r > 0) {
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n > 0) {
        end.received.append(buffer, static_cast<std::size_t>(n));
        continue;
      }
      if (n == 0) eof = true;
      if (n < 0 && errno != EINTR && errno != EAGAIN) break;
    }
    if (::waitpid(pid, &end.status, WNOHANG) == pid) {
      exited = true;
      drain(fd, end.received);  // what the child wrote before it exited
      break;
    }
    if (timeout_seconds > 0.0 && clock.seconds() > timeout_seconds) {
      end.timed_out = true;
      ::kill(pid, SIGKILL);
      break;
    }
  }
  if (!exited) {
    while (::waitpid(pid, &end.status, 0) < 0 && errno == EINTR) {
    }
  }
  return end;
}

IsolatedOutcome parse_outcome(const ChildEnd& end) {
  if (!WIFEXITED(end.status) || end.received.empty()) throw ChildProcessError(describe_status(end.status));
  IsolatedOutcome out;
  const int code = WEXITSTATUS(end.status);
  const char tag = end.received[0];
  if (tag == kTagOk && code == 0) {
    out.kind = IsolatedOutcome::Kind::kOk;
    out.data = end.received.substr(1);
  } else if (tag == kTagInt && code == 2 && end.received.size() == 1 + sizeof(int)) {
    out.kind = IsolatedOutcome::Kind::kThrewInt;
    std::memcpy(&out.thrown_int, end.received.data() + 1, sizeof(int));
  } else if (tag == kTagException && code == 3) {
    out.kind = IsolatedOutcome::Kind::kThrewException;
    out.data = end.received.substr(1);
  } else {
    throw ChildProcessError(describe_status(end.status));
  }
  return out;
}

}  // namespace

IsolatedOutcome run_isolated(const std::function<std::string()>& work, double timeout_seconds) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0)
    throw ChildProcessError(std::string("cannot create a pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(fds[0]);
    ::close(fds[1]);
    throw ChildProcessError(std::string("cannot start a child process: ") + std::strerror(err));
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_main(fds[1], work);
  }
  ::close(fds[1]);
  const ChildEnd end = wait_for_child(fds[0], pid, timeout_seconds);
  ::close(fds[0]);
  if (end.timed_out)
    throw ChildProcessError("child process timed out after " + std::to_string(timeout_seconds) +
                            " s and was killed (signal " + std::to_string(SIGKILL) + ")");
  return parse_outcome(end);
}

}  // namespace blayer
