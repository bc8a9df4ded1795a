// blayer: starts the command line (blayer-cli, next to this file) on huge pages. glibc
// reads the tunable that gives malloc's large chunks huge pages only when a process
// starts (huge_pages.h), so the process that runs a mesh job must be executed with it
// set. This launcher sets it and executes the command line with the same arguments; it
// links none of the command line's libraries, which a self-re-executing command line
// loaded twice.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "huge_pages.h"

namespace {

// The command line's path: blayer-cli in this executable's directory (symbolic links
// resolved, so that a link to the launcher elsewhere finds it), else next to argv[0].
std::string command_line_path(const char* argv0) {
  std::string self(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", self.data(), self.size() - 1);
  self = n > 0 ? self.substr(0, static_cast<std::size_t>(n)) : std::string(argv0 ? argv0 : "");
  const std::size_t slash = self.rfind('/');
  return (slash == std::string::npos ? std::string(".") : self.substr(0, slash)) + "/blayer-cli";
}

}  // namespace

int main(int argc, char** argv) {
  blayer::set_huge_page_environment(argc, argv);
  const std::string cli = command_line_path(argc > 0 ? argv[0] : nullptr);
  ::execv(cli.c_str(), argv);
  std::fprintf(stderr, "error: cannot run the command line %s: %s\n", cli.c_str(), std::strerror(errno));
  return 1;
}
