#include "huge_pages.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>

#include "../io/temp_dir.h"
#include "run_cli.h"

namespace blayer {
namespace {

using testing::run_blayer;
using testing::TempDir;

// A Debian 12 machine with THP in "madvise" mode, about to extrude, nothing set.
HugePageSetup debian_extrude() {
  HugePageSetup s;
  s.thp_mode = "madvise";
  s.glibc_major = 2;
  s.glibc_minor = 36;
  s.command = "extrude";
  return s;
}

TEST(HugePages, ThpModeIsTheBracketedWord) {
  EXPECT_EQ(thp_mode_of("always [madvise] never\n"), "madvise");
  EXPECT_EQ(thp_mode_of("[always] madvise never\n"), "always");
  EXPECT_EQ(thp_mode_of("always madvise [never]"), "never");
  EXPECT_EQ(thp_mode_of(""), "");
  EXPECT_EQ(thp_mode_of("always madvise never"), "");
  EXPECT_EQ(thp_mode_of("[madvise"), "");
}

TEST(HugePages, ReexecutesWithTheTunablesAddedToTheUsersOnes) {
  HugePageSetup s = debian_extrude();
  EXPECT_EQ(huge_page_tunables(s), "glibc.malloc.hugetlb=1:glibc.malloc.arena_max=1");
  s.tunables = "";
  EXPECT_EQ(huge_page_tunables(s), "glibc.malloc.hugetlb=1:glibc.malloc.arena_max=1");
  s.tunables = "glibc.malloc.tcache_count=0";
  EXPECT_EQ(huge_page_tunables(s), "glibc.malloc.tcache_count=0:glibc.malloc.hugetlb=1:glibc.malloc.arena_max=1");
  // The user's own arena count stays.
  s.tunables = "glibc.malloc.arena_max=2";
  EXPECT_EQ(huge_page_tunables(s), "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
  for (const char* command : {"normals", "check"}) {
    s.command = command;
    EXPECT_TRUE(huge_page_tunables(s)) << command;
  }
  s.glibc_major = 3;
  s.glibc_minor = 0;
  EXPECT_TRUE(huge_page_tunables(s));
  s.preload = "/usr/lib/libsomething.so";
  EXPECT_TRUE(huge_page_tunables(s));
}

TEST(HugePages, StaysWhereTheTunableWouldChangeNothingOrIsTheUsersChoice) {
  auto stays = [](void (*change)(HugePageSetup*)) {
    HugePageSetup s = debian_extrude();
    change(&s);
    return !huge_page_tunables(s).has_value();
  };
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->setting = "0"; }));  // turned off
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->setting = "1"; }));  // the re-executed process
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->tunables = "glibc.malloc.hugetlb=0"; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->tunables = "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=2"; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->command = "params"; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->command = "--help"; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->command = ""; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->thp_mode = "always"; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->thp_mode = "never"; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->thp_mode = ""; }));  // no THP in the kernel
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->glibc_minor = 34; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->glibc_major = s->glibc_minor = 0; }));  // not glibc
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->own_malloc = false; }));
  EXPECT_TRUE(stays([](HugePageSetup* s) { s->preload = "/usr/libexec/valgrind/vgpreload_core-amd64-linux.so"; }));
  EXPECT_FALSE(stays([](HugePageSetup*) {}));
}

TEST(HugePages, StateSaysWhetherTheRunningProcessGetsThem) {
  HugePageSetup s = debian_extrude();
  EXPECT_EQ(huge_page_state(s), "off");
  s.tunables = "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1";
  EXPECT_EQ(huge_page_state(s), "on");
  s.glibc_minor = 34;
  EXPECT_EQ(huge_page_state(s), "off");
  s.glibc_minor = 36;
  s.own_malloc = false;
  EXPECT_EQ(huge_page_state(s), "off");
  s.own_malloc = true;
  s.thp_mode = "never";
  EXPECT_EQ(huge_page_state(s), "off");
  s.thp_mode = "always";
  s.tunables.reset();
  EXPECT_EQ(huge_page_state(s), "on (system-wide)");
}

// The re-executed run is the same run: same arguments, same mesh to the byte; its
// summary reports what this machine gives it (the state the test expects is worked out
// from the same setup the command line reads).
TEST(HugePages, ReexecutedExtrusionWritesTheSameMeshAndSaysItsPages) {
  TempDir dir;
  const std::string cube = std::string(BLAYER_CASES_DIR) + "/003_cube/surface.stl";
  const std::string args = "extrude " + cube + " --layers 3 --first-height 0.01 -o ";
  const char* before = std::getenv("BLAYER_HUGE_PAGES");
  const std::string saved = before ? before : "";
  ::setenv("BLAYER_HUGE_PAGES", "0", 1);
  const auto off = run_blayer(args + dir.file("off.vtu"), dir.file(""));
  ::unsetenv("BLAYER_HUGE_PAGES");
  const auto run = run_blayer(args + dir.file("run.vtu"), dir.file(""));
  ASSERT_EQ(off.status, 0) << off.out << off.err;
  ASSERT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_NE(off.out.find("; huge pages off\n"), std::string::npos) << off.out;

  char exe_name[] = "blayer", command[] = "extrude";
  char* argv[] = {exe_name, command, nullptr};
  const HugePageSetup here = current_huge_page_setup(2, argv);
  HugePageSetup child = here;
  if (const auto tunables = huge_page_tunables(here)) child.tunables = tunables;
  const std::string expected = huge_page_state(child);
  if (before) ::setenv("BLAYER_HUGE_PAGES", saved.c_str(), 1);
  EXPECT_NE(run.out.find("; huge pages " + expected + "\n"), std::string::npos) << expected << "\n" << run.out;
  EXPECT_NE(run.out.find("memory: peak "), std::string::npos) << run.out;

  const std::string a = testing::slurp(dir.file("off.vtu")), b = testing::slurp(dir.file("run.vtu"));
  EXPECT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == b) << "the meshes differ: " << a.size() << " and " << b.size() << " bytes";
}

// The launcher (launcher.cpp) finds the command line next to the file it is, through
// symbolic links: a link to it elsewhere runs the command line.
TEST(HugePages, ALinkToTheLauncherRunsTheCommandLine) {
  TempDir dir;
  std::filesystem::create_symlink(BLAYER_EXE, dir.file("blayer"));
  const std::string cmd = dir.file("blayer") + " params >" + dir.file("out.txt") + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << testing::slurp(dir.file("out.txt"));
  EXPECT_NE(testing::slurp(dir.file("out.txt")).find("first-height"), std::string::npos);
}

TEST(HugePages, ALauncherWithoutItsCommandLineSaysWhatIsMissing) {
  TempDir dir;
  std::filesystem::copy_file(BLAYER_EXE, dir.file("blayer"));
  const std::string cmd = dir.file("blayer") + " params >" + dir.file("out.txt") + " 2>&1";
  const int raw = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 1);
  const std::string out = testing::slurp(dir.file("out.txt"));
  EXPECT_NE(out.find("error: cannot run the command line " + dir.file("blayer-cli")), std::string::npos) << out;
}

}  // namespace
}  // namespace blayer
