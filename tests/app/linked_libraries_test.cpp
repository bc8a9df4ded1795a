// What the command line loads when it starts: VTK only in its module, on first use
// (io/src/vtk_module.h).
#include <gtest/gtest.h>

#include <string>

#include "../io/external_tool.h"

namespace blayer {
namespace {

// The dynamic loader lists the libraries a program needs without running it
// (LD_TRACE_LOADED_OBJECTS, what ldd does): VTK's, which take 17 ms to load, must not
// be among the command line's.
TEST(LinkedLibraries, TheCommandLineDoesNotLinkVtk) {
  const std::string cli = std::string(BLAYER_EXE) + "-cli";
  const testing::ToolRun run = testing::run_tool("LD_TRACE_LOADED_OBJECTS=1 " + testing::shell_quote(cli));
  const std::string& libs = run.output;
  ASSERT_EQ(run.exit_code, 0) << libs;
  ASSERT_NE(libs.find("libtbb"), std::string::npos) << libs;  // the listing worked
  EXPECT_EQ(libs.find("libvtk"), std::string::npos) << libs;
}

}  // namespace
}  // namespace blayer
