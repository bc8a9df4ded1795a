// Inputs the fuzzers (fuzz/) found to crash, hang, leak or trip a sanitizer, kept as
// files under tests/io/fuzz_regressions/<format>/. Each must now be read or refused
// with an InputError naming the file; the sanitizer build of the suite runs them with
// AddressSanitizer and UndefinedBehaviorSanitizer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "blayer/core/errors.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/io/read_surface.h"

namespace blayer {
namespace {

namespace fs = std::filesystem;

const fs::path kRegressions = fs::path(BLAYER_SOURCE_DIR) / "tests" / "io" / "fuzz_regressions";

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// "" when the file is read and prepared, else the InputError's message.
std::string outcome(const fs::path& file) {
  const std::string format = file.parent_path().filename().string();
  try {
    const PolygonSoup soup = parse_polygon_soup(bytes_of(file), format, file.filename().string());
    PrepareOptions open;
    open.allow_open = true;
    prepare_surface(soup, file.filename().string(), open);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FuzzRegressions, EveryFindingIsReadOrRefusedWithAnInputError) {
  int n = 0;
  for (const auto& dir : fs::directory_iterator(kRegressions))
    for (const auto& file : fs::directory_iterator(dir.path())) {
      ++n;
      const std::string msg = outcome(file.path());
      if (!msg.empty()) {
        EXPECT_EQ(msg.rfind(file.path().filename().string(), 0), 0u) << msg;
      }
    }
  EXPECT_GT(n, 0);
}

TEST(FuzzRegressions, PlyDeclaringTheVertexAndFaceElementsTwiceIsRefusedByName) {
  EXPECT_NE(outcome(kRegressions / "ply" / "elements_declared_twice.ply").find("element vertex is declared twice"),
            std::string::npos);
}

// Headers that claim blocks of exabytes, or a billion blocks (an 8 GB table of block
// sizes), are refused before VTK allocates the claim (io/src/vtk_module/vtp_precheck.h);
// under AddressSanitizer VTK's allocation would be a sanitizer report.
TEST(FuzzRegressions, VtpWhoseBlockHeaderClaimsExabytesIsRefusedBeforeVtkAllocates) {
  const std::pair<const char*, const char*> files[] = {
      {"block_header_claims_4e18_bytes.vtp", "bytes decompressed"},
      {"block_header_claims_5e17_bytes.vtp", "claims 576460752303423488 bytes of compressed blocks"}};
  for (const auto& [f, claim] : files) {
    const std::string msg = outcome(kRegressions / "vtp" / f);
    EXPECT_EQ(msg.rfind(std::string(f) + ": cannot parse the .vtp file: the compressed-data header of DataArray", 0), 0u)
        << msg;
    EXPECT_NE(msg.find(claim), std::string::npos) << msg;
  }
}

TEST(FuzzRegressions, VtpWhoseBlockCountClaimsABillionBlocksIsRefusedBeforeVtkAllocates) {
  const std::string f = "block_count_claims_a_billion_blocks.vtp";
  const std::string msg = outcome(kRegressions / "vtp" / f);
  EXPECT_EQ(msg.rfind(f + ": cannot parse the .vtp file: the compressed-data header of DataArray \"normal_status\" "
                          "claims 1073741825 blocks, a table of 8589934600 bytes",
                      0),
            0u)
      << msg;
}

// Without header_type the header's words are 32-bit: this one claims blocks of 0 bytes,
// by which VTK divides (a SIGFPE).
TEST(FuzzRegressions, VtpWhoseHeaderClaimsBlocksOfZeroBytesIsRefusedBeforeVtkDividesByIt) {
  const std::string f = "block_size_zero_divides_by_zero.vtp";
  EXPECT_NE(outcome(kRegressions / "vtp" / f).find("DataArray \"normal\" claims 1 blocks of 0 bytes"), std::string::npos);
}

// A Points array without NumberOfComponents (misspelt) has one component; VTK 9.1 fails
// on it after taking objects it never frees.
TEST(FuzzRegressions, VtpWhosePointsHaveOneComponentIsRefusedBeforeVtkReadsThem) {
  const std::string f = "points_of_one_component.vtp";
  EXPECT_NE(outcome(kRegressions / "vtp" / f).find("the points' DataArray (no Name) has 1 components per point, not 3"),
            std::string::npos);
}

// VTK 9.1 cannot allocate the points this piece claims and leaks the arrays it made.
TEST(FuzzRegressions, VtpWhosePieceClaimsMorePointsThanMemoryIsRefusedBeforeVtkAllocates) {
  const std::string f = "points_count_beyond_memory_leaks.vtp";
  EXPECT_NE(outcome(kRegressions / "vtp" / f).find("the pieces claim NumberOfPoints=7777777777777774"), std::string::npos);
}

}  // namespace
}  // namespace blayer
