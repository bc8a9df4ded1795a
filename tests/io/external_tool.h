// Runs an external program (xmllint, Debian's python3 with meshio) from a test and
// captures what it prints. The tools are test dependencies installed by
// scripts/install-deps.sh; a missing tool fails the test with the package to install.
#pragma once

#include <array>
#include <cstdio>
#include <string>

#include <sys/wait.h>

namespace blayer::testing {

struct ToolRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr, interleaved
};

// Runs `command` through the shell. Exit code 127 is the shell's "command not found".
inline ToolRun run_tool(const std::string& command) {
  ToolRun run;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return run;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) run.output.append(buf.data(), n);
  const int status = ::pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

// What to print when a tool run failed: its output, and where the tool comes from.
inline std::string describe_failure(const ToolRun& run, const std::string& tool, const std::string& package) {
  return tool + " exited with " + std::to_string(run.exit_code) + (run.exit_code == 127 ? " (not installed?)" : "") +
         "; it comes from the Debian package " + package + ", installed by scripts/install-deps.sh. Output:\n" +
         run.output;
}

// Single quotes for the shell; the paths tests use contain none.
inline std::string shell_quote(const std::string& s) { return "'" + s + "'"; }

}  // namespace blayer::testing
