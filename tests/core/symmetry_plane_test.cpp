#include "blayer/core/symmetry_plane.h"

#include <gtest/gtest.h>

namespace blayer {
namespace {

TEST(SymmetryPlane, ParsesCoordinatePlanesAndGeneralOnes) {
  SymmetryPlane p;
  ASSERT_TRUE(parse_symmetry_plane("y=0", &p));
  EXPECT_EQ(p.axis, 1);
  EXPECT_EQ(p.offset, 0.0);
  ASSERT_TRUE(parse_symmetry_plane(" z = -1.5 ", &p));
  EXPECT_EQ(p.axis, 2);
  EXPECT_EQ(p.offset, -1.5);
  ASSERT_TRUE(parse_symmetry_plane("0 -2 0 3", &p));  // -2 y = 3: y = -1.5
  EXPECT_EQ(p.axis, 1);
  EXPECT_EQ(p.offset, -1.5);
  ASSERT_TRUE(parse_symmetry_plane("3 4 0 10", &p));
  EXPECT_EQ(p.axis, -1);
  EXPECT_NEAR(p.normal[0], 0.6, 1e-15);
  EXPECT_NEAR(p.offset, 2.0, 1e-15);
  for (const char* bad : {"", "w=0", "y=", "y=1x", "1 2 3", "0 0 0 1", "1 2 3 4 5", "1 2 3 nan"})
    EXPECT_FALSE(parse_symmetry_plane(bad, &p)) << bad;
}

TEST(SymmetryPlane, CoordinatePlaneProjectionAndMirrorAreExact) {
  SymmetryPlane p;
  ASSERT_TRUE(parse_symmetry_plane("y=0.1", &p));
  p.normal = {0.0, -1.0, 0.0};  // the model lies at y < 0.1
  const Vec3 q{0.3, -0.7, 2.0};
  EXPECT_EQ(p.project(q)[1], 0.1);
  EXPECT_EQ(p.signed_distance(p.project(q)), 0.0);
  EXPECT_NEAR(p.signed_distance(q), 0.8, 1e-15);
  EXPECT_EQ(p.mirror(p.mirror(q))[0], q[0]);
  EXPECT_NEAR(p.mirror(q)[1], 0.9, 1e-15);
  EXPECT_EQ(p.in_plane({1.0, 2.0, 3.0})[1], 0.0);
}

TEST(SymmetryPlane, GeneralPlaneProjectionLandsOnThePlane) {
  SymmetryPlane p;
  ASSERT_TRUE(parse_symmetry_plane("1 2 2 3", &p));  // unit normal (1,2,2)/3, offset 1
  const Vec3 q{5.0, -1.0, 7.0};
  EXPECT_NEAR(p.signed_distance(p.project(q)), 0.0, 1e-14);
  EXPECT_NEAR(p.signed_distance(p.mirror(q)), -p.signed_distance(q), 1e-13);
  EXPECT_NEAR(dot(p.in_plane({1.0, 1.0, 1.0}), p.normal), 0.0, 1e-15);
}

}  // namespace
}  // namespace blayer
