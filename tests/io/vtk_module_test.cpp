// The VTK module (io/src/vtk_module.h): a clear error when it cannot be loaded, and
// its errors back as blayer's exceptions. (tests/app: the command line links no VTK.)
#include "vtk_module.h"

#include <gtest/gtest.h>

#include <string>

#include "blayer/core/errors.h"

namespace blayer {
namespace {

TEST(VtkModule, AMissingModuleIsAnIoErrorNamingItAndTheBuild) {
  const std::string path = "/nonexistent/libblayer_vtk.so";
  try {
    detail::load_vtk_module(path);
    FAIL() << "loaded a module that does not exist";
  } catch (const IoError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cannot load blayer's VTK module " + path), std::string::npos) << what;
    EXPECT_NE(what.find("scripts/build.sh"), std::string::npos) << what;
  }
}

TEST(VtkModule, ALibraryThatIsNoModuleIsRefused) {
  // libz has no blayer_vtk_module.
  try {
    detail::load_vtk_module("libz.so.1");
    FAIL() << "took libz for the module";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("libz.so.1 is not blayer's VTK module of this build"), std::string::npos)
        << e.what();
  }
}

TEST(VtkModule, TheBuiltModuleLoadsWithEveryFunction) {
  const detail::VtkModule& m = detail::vtk_module("test");
  EXPECT_EQ(m.version, detail::VtkModule::kVersion);
  EXPECT_NE(m.parse_vtp, nullptr);
  EXPECT_NE(m.write_vtp, nullptr);
  EXPECT_NE(m.read_volume_mesh, nullptr);
}

// An exception inside the module comes back as the one it stands for.
TEST(VtkModule, ErrorsInsideTheModuleComeBackAsTheirExceptions) {
  const detail::VtkModule& m = detail::vtk_module("test");
  detail::VtkCallError error;
  m.read_volume_mesh("/nonexistent/mesh.vtu", &error);
  EXPECT_EQ(error.kind, detail::VtkCallError::Kind::kInput);
  EXPECT_THROW(detail::rethrow(error), InputError);
  m.parse_vtp("<VTKFile", "broken.vtp", false, &error);
  EXPECT_EQ(error.kind, detail::VtkCallError::Kind::kInput);
  EXPECT_NE(error.message.find("broken.vtp: cannot parse the .vtp file"), std::string::npos) << error.message;
  error = {detail::VtkCallError::Kind::kIo, "x: cannot write the file"};
  EXPECT_THROW(detail::rethrow(error), IoError);
  error = {};
  EXPECT_NO_THROW(detail::rethrow(error));
}

}  // namespace
}  // namespace blayer
