// Large arrays on transparent huge pages. A run fills hundreds of megabytes of fresh
// arrays, and on 4 KiB pages the kernel takes a fault for each page it hands out: on
// the M6 571k surface, 719,000 faults and a third of the run's wall time. glibc's malloc
// advises the kernel to back its large chunks with 2 MiB pages when the tunable
// glibc.malloc.hugetlb=1 is set (glibc 2.35 and later, with the kernel's THP mode
// "madvise"), but glibc reads its tunables only when a process starts: the process that
// runs the command line is executed with the tunable added, by the `blayer` launcher
// (launcher.cpp), which loads none of the command line's libraries (a command line that
// re-executed itself loaded them twice). BLAYER_HUGE_PAGES=0 turns this off; the
// executed process finds it set to 1.
#pragma once

#include <optional>
#include <string>

namespace blayer {

// What decides it, read from the process and the system (current_huge_page_setup), or
// given by a test.
struct HugePageSetup {
  std::optional<std::string> tunables;  // GLIBC_TUNABLES
  std::optional<std::string> setting;   // BLAYER_HUGE_PAGES
  std::optional<std::string> preload;   // LD_PRELOAD: valgrind's preloads replace malloc
  std::string thp_mode;                 // the bracketed word of the kernel's THP mode file, or ""
  int glibc_major = 0, glibc_minor = 0; // 0.0 when the C library is not glibc
  bool own_malloc = true;               // false under AddressSanitizer, whose malloc is its own
  std::string command;                  // the subcommand (argv[1]), or ""
};

// The kernel's THP mode from the contents of its mode file ("always [madvise] never"):
// the word in brackets, or "" when there is none.
std::string thp_mode_of(const std::string& mode_file);

// The GLIBC_TUNABLES value to execute the command line with: the user's tunables, then
// glibc.malloc.hugetlb=1 and, unless the user chose it, glibc.malloc.arena_max=1 (one
// malloc arena: huge_pages.cpp says why). Or nothing when the process stays as it is:
// off (BLAYER_HUGE_PAGES set), a command that builds or reads no mesh, another malloc,
// a glibc without the tunable, a THP mode where advice changes nothing ("always" gives
// every large mapping huge pages already, "never" none), or a GLIBC_TUNABLES that
// chooses the huge-page tunable itself.
std::optional<std::string> huge_page_tunables(const HugePageSetup& s);

// Whether the running process's large arrays get huge pages, for the summary: "on",
// "on (system-wide)" (THP mode "always"), or "off".
std::string huge_page_state(const HugePageSetup& s);

HugePageSetup current_huge_page_setup(int argc, char** argv);

// Adds the tunables to this process's environment, for the process it executes next, when
// huge_page_tunables says so (with BLAYER_HUGE_PAGES=1, so that the executed process
// stays); returns whether it did.
bool set_huge_page_environment(int argc, char** argv);
// Undoes set_huge_page_environment, given the GLIBC_TUNABLES it found (nullopt: unset).
void restore_huge_page_environment(const std::optional<std::string>& tunables);

// Re-executes the running binary (/proc/self/exe) with argv and the tunable when
// huge_page_tunables says so. Returns when it does not, or when exec fails: the run then
// goes on as it is. The `blayer` launcher (launcher.cpp) sets the tunable before it
// executes the command line, which then finds BLAYER_HUGE_PAGES=1 and stays; run
// directly, the command line re-executes itself.
void reexecute_on_huge_pages(int argc, char** argv);

}  // namespace blayer
