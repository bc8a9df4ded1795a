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

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif

// A .vtp whose name says it "claims" more data than exists makes VTK request that much
// memory. Under AddressSanitizer the reader runs in the test's process (see
// io/src/parse_in_child.cpp) and the sanitizer's operator new reports such a request
// instead of throwing bad_alloc, so these files run in the normal build only.
bool runs_here(const fs::path& file) {
  return !(kAddressSanitizer && file.parent_path().filename() == "vtp" &&
           file.filename().string().find("claims") != std::string::npos);
}

TEST(FuzzRegressions, EveryFindingIsReadOrRefusedWithAnInputError) {
  int n = 0;
  for (const auto& dir : fs::directory_iterator(kRegressions))
    for (const auto& file : fs::directory_iterator(dir.path())) {
      if (!runs_here(file.path())) continue;
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

// VTK allocates what the header claims; in a normal build that throws bad_alloc and the
// file is refused.
TEST(FuzzRegressions, VtpWhoseBlockHeaderClaimsExabytesIsRefusedNotACrash) {
  if (kAddressSanitizer) GTEST_SKIP() << "VTK's huge request is reported by AddressSanitizer (runs_here)";
  for (const char* f : {"block_header_claims_4e18_bytes.vtp", "block_header_claims_5e17_bytes.vtp"}) {
    const std::string msg = outcome(kRegressions / "vtp" / f);
    EXPECT_EQ(msg.rfind(std::string(f) + ": cannot parse the", 0), 0u) << msg;
  }
}

// A header that claims a billion compressed blocks (an 8 GB table of block sizes):
// VTK's reader would have the system zero gigabytes before failing; the reader's
// process is refused that much address space and the file is named as corrupt at once.
// Under AddressSanitizer the limit is not set (its shadow memory needs the space).
TEST(FuzzRegressions, VtpWhoseBlockCountClaimsABillionBlocksIsRefusedAsCorrupt) {
  if (kAddressSanitizer) GTEST_SKIP() << "no address-space limit under AddressSanitizer (runs_here)";
  const std::string f = "block_count_claims_a_billion_blocks.vtp";
  const std::string msg = outcome(kRegressions / "vtp" / f);
  EXPECT_EQ(msg.rfind(f + ": cannot parse the .vtp file (it claims more data than memory can hold", 0), 0u) << msg;
}

}  // namespace
}  // namespace blayer
