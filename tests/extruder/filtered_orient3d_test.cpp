#include "blayer/quality/filtered_orient3d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "blayer/extruder/triangle_intersections.h"
#include "blayer/quality/orient3d.h"
#include "lcg.h"

namespace blayer {
namespace {

struct Rng {
  testing::Lcg lcg{987654321};
  double operator()() { return lcg.uniform(); }
};

// The filter must give orient3d_sign's answer everywhere, in particular where it cannot
// decide: exactly coplanar points, points one ulp off a plane, and scales where the
// error bound would be invalid (underflow, overflow).
TEST(FilteredOrient3d, AgreesWithTheExactPredicate) {
  Rng rnd;
  int n_zero = 0, n_pos = 0, n_neg = 0;
  for (double scale : {1.0, 1e-3, 1e6, 1e-160, 1e-300, 1e160, 1e300}) {
    for (int i = 0; i < 20000; ++i) {
      Vec3 p[4];
      for (Vec3& x : p) x = Vec3{rnd() - 0.5, rnd() - 0.5, rnd() - 0.5} * scale;
      const int kind = i % 4;
      if (kind >= 1) {
        // d on the plane of a, b, c: an affine combination with dyadic weights is often
        // exactly coplanar; nudging one coordinate by an ulp makes it nearly so.
        const double u = std::ldexp(std::floor(rnd() * 8), -3), w = std::ldexp(std::floor(rnd() * 8), -3);
        p[3] = p[0] + u * (p[1] - p[0]) + w * (p[2] - p[0]);
        if (kind == 2) p[3][2] = std::nextafter(p[3][2], HUGE_VAL);
        if (kind == 3) p[3][0] = std::nextafter(p[3][0], -HUGE_VAL);
      }
      const int exact = orient3d_sign(p[0], p[1], p[2], p[3]);
      ASSERT_EQ(detail::orient3d_filtered(p[0], p[1], p[2], p[3]), exact) << "scale " << scale << " i " << i;
      n_zero += exact == 0;
      n_pos += exact > 0;
      n_neg += exact < 0;
    }
  }
  EXPECT_GT(n_zero, 100);
  EXPECT_GT(n_pos, 1000);
  EXPECT_GT(n_neg, 1000);
}

// The same for one plane against several points, with the plane's minors shared, at
// mixed scales (points far from the plane relative to its size, and a plane of
// differences near 1e-155 whose products are subnormal, seen from points 1e110 away,
// beyond the filter's limit on differences). Every coordinate stays finite.
TEST(FilteredOrient3d, PlaneAgainstSeveralPointsAgreesWithTheExactPredicate) {
  Rng rnd;
  int n_zero = 0, n_decided = 0;
  const std::pair<double, double> scales[] = {{1.0, 1.0},     {1.0, 1e80},     {1.0, 1e-80},   {1e-3, 1.0},
                                              {1e6, 1e200},   {1e-160, 1.0},   {1e-160, 1e80}, {1e-300, 1.0},
                                              {1e-300, 1e200}, {1e160, 1.0},   {1e160, 1e-80}, {1e300, 1.0},
                                              {1e-155, 1e265}, {1e-155, 1e50}};
  for (const auto& [scale, far] : scales) {
    for (int i = 0; i < 5000; ++i) {
      Vec3 plane[3], p[4];
      for (Vec3& x : plane) x = Vec3{rnd() - 0.5, rnd() - 0.5, rnd() - 0.5} * scale;
      for (int k = 0; k < 4; ++k) {
        p[k] = Vec3{rnd() - 0.5, rnd() - 0.5, rnd() - 0.5} * (scale * far);
        if ((i + k) % 3 != 0) {
          const double u = std::ldexp(std::floor(rnd() * 8), -3), w = std::ldexp(std::floor(rnd() * 8), -3);
          p[k] = plane[0] + u * (plane[1] - plane[0]) + w * (plane[2] - plane[0]);
          if ((i + k) % 3 == 2) p[k][k % 3] = std::nextafter(p[k][k % 3], k % 2 ? HUGE_VAL : -HUGE_VAL);
        }
        ASSERT_TRUE(is_finite(p[k])) << "scale " << scale << " far " << far;
      }
      int sides[4];
      const Vec3* const at[4] = {&p[0], &p[1], &p[2], &p[3]};
      detail::orient3d_sides(plane[0], plane[1], plane[2], at, 4, sides);
      for (int k = 0; k < 4; ++k) {
        const int exact = orient3d_sign(plane[0], plane[1], plane[2], p[k]);
        ASSERT_EQ(sides[k], exact) << "scale " << scale << " far " << far << " i " << i << " point " << k;
        n_zero += exact == 0;
        n_decided += exact != 0;
      }
    }
  }
  EXPECT_GT(n_zero, 1000);
  EXPECT_GT(n_decided, 10000);
}

// A product of two differences near 2^-538 is below half the smallest subnormal and
// rounds to 0, losing 0.225 * 2^-1074 of the determinant; multiplied by a difference of
// 2^600 that is 0.225 * 2^-474, more than the one surviving term (-0.1 * 2^-474), so
// the computed determinant has the wrong sign, with a permanent of 0.1 * 2^-474 that a
// range test alone accepts and Shewchuk's relative bound far below |det|. The filters
// must hand such a case to the exact predicate (they refuse differences over 1e100).
TEST(FilteredOrient3d, UnderflowUnderAHugeDifferenceGoesToTheExactPredicate) {
  const Vec3 o{0.0, 0.0, 0.0};
  const Vec3 a{std::ldexp(1.0, 64) / 9.0, 0.0, std::ldexp(1.0, 600)};
  const Vec3 b{std::ldexp(1.0, -538), 0.0, 1.0};
  const Vec3 c{0.0, 0.9 * std::ldexp(1.0, -538), 0.0};
  const int exact = orient3d_sign(a, b, c, o);
  ASSERT_NE(exact, 0);
  EXPECT_EQ(detail::orient3d_filtered(a, b, c, o), exact);
  // The same matrix transposed, as orient3d_sides expands it: rows b - a, c - a, p - a.
  const Vec3 tb{a[0], b[0], c[0]}, tc{a[1], b[1], c[1]}, tp{a[2], b[2], c[2]};
  const int exact_t = orient3d_sign(o, tb, tc, tp);
  ASSERT_NE(exact_t, 0);
  int side;
  const Vec3* const at = &tp;
  detail::orient3d_sides(o, tb, tc, &at, 1, &side);
  EXPECT_EQ(side, exact_t);
}

TEST(FilteredOrient3d, KeepsTheSignConvention) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  EXPECT_EQ(detail::orient3d_filtered(a, b, c, Vec3{0, 0, 1}), 1);
  EXPECT_EQ(detail::orient3d_filtered(a, b, c, Vec3{0, 0, -1}), -1);
  EXPECT_EQ(detail::orient3d_filtered(a, b, c, Vec3{0.3, 0.3, 0}), 0);
}

// The plane-separation shortcut of the disjoint-triangle test must not change a verdict:
// compare with the plain definition (an edge of one meets the other) on random close
// triangles, many of which touch or nearly touch.
TEST(FilteredOrient3d, TriangleTestMatchesEdgeDefinition) {
  Rng rnd;
  std::vector<Vec3> pts(6);
  const IndexedTriangle s{0, 1, 2}, t{3, 4, 5};
  int n_hit = 0;
  for (int i = 0; i < 50000; ++i) {
    for (Vec3& x : pts) x = Vec3{std::floor(rnd() * 5), std::floor(rnd() * 5), std::floor(rnd() * 5)};
    bool reference = false;
    for (int k = 0; k < 3; ++k) {
      reference = reference || segment_intersects_triangle(pts[k], pts[(k + 1) % 3], pts[3], pts[4], pts[5]) ||
                  segment_intersects_triangle(pts[3 + k], pts[3 + (k + 1) % 3], pts[0], pts[1], pts[2]);
    }
    // Degenerate triangles are outside the contract (small integers: the cross is exact).
    if (norm2(cross(pts[1] - pts[0], pts[2] - pts[0])) == 0 || norm2(cross(pts[4] - pts[3], pts[5] - pts[3])) == 0)
      continue;
    ASSERT_EQ(soup_triangles_intersect(pts, s, t), reference) << i;
    n_hit += reference;
  }
  EXPECT_GT(n_hit, 1000);
}

// Nearly coplanar triangles, as on a flat face of a front whose heights vary a little:
// most pairs cross each other's planes with no corner on them, where the test orders the
// two segments on the planes' common line with two orientations. Some pairs share a
// corner position exactly (touching), others overlap in the plane.
TEST(FilteredOrient3d, NearlyCoplanarCrossingTrianglesMatchTheEdgeDefinition) {
  Rng rnd;
  std::vector<Vec3> pts(6);
  const IndexedTriangle s{0, 1, 2}, t{3, 4, 5};
  int n_hit = 0, n_miss = 0;
  for (int i = 0; i < 50000; ++i) {
    for (Vec3& x : pts) x = Vec3{rnd() * 4.0, rnd(), (rnd() - 0.5) * 1e-6};
    if (i % 5 == 0) pts[3] = pts[i % 3];  // a corner of t on a corner of s
    bool reference = false;
    for (int k = 0; k < 3; ++k) {
      reference = reference || segment_intersects_triangle(pts[k], pts[(k + 1) % 3], pts[3], pts[4], pts[5]) ||
                  segment_intersects_triangle(pts[3 + k], pts[3 + (k + 1) % 3], pts[0], pts[1], pts[2]);
    }
    ASSERT_EQ(soup_triangles_intersect(pts, s, t), reference) << i;
    n_hit += reference;
    n_miss += !reference;
  }
  EXPECT_GT(n_hit, 5000);
  EXPECT_GT(n_miss, 5000);
}

}  // namespace
}  // namespace blayer
