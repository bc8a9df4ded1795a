// Runs the blayer executable as a user would and captures its exit status and output.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace blayer::testing {

struct CliRun {
  int status = -1;       // exit status; -1 if killed by a signal
  int signal = 0;
  std::string out, err;
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// args is appended to the executable verbatim (the caller quotes paths). With
// kill_after_seconds > 0 the run is killed (SIGKILL) when it takes longer, so that a
// hang fails its test instead of stalling the suite.
inline CliRun run_blayer(const std::string& args, const std::string& scratch_dir, int kill_after_seconds = 0) {
  const std::string out = scratch_dir + "/stdout.txt", err = scratch_dir + "/stderr.txt";
  const std::string limit = kill_after_seconds > 0 ? "timeout -s KILL " + std::to_string(kill_after_seconds) + " " : "";
  const std::string cmd = limit + std::string(BLAYER_EXE) + " " + args + " >" + out + " 2>" + err + " </dev/null";
  const int raw = std::system(cmd.c_str());
  CliRun r;
  if (WIFEXITED(raw)) r.status = WEXITSTATUS(raw);
  if (WIFSIGNALED(raw)) r.signal = WTERMSIG(raw);
  // /bin/sh reports a child killed by signal N as exit status 128+N.
  if (r.status > 128) r.signal = r.status - 128;
  r.out = slurp(out);
  r.err = slurp(err);
  std::remove(out.c_str());
  std::remove(err.c_str());
  return r;
}

}  // namespace blayer::testing
