#include "huge_pages.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#if defined(__GLIBC__)
#include <gnu/libc-version.h>
#endif

#include "blayer/core/address_sanitizer.h"

namespace blayer {

namespace {

constexpr const char* kTunable = "glibc.malloc.hugetlb";
// One malloc arena for all threads: memory that TBB's worker threads freed stayed
// resident in their own arenas, out of reach of the other threads' allocations, and
// added to the peak (peak resident set: the 717 wing's 115,000 KiB became 106,000 KiB
// with one arena, the BWB's 120,000 KiB 111,000 KiB). Threads that allocate side by
// side then wait on the arena's lock, so parallel loops keep their allocations out of
// the loop body (per-thread buffers: the fan layout, the fidelity report, the .vtu
// writer's zlib streams).
constexpr const char* kArenaTunable = "glibc.malloc.arena_max";
constexpr const char* kSettingVariable = "BLAYER_HUGE_PAGES";

std::optional<std::string> variable(const char* name) {
  const char* v = std::getenv(name);
  if (!v) return std::nullopt;
  return std::string(v);
}

bool glibc_has_tunable(const HugePageSetup& s) {
  return s.glibc_major > 2 || (s.glibc_major == 2 && s.glibc_minor >= 35);
}

bool builds_or_reads_meshes(const std::string& command) {
  return command == "extrude" || command == "normals" || command == "check";
}

}  // namespace

std::string thp_mode_of(const std::string& mode_file) {
  const std::size_t open = mode_file.find('['), close = mode_file.find(']', open);
  if (open == std::string::npos || close == std::string::npos) return "";
  return mode_file.substr(open + 1, close - open - 1);
}

std::optional<std::string> huge_page_tunables(const HugePageSetup& s) {
  if (s.setting || !builds_or_reads_meshes(s.command) || !s.own_malloc || !glibc_has_tunable(s)) return std::nullopt;
  if (s.preload && s.preload->find("vgpreload") != std::string::npos) return std::nullopt;
  if (s.thp_mode != "madvise") return std::nullopt;
  const std::string own = s.tunables ? *s.tunables : "";
  if (own.find(kTunable) != std::string::npos) return std::nullopt;
  std::string t = own.empty() ? "" : own + ":";
  t += std::string(kTunable) + "=1";
  if (own.find(kArenaTunable) == std::string::npos) t += std::string(":") + kArenaTunable + "=1";
  return t;
}

std::string huge_page_state(const HugePageSetup& s) {
  if (s.thp_mode == "always") return "on (system-wide)";
  const bool advised = s.tunables && s.tunables->find(std::string(kTunable) + "=1") != std::string::npos;
  return s.thp_mode == "madvise" && advised && s.own_malloc && glibc_has_tunable(s) ? "on" : "off";
}

HugePageSetup current_huge_page_setup(int argc, char** argv) {
  HugePageSetup s;
  s.tunables = variable("GLIBC_TUNABLES");
  s.setting = variable(kSettingVariable);
  s.preload = variable("LD_PRELOAD");
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::stringstream text;
  text << mode.rdbuf();
  s.thp_mode = thp_mode_of(text.str());
#if defined(__GLIBC__)
  std::sscanf(gnu_get_libc_version(), "%d.%d", &s.glibc_major, &s.glibc_minor);
#endif
  s.own_malloc = !kAddressSanitizer;
  s.command = argc > 1 ? argv[1] : "";
  return s;
}

bool set_huge_page_environment(int argc, char** argv) {
  const std::optional<std::string> tunables = huge_page_tunables(current_huge_page_setup(argc, argv));
  if (!tunables) return false;
  // The executed process finds the setting and stays: one exec at most, whatever the C
  // library does with GLIBC_TUNABLES.
  const std::optional<std::string> before = variable("GLIBC_TUNABLES");
  if (::setenv(kSettingVariable, "1", 1) == 0 && ::setenv("GLIBC_TUNABLES", tunables->c_str(), 1) == 0) return true;
  restore_huge_page_environment(before);
  return false;
}

void restore_huge_page_environment(const std::optional<std::string>& tunables) {
  ::unsetenv(kSettingVariable);
  if (tunables)
    ::setenv("GLIBC_TUNABLES", tunables->c_str(), 1);
  else
    ::unsetenv("GLIBC_TUNABLES");
}

void reexecute_on_huge_pages(int argc, char** argv) {
  const std::optional<std::string> before = variable("GLIBC_TUNABLES");
  if (!set_huge_page_environment(argc, argv)) return;
  ::execv("/proc/self/exe", argv);
  // No /proc, or the binary is gone: this process runs on, with 4 KiB pages, and its
  // environment says so again (the summary reads it).
  restore_huge_page_environment(before);
}

}  // namespace blayer
