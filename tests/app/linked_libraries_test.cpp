// What the command line loads when it starts: VTK only in its module, on first use
// (io/src/vtk_module.h).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace blayer {
namespace {

std::string output_of(const std::string& cmd) {
  std::string out;
  if (std::FILE* p = ::popen(cmd.c_str(), "r")) {
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    ::pclose(p);
  }
  return out;
}

// The dynamic loader lists the libraries a program needs without running it
// (LD_TRACE_LOADED_OBJECTS, what ldd does): VTK's, which take 17 ms to load, must not
// be among the command line's.
TEST(LinkedLibraries, TheCommandLineDoesNotLinkVtk) {
  const std::string cli = std::string(BLAYER_EXE) + "-cli";
  const std::string libs = output_of("LD_TRACE_LOADED_OBJECTS=1 " + cli + " 2>&1");
  ASSERT_NE(libs.find("libtbb"), std::string::npos) << libs;  // the listing worked
  EXPECT_EQ(libs.find("libvtk"), std::string::npos) << libs;
}

}  // namespace
}  // namespace blayer
