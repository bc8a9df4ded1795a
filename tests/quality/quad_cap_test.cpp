// The pyramid cap of an envelope quad (quality/quad_cap.h), against its definition: a
// valid pyramid (exact) with its apex on the quad's normal through its centre.
#include "blayer/quality/quad_cap.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "blayer/quality/cell_validity.h"

namespace blayer {
namespace {

bool valid_pyramid(const std::array<Vec3, 4>& q, const Vec3& apex) {
  const Vec3 corners[5] = {q[0], q[1], q[2], q[3], apex};
  return cell_is_valid(CellType::kPyramid, corners);
}

Vec3 centre_of(const std::array<Vec3, 4>& q) { return 0.25 * (q[0] + q[1] + q[2] + q[3]); }

// Oracle: is there any height d in (0, longest edge] on the normal through the centre
// that gives a valid pyramid? Brute force over 20,000 heights, geometric from 1e-9 of the
// longest edge.
bool some_height_caps(const std::array<Vec3, 4>& q) {
  Vec3 n{0, 0, 0};
  double longest = 0.0;
  for (int i = 0; i < 4; ++i) {
    n = n + cross(q[i], q[(i + 1) % 4]);
    longest = std::max(longest, norm(q[(i + 1) % 4] - q[i]));
  }
  n = normalized(n);
  for (int k = 0; k < 20000; ++k) {
    const double d = longest * std::pow(1e-9, 1.0 - k / 19999.0);
    if (valid_pyramid(q, centre_of(q) + d * n)) return true;
  }
  return false;
}

TEST(QuadCap, APlanarSquareIsCappedHalfItsEdgeAboveItsCentre) {
  const std::array<Vec3, 4> q{Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{2, 2, 0}, Vec3{0, 2, 0}};
  const auto apex = quad_cap_apex(q);
  ASSERT_TRUE(apex.has_value());
  EXPECT_EQ(*apex, (Vec3{1, 1, 1}));
  // Wound the other way the normal, and with it the apex, points down.
  const auto below = quad_cap_apex({q[0], q[3], q[2], q[1]});
  ASSERT_TRUE(below.has_value());
  EXPECT_EQ(*below, (Vec3{1, 1, -1}));
}

TEST(QuadCap, TheApexDoesNotDependOnTheCornerTheQuadStartsAt) {
  const std::array<Vec3, 4> q{Vec3{0.1, 0.3, 0.7}, Vec3{2.3, 0.2, 0.5}, Vec3{2.1, 1.9, 0.9}, Vec3{0.2, 2.2, 0.4}};
  const auto first = quad_cap_apex(q);
  ASSERT_TRUE(first.has_value());
  for (int s = 1; s < 4; ++s) {
    const auto other = quad_cap_apex({q[s], q[(s + 1) % 4], q[(s + 2) % 4], q[(s + 3) % 4]});
    ASSERT_TRUE(other.has_value());
    EXPECT_EQ(*other, *first) << "starting at corner " << s;  // bitwise
  }
}

// The top of a thin twisted fan strip on a CAD block (bench/make_perforated_block.py):
// 0.24e-3 wide at one end, 2.1e-3 at the other, 19.7e-3 long. Half its shortest edge
// above the centre is too low; a higher apex caps it.
TEST(QuadCap, AThinTwistedStripTopIsCappedHigherThanHalfItsShortestEdge) {
  const std::array<Vec3, 4> q{Vec3{8.7867775205456464, 3.5568263854798854, -0.0035291466296794535},
                              Vec3{8.786705590609877, 3.556616970657005, -0.0034353785407497677},
                              Vec3{8.7819069626196082, 3.5756378985984187, -0.0021299118574079311},
                              Vec3{8.7828354881436166, 3.5758440442059012, -0.0039644691344286756}};
  const auto apex = quad_cap_apex(q);
  ASSERT_TRUE(apex.has_value());
  EXPECT_TRUE(valid_pyramid(q, *apex));
  const Vec3 c = centre_of(q);
  const Vec3 n = normalized(*apex - c);
  const double shortest = norm(q[1] - q[0]);
  for (double m : {0.5, 0.25, 0.125, 0.0625, 0.03125})
    EXPECT_FALSE(valid_pyramid(q, c + m * shortest * n)) << m << " of the shortest edge";
  EXPECT_GT(norm(*apex - c), 0.5 * shortest);
}

// A quad whose corner 3 is reflex (by 1.8e-7 against 4e-5 at the others: the slanted
// face of a closure wedge on the same block) folds one split; no height caps it.
TEST(QuadCap, AQuadWithAReflexCornerHasNoCap) {
  const std::array<Vec3, 4> q{Vec3{0.75818113439907, 1.6490612851212991, -0.001230185052746917},
                              Vec3{0.7578660738610123, 1.6488794502448303, -0.00018987949182620238},
                              Vec3{0.7241673841932597, 1.652698575226996, -0.025256848962415108},
                              Vec3{0.725291289268835, 1.6526382343654233, -0.024442098133800275}};
  EXPECT_FALSE(quad_cap_apex(q).has_value());
  EXPECT_FALSE(some_height_caps(q));
}

// Quads jittered from a unit square, in the plane and out of it, some of them twisted or
// reflex: every apex given makes a valid pyramid, and where none is given the brute-force
// search finds none either, or only at heights off the list's (counted, not failed).
TEST(QuadCap, EveryApexGivenCapsAndMostCappableQuadsGetOne) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.45, 0.45);
  int capped = 0, missed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    std::array<Vec3, 4> q{Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}};
    for (Vec3& p : q) p = p + Vec3{jitter(rng), jitter(rng), jitter(rng)};
    const auto apex = quad_cap_apex(q);
    if (apex) {
      ++capped;
      EXPECT_TRUE(valid_pyramid(q, *apex)) << "trial " << trial;
    } else if (some_height_caps(q)) {
      ++missed;
    }
  }
  EXPECT_GT(capped, 100);
  EXPECT_LE(missed, capped / 10);
}

}  // namespace
}  // namespace blayer
