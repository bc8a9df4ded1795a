#include "blayer/core/ray_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace blayer {
namespace {

const Vec3 kA{0, 0, 0}, kB{1, 0, 0}, kC{0, 1, 0};

TEST(RayTriangle, BarycentricCoordinatesAndDistanceOfAPerpendicularRay) {
  const RayTriangleHit h = intersect_ray_triangle({0.25, 0.5, 2.0}, {0, 0, -1}, kA, kB, kC);
  EXPECT_GT(h.det, 0.0);  // against the right-hand normal +z
  EXPECT_DOUBLE_EQ(h.u, 0.25);
  EXPECT_DOUBLE_EQ(h.v, 0.5);
  EXPECT_DOUBLE_EQ(h.t, 2.0);
  EXPECT_DOUBLE_EQ(ray_triangle_distance({0.25, 0.5, 2.0}, {0, 0, -1}, kA, kB, kC, 10.0), 2.0);
}

TEST(RayTriangle, ParallelRayHasZeroDeterminantAndMisses) {
  EXPECT_EQ(intersect_ray_triangle({0.2, 0.2, 1}, {1, 0, 0}, kA, kB, kC).det, 0.0);
  EXPECT_EQ(ray_triangle_distance({0.2, 0.2, 1}, {1, 0, 0}, kA, kB, kC, 10.0), HUGE_VAL);
}

TEST(RayTriangle, DistanceMissesOutsideTheTriangleBehindTheOriginAndBeyondTheLimit) {
  EXPECT_EQ(ray_triangle_distance({0.8, 0.8, 1}, {0, 0, -1}, kA, kB, kC, 10.0), HUGE_VAL);  // u + v > 1
  EXPECT_EQ(ray_triangle_distance({0.2, 0.2, -1}, {0, 0, -1}, kA, kB, kC, 10.0), HUGE_VAL);  // behind
  EXPECT_EQ(ray_triangle_distance({0.2, 0.2, 3}, {0, 0, -1}, kA, kB, kC, 2.5), HUGE_VAL);   // too far
  EXPECT_DOUBLE_EQ(ray_triangle_distance({0.2, 0.2, 3}, {0, 0, -1}, kA, kB, kC, 3.0), 3.0);
  // Edges count as hits: u + v == 1 exactly.
  EXPECT_DOUBLE_EQ(ray_triangle_distance({0.5, 0.5, 1}, {0, 0, -1}, kA, kB, kC, 10.0), 1.0);
}

// Oracle: the crossing point rebuilt from (u, v) equals the one rebuilt from t.
TEST(RayTriangle, BarycentricPointAndRayPointAgreeOnRandomTriangles) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(-2.0, 2.0);
  for (int i = 0; i < 200; ++i) {
    const Vec3 a{x(rng), x(rng), x(rng)}, b{x(rng), x(rng), x(rng)}, c{x(rng), x(rng), x(rng)};
    const Vec3 o{x(rng), x(rng), x(rng)}, d{x(rng), x(rng), x(rng)};
    const RayTriangleHit h = intersect_ray_triangle(o, d, a, b, c);
    if (std::abs(h.det) < 1e-3) continue;
    const Vec3 on_plane = a + h.u * (b - a) + h.v * (c - a);
    const Vec3 on_ray = o + h.t * d;
    EXPECT_NEAR(norm(on_plane - on_ray), 0.0, 1e-9) << i;
    EXPECT_EQ(h.det > 0.0, dot(d, cross(b - a, c - a)) < 0.0) << i;
  }
}

}  // namespace
}  // namespace blayer
