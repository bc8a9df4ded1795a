#include "parse_in_child.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "blayer/core/address_sanitizer.h"
#include "blayer/core/errors.h"

namespace blayer::detail {

namespace {

// The child's message: one status byte, then the soup or an error text.
enum Status : char { kSoup = 'S', kInputError = 'E', kOtherError = 'X' };

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

template <class T>
bool take(const std::string& in, std::size_t& pos, T* v) {
  if (in.size() - pos < sizeof(T)) return false;
  std::memcpy(v, in.data() + pos, sizeof(T));
  pos += sizeof(T);
  return true;
}

std::string encode(const PolygonSoup& s) {
  std::string out(1, kSoup);
  put(out, static_cast<std::uint64_t>(s.points.size()));
  for (const Vec3& p : s.points) put(out, p);
  put(out, static_cast<std::uint64_t>(s.faces.size()));
  for (const auto& f : s.faces) {
    put(out, static_cast<std::uint64_t>(f.size()));
    if (!f.empty()) out.append(reinterpret_cast<const char*>(f.data()), f.size() * sizeof(int));
  }
  return out;
}

bool decode(const std::string& in, PolygonSoup* s) {
  std::size_t pos = 1;
  std::uint64_t n = 0;
  if (!take(in, pos, &n) || n > (in.size() - pos) / sizeof(Vec3)) return false;
  s->points.resize(n);
  for (Vec3& p : s->points) take(in, pos, &p);
  if (!take(in, pos, &n) || n > (in.size() - pos) / sizeof(std::uint64_t)) return false;
  s->faces.resize(n);
  for (auto& f : s->faces) {
    std::uint64_t k = 0;
    if (!take(in, pos, &k) || k > (in.size() - pos) / sizeof(int)) return false;
    f.resize(k);
    if (k > 0) std::memcpy(f.data(), in.data() + pos, k * sizeof(int));  // an empty face has no data()
    pos += k * sizeof(int);
  }
  return pos == in.size();
}

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void run_child(const std::function<PolygonSoup()>& parse, int fd) {
  std::string message;
  try {
    message = encode(parse());
  } catch (const InputError& e) {
    message = std::string(1, kInputError) + e.what();
  } catch (const std::exception& e) {
    message = std::string(1, kOtherError) + e.what();
  } catch (...) {
    message = std::string(1, kOtherError) + "an unknown exception";
  }
  write_all(fd, message);
  ::close(fd);
  ::_exit(0);
}

std::string read_all(int fd) {
  std::string bytes;
  char buf[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    bytes.append(buf, static_cast<std::size_t>(n));
  }
  return bytes;
}

PolygonSoup parse_forked(const std::function<PolygonSoup()>& parse, const std::string& name) {
  int fds[2];
  if (::pipe(fds) != 0) throw IoError(name + ": cannot create a pipe for the reader process");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw IoError(name + ": cannot start the reader process");
  }
  if (pid == 0) {
    ::close(fds[0]);
    run_child(parse, fds[1]);
  }
  ::close(fds[1]);
  const std::string message = read_all(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFSIGNALED(status))
    throw InputError(name + ": cannot parse the file: the reader crashed on it (signal " +
                     std::to_string(WTERMSIG(status)) + ", " + ::strsignal(WTERMSIG(status)) + ")");
  if (message.empty()) throw InputError(name + ": cannot parse the file: the reader ended without a result");
  if (message[0] == kInputError) throw InputError(message.substr(1));
  if (message[0] == kOtherError) throw InputError(name + ": cannot parse the file (" + message.substr(1) + ")");
  PolygonSoup soup;
  if (!decode(message, &soup)) throw InputError(name + ": cannot parse the file: the reader's result is incomplete");
  return soup;
}

// AddressSanitizer's allocator is not fork-safe: a fork while another thread (an idle
// TBB worker finishing a task) holds its lock leaves the child waiting on that lock for
// ever, which the sanitized suite met in a test that writes a .vtp with TBB and reads it
// back. So under AddressSanitizer the reader runs in this process instead (its own
// exceptions still become InputErrors; a crash or a leak inside VTK is then reported,
// which is what a sanitizer run wants to see). The .vtp reader refuses what would make
// VTK allocate a corrupt header's claim (vtp_precheck.h) before VTK reads the data, so
// ASan's operator new, which reports a huge request instead of throwing, is not met.
PolygonSoup parse_here(const std::function<PolygonSoup()>& parse, const std::string& name) {
  try {
    return parse();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(name + ": cannot parse the file (" + e.what() + ")");
  }
}

}  // namespace

PolygonSoup parse_in_child(const std::function<PolygonSoup()>& parse, const std::string& name) {
  return kAddressSanitizer ? parse_here(parse, name) : parse_forked(parse, name);
}

}  // namespace blayer::detail
