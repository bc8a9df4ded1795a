// The CGNS library is loaded when a .cgns file is written (io/src/cgns_library.h).
#include "cgns_library.h"

#include <gtest/gtest.h>

#include <string>

#include "blayer/core/errors.h"

namespace blayer {
namespace {

std::string error_of(const std::string& path) {
  try {
    detail::load_cgns_library(path);
  } catch (const IoError& e) {
    return e.what();
  }
  return "";
}

TEST(CgnsLibrary, TheBuildsLibraryGivesTheFunctionsTheLinkerWouldHave) {
  // The tests link the same library, so the loaded functions are the linked ones.
  const detail::CgnsLibrary& cg = detail::cgns_library("grid.cgns");
  EXPECT_EQ(cg.open, &::cg_open);
  EXPECT_EQ(cg.go_to, &::cg_goto);
  EXPECT_EQ(cg.section_write, &::cg_section_write);
  EXPECT_EQ(cg.boco_gridlocation_write, &::cg_boco_gridlocation_write);
}

TEST(CgnsLibrary, AMissingLibraryIsRefusedWithItsPath) {
  const std::string e = error_of("/nonexistent/dir/libcgns_missing.so.9");
  EXPECT_NE(e.find("cannot load the CGNS library /nonexistent/dir/libcgns_missing.so.9"), std::string::npos) << e;
}

TEST(CgnsLibrary, ALibraryWithoutTheFunctionsIsRefusedNamingOne) {
  // zlib is loaded in every test process: it loads, and has no CGNS function.
  const std::string e = error_of("libz.so.1");
  EXPECT_NE(e.find("the CGNS library libz.so.1 has no function cg_open"), std::string::npos) << e;
}

}  // namespace
}  // namespace blayer
