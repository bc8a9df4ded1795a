#include "blayer/extruder/diagonal_slabs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "blayer/extruder/triangle_bvh.h"
#include "blayer/extruder/triangle_intersections.h"
#include "lcg.h"

namespace blayer {
namespace {

bool boxes_overlap(const std::vector<Vec3>& p) {
  return Box::of_triangle(p[0], p[1], p[2]).overlaps(Box::of_triangle(p[3], p[4], p[5]));
}

bool slabs_apart(const std::vector<Vec3>& p) {
  return DiagonalSlabs::of_triangle(p[0], p[1], p[2]).apart(DiagonalSlabs::of_triangle(p[3], p[4], p[5]));
}

// The exact test on points 0-2 against 3-5 (no shared ids: a common point is a meeting).
bool meet(const std::vector<Vec3>& p) { return soup_triangles_intersect(p, {0, 1, 2}, {3, 4, 5}); }

TEST(DiagonalSlabs, SeparateParallelSliversAcrossTheAxesWhoseBoxesOverlap) {
  // Two slivers along x = y in the plane z = 0, 0.2 apart in x - y: each box holds
  // most of the other, the x - y slab of each holds nothing of the other.
  const std::vector<Vec3> p = {{0, 0, 0},       {1, 1, 0},       {1.01, 0.99, 0},
                               {0.1, -0.1, 0}, {1.1, 0.9, 0}, {1.11, 0.89, 0}};
  EXPECT_TRUE(boxes_overlap(p));
  EXPECT_TRUE(slabs_apart(p));
  EXPECT_FALSE(meet(p));
  // The same slivers on a slope, the second a layer above it, as a front over a wall:
  // the boxes overlap in z too, the slabs are still apart.
  std::vector<Vec3> q = p;
  for (int i = 0; i < 6; ++i) q[i][2] = 0.3 * q[i][0] + (i < 3 ? 0.0 : 0.05);
  EXPECT_TRUE(boxes_overlap(q));
  EXPECT_TRUE(slabs_apart(q));
}

// Coordinates near 1 and 1e6 with random low bits: most diagonal sums are inexact, and
// the float bounds round many distinct true values to one.
Vec3 random_point(testing::Lcg& lcg, double scale) {
  return {scale * (1.0 + lcg.uniform()), scale * (1.0 + lcg.uniform()), scale * (1.0 + lcg.uniform())};
}

Vec3 random_offset(testing::Lcg& lcg, double size) {
  return {size * (lcg.uniform() - 0.5), size * (lcg.uniform() - 0.5), size * (lcg.uniform() - 0.5)};
}

// Apart must imply no meeting, which the exact test decides, on pairs that touch
// (a corner of one on a corner or near an edge point of the other), on copies moved by
// a few units of the last place and on pairs drawn anywhere in one cube; a corner shared by value is a tie of the
// true bounds, which the rounded ones must keep.
TEST(DiagonalSlabs, ApartOnlyForTrianglesThatDoNotMeet) {
  testing::Lcg lcg(2026);
  int apart = 0, met = 0, shared_corners = 0;
  for (double scale : {1.0, 1e6}) {
    for (int i = 0; i < 20000; ++i) {
      std::vector<Vec3> p(6);
      for (int j = 0; j < 3; ++j) p[j] = random_point(lcg, scale);
      const int kind = i % 4;
      const double size = scale * std::ldexp(1.0, -static_cast<int>(lcg.uniform() * 50.0));
      if (kind == 0) {  // a corner on A's corner
        p[3] = p[i % 3];
        p[4] = p[3] + random_offset(lcg, size);
        p[5] = p[3] + random_offset(lcg, size);
      } else if (kind == 1) {  // a corner near A's edge midpoint
        p[3] = 0.5 * (p[0] + p[1]) + random_offset(lcg, size * 1e-12);
        p[4] = p[3] + random_offset(lcg, size);
        p[5] = p[3] + random_offset(lcg, size);
      } else if (kind == 2) {  // A moved by a tiny offset
        const Vec3 d = random_offset(lcg, scale * 1e-15);
        for (int j = 0; j < 3; ++j) p[3 + j] = p[j] + d;
      } else {  // anywhere in the same cube
        for (int j = 3; j < 6; ++j) p[j] = random_point(lcg, scale);
      }
      const bool a = slabs_apart(p), m = meet(p);
      ASSERT_FALSE(a && m) << "case " << i << " scale " << scale;
      if (kind == 0) {
        ASSERT_FALSE(a) << "a shared corner, case " << i;
        ++shared_corners;
      }
      apart += a;
      met += m;
    }
  }
  // Both outcomes are well represented, so the implication above was tested.
  EXPECT_GT(apart, 1000);
  EXPECT_GT(met, 10000);
  EXPECT_EQ(shared_corners, 10000);
}

TEST(DiagonalSlabs, ATriangleWithANonFiniteCoordinateIsNeverApart) {
  const double nan = std::nan(""), inf = HUGE_VAL;
  const DiagonalSlabs a = DiagonalSlabs::of_triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  // Without the bad coordinate the other triangle is apart from a.
  ASSERT_TRUE(a.apart(DiagonalSlabs::of_triangle({5, 5, 5}, {6, 5, 5}, {5, 6, 5})));
  for (double bad : {nan, inf, -inf})
    for (int corner = 0; corner < 3; ++corner) {
      Vec3 q[3] = {{5, 5, 5}, {6, 5, 5}, {5, 6, 5}};
      q[corner][corner] = bad;
      const DiagonalSlabs b = DiagonalSlabs::of_triangle(q[0], q[1], q[2]);
      EXPECT_FALSE(a.apart(b)) << bad << " at corner " << corner;
      EXPECT_FALSE(b.apart(a)) << bad << " at corner " << corner;
    }
}

}  // namespace
}  // namespace blayer
