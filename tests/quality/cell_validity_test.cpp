#include "blayer/quality/cell_validity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "blayer/quality/orient3d.h"

#include "test_cells.h"

namespace blayer {
namespace {

using test::mirrored;

Validity validity(CellType t, const std::vector<Vec3>& p) {
  EXPECT_EQ(static_cast<int>(p.size()), corner_count(t));
  return cell_validity(t, p.data());
}

TEST(CellValidity, ReferenceCellsOfEveryTypeAreValid) {
  EXPECT_EQ(validity(CellType::kTet, test::unit_tet()), Validity::kValid);
  EXPECT_EQ(validity(CellType::kPyramid, test::unit_pyramid()), Validity::kValid);
  EXPECT_EQ(validity(CellType::kWedge, test::right_prism()), Validity::kValid);
  EXPECT_EQ(validity(CellType::kHex, test::unit_hex()), Validity::kValid);
  EXPECT_TRUE(prism_is_valid(test::right_prism().data()));
}

TEST(CellValidity, MirroredCellsOfEveryTypeAreInverted) {
  EXPECT_EQ(validity(CellType::kTet, mirrored(test::unit_tet())), Validity::kInverted);
  EXPECT_EQ(validity(CellType::kPyramid, mirrored(test::unit_pyramid())), Validity::kInverted);
  EXPECT_EQ(validity(CellType::kWedge, mirrored(test::right_prism())), Validity::kInverted);
  EXPECT_EQ(validity(CellType::kHex, mirrored(test::unit_hex())), Validity::kInverted);
  EXPECT_FALSE(prism_is_valid(mirrored(test::right_prism()).data()));
}

TEST(CellValidity, WedgeWrittenWithTheWallWindingIsInverted) {
  // (a, b, c, a', b', c') for a wall triangle whose normal points to the top: the
  // winding VTK rejects.
  const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  EXPECT_EQ(validity(CellType::kWedge, p), Validity::kInverted);
}

TEST(CellValidity, ZeroHeightCellsAreFlat) {
  EXPECT_EQ(validity(CellType::kPyramid, test::unit_pyramid(0.0)), Validity::kFlat);
  EXPECT_EQ(validity(CellType::kWedge, test::right_prism(0.0)), Validity::kFlat);
  EXPECT_FALSE(prism_is_valid(test::right_prism(0.0).data()));
  std::vector<Vec3> tet = test::unit_tet();
  tet[3] = {0.25, 0.25, 0.0};
  EXPECT_EQ(validity(CellType::kTet, tet), Validity::kFlat);
  std::vector<Vec3> hex = test::unit_hex();
  for (int i = 4; i < 8; ++i) hex[i][2] = 0.0;
  EXPECT_EQ(validity(CellType::kHex, hex), Validity::kFlat);
}

TEST(CellValidity, PrismWithOneCollapsedColumnEdgeIsFlat) {
  std::vector<Vec3> p = test::right_prism();
  p[4] = p[1];
  EXPECT_EQ(validity(CellType::kWedge, p), Validity::kFlat);
}

TEST(CellValidity, PrismWhoseTopNodeCrossesTheWallIsInverted) {
  std::vector<Vec3> p = test::right_prism();
  p[5][2] = -0.1;
  EXPECT_EQ(validity(CellType::kWedge, p), Validity::kInverted);
}

}  // namespace
}  // namespace blayer

namespace blayer {
namespace {

// The unit hex with its top face turned by `deg` degrees about the vertical axis
// through the face centres.
std::vector<Vec3> twisted_hex(double deg) {
  std::vector<Vec3> h = test::unit_hex();
  const double t = deg * 3.14159265358979323846 / 180.0;
  for (int i = 4; i < 8; ++i) {
    const double x = h[i][0] - 0.5, y = h[i][1] - 0.5;
    h[i][0] = 0.5 + std::cos(t) * x - std::sin(t) * y;
    h[i][1] = 0.5 + std::sin(t) * x + std::cos(t) * y;
  }
  return h;
}

TEST(CellValidity, HexTwistedPastFortyFiveDegreesIsTwistedThoughItsCornerTetsArePositive) {
  const std::vector<Vec3> h = twisted_hex(60.0);
  std::size_t n = 0;
  const std::array<int, 4>* tets = validity_tets(CellType::kHex, &n);
  ASSERT_EQ(n, 58u);
  for (std::size_t i = 0; i < 8; ++i)  // the corner tets
    EXPECT_GT(orient3d_sign(h[tets[i][0]], h[tets[i][1]], h[tets[i][2]], h[tets[i][3]]), 0) << i;
  EXPECT_EQ(validity(CellType::kHex, h), Validity::kTwisted);
  EXPECT_EQ(validity(CellType::kHex, twisted_hex(30.0)), Validity::kValid);
}

TEST(CellValidity, EveryAffineImageOfTheCubeIsAValidHex) {
  std::vector<Vec3> h = test::unit_hex();
  // A thin, sheared, stretched layer cell: x' = 3x + 0.4z, y' = 0.5y + 0.2x, z' = 0.01z.
  for (Vec3& p : h) p = Vec3{3.0 * p[0] + 0.4 * p[2], 0.5 * p[1] + 0.2 * p[0], 0.01 * p[2]};
  EXPECT_EQ(validity(CellType::kHex, h), Validity::kValid);
}

}  // namespace
}  // namespace blayer
