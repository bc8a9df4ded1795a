#include "blayer/io/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../io/temp_dir.h"
#include "blayer/core/errors.h"
#include "run_cli.h"

namespace blayer {
namespace {

using testing::slurp;
using testing::TempDir;

TEST(AtomicOutputs, TargetsAppearOnlyAtCommitAndAllTogether) {
  TempDir dir;
  dir.write("old.json", "old");
  {
    AtomicOutputs out;
    const std::string a = out.stage(dir.file("mesh.vtu")), b = out.stage(dir.file("old.json"));
    EXPECT_EQ(std::filesystem::path(a).parent_path(), std::filesystem::path(dir.file("mesh.vtu")).parent_path());
    EXPECT_EQ(std::filesystem::path(a).extension(), ".vtu");
    write_text_file(a, "mesh", dir.file("mesh.vtu"));
    write_text_file(b, "new", dir.file("old.json"));
    EXPECT_FALSE(std::filesystem::exists(dir.file("mesh.vtu")));
    EXPECT_EQ(slurp(dir.file("old.json")), "old");
    out.commit();
  }
  EXPECT_EQ(slurp(dir.file("mesh.vtu")), "mesh");
  EXPECT_EQ(slurp(dir.file("old.json")), "new");
  EXPECT_EQ(dir.entries(), 2) << "a temporary was left behind";
}

TEST(AtomicOutputs, NothingIsLeftBehindWithoutCommit) {
  TempDir dir;
  dir.write("keep.vtp", "previous run");
  {
    AtomicOutputs out;
    write_text_file(out.stage(dir.file("a.vtu")), "partial", dir.file("a.vtu"));
    write_text_file(out.stage(dir.file("keep.vtp")), "partial", dir.file("keep.vtp"));
    out.stage(dir.file("never_written.json"));
  }
  EXPECT_EQ(dir.entries(), 1);
  EXPECT_EQ(slurp(dir.file("keep.vtp")), "previous run");
}

TEST(AtomicOutputs, MissingDirectoryFailsAtStaging) {
  TempDir dir;
  AtomicOutputs out;
  try {
    out.stage(dir.file("no/such/dir/m.vtu"));
    FAIL() << "staged into a missing directory";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
}

// A target that has become a non-empty directory cannot be replaced by rename(): the
// files before it are written, it and the ones after keep what they held, and no
// temporary remains.
TEST(AtomicOutputs, RenameFailingHalfWayNamesWhatWasWrittenAndLeavesNoTemporary) {
  TempDir dir;
  AtomicOutputs out;
  write_text_file(out.stage(dir.file("first.vtu")), "1", dir.file("first.vtu"));
  write_text_file(out.stage(dir.file("blocked")), "2", dir.file("blocked"));
  write_text_file(out.stage(dir.file("third.json")), "3", dir.file("third.json"));
  std::filesystem::create_directories(dir.file("blocked/inside"));
  try {
    out.commit();
    FAIL() << "renamed onto a non-empty directory";
  } catch (const IoError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(dir.file("blocked") + ": cannot write", 0), 0u) << msg;
    EXPECT_NE(msg.find("already written: " + dir.file("first.vtu")), std::string::npos) << msg;
  }
  EXPECT_EQ(slurp(dir.file("first.vtu")), "1");
  EXPECT_FALSE(std::filesystem::exists(dir.file("third.json")));
  EXPECT_TRUE(std::filesystem::is_directory(dir.file("blocked/inside")));
  EXPECT_EQ(dir.entries(), 2) << "a temporary was left behind";
}

TEST(AtomicOutputs, FailedCommitLeavesOnlyTheBlockingDirectory) {
  TempDir dir;
  {
    AtomicOutputs out;
    write_text_file(out.stage(dir.file("blocked")), "x", dir.file("blocked"));
    write_text_file(out.stage(dir.file("later.vtu")), "y", dir.file("later.vtu"));
    std::filesystem::create_directories(dir.file("blocked/inside"));
    EXPECT_THROW(out.commit(), IoError);
  }
  EXPECT_EQ(dir.entries(), 1);  // the directory only
}

// An existing file is moved aside before its replacement is renamed in (atomic_file.cpp
// says why). A target that is a symbolic link is replaced as rename() alone replaces
// it: the link gives way to the new file and the file it pointed to keeps its content.
TEST(AtomicOutputs, ATargetLinkIsReplacedAndItsFileKept) {
  TempDir dir;
  dir.write("elsewhere.vtu", "not ours");
  std::filesystem::create_symlink(dir.file("elsewhere.vtu"), dir.file("mesh.vtu"));
  {
    AtomicOutputs out;
    write_text_file(out.stage(dir.file("mesh.vtu")), "new", dir.file("mesh.vtu"));
    out.commit();
  }
  EXPECT_FALSE(std::filesystem::is_symlink(dir.file("mesh.vtu")));
  EXPECT_EQ(slurp(dir.file("mesh.vtu")), "new");
  EXPECT_EQ(slurp(dir.file("elsewhere.vtu")), "not ours");
  EXPECT_EQ(dir.entries(), 2) << "a temporary or the moved-aside link was left behind";
}

TEST(AtomicOutputs, WritingIntoAMissingPlaceIsAnIoErrorNamingTheTarget) {
  TempDir dir;
  try {
    write_text_file(dir.file("no/such/file.json"), "x", "report.json");
    FAIL() << "wrote into a missing directory";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("report.json"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace blayer
