#include "blayer/core/point_in_surface.h"

#include <gtest/gtest.h>

#include <random>

#include "analytic_surfaces.h"

namespace blayer {
namespace {

using namespace test_surfaces;  // box, flipped, icosphere, merged

// Oracle: strictly behind every face plane of a convex outward surface, and the signed
// distance to the nearest plane (to skip points too close to call).
double convex_depth(const TriSurface& s, const Vec3& p) {
  double depth = HUGE_VAL;
  for (const Triangle& t : s.triangles) {
    const Vec3 n = normalized(triangle_area_vector(s, t));
    depth = std::min(depth, -dot(n, p - s.points[t[0]]));
  }
  return depth;  // > 0 inside, < 0 outside
}

TEST(PointInSurface, AgreesWithTheHalfSpaceTestOnAConvexBody) {
  const TriSurface sphere = icosphere(2);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> x(-1.2, 1.2);  // about 30 % inside
  int n_inside = 0, n_checked = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 p{x(rng), x(rng), x(rng)};
    const double depth = convex_depth(sphere, p);
    if (std::abs(depth) < 1e-6) continue;
    const Containment c = point_in_closed_surface(sphere, p, 2.0);
    ASSERT_NE(c, Containment::kUndecided) << i;
    EXPECT_EQ(c == Containment::kInside, depth > 0) << i;
    n_inside += depth > 0;
    ++n_checked;
  }
  EXPECT_GT(n_inside, 50);
  EXPECT_GT(n_checked - n_inside, 50);
}

// A hollow box (outer box, inner box wound inward): rays cross two walls, so parity
// and not the first hit decides.
TEST(PointInSurface, AgreesWithTheAnalyticShellOnANonConvexRegion) {
  const TriSurface outer = box({0, 0, 0}, {4, 4, 4}, 2), inner = box({1, 1, 1}, {3, 3, 3}, 2);
  const TriSurface shell = merged(outer, flipped(inner));
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> x(-0.5, 4.5);
  for (int i = 0; i < 300; ++i) {
    const Vec3 p{x(rng), x(rng), x(rng)};
    const double d_out = convex_depth(outer, p), d_in = convex_depth(inner, p);
    if (std::abs(d_out) < 1e-6 || std::abs(d_in) < 1e-6) continue;
    const bool expected = d_out > 0 && d_in < 0;
    EXPECT_EQ(point_in_closed_surface(shell, p, 7.0) == Containment::kInside, expected) << i;
  }
}

TEST(PointInSurface, OrientationDoesNotMatter) {
  const TriSurface sphere = icosphere(1);
  EXPECT_EQ(point_in_closed_surface(flipped(sphere), {0.1, 0.05, 0}, 2.0), Containment::kInside);
  EXPECT_EQ(point_in_closed_surface(flipped(sphere), {3, 0, 0}, 2.0), Containment::kOutside);
}

TEST(PointInSurface, PointOnTheSurfaceIsUndecided) {
  const TriSurface cube = box({0, 0, 0}, {1, 1, 1}, 1);
  EXPECT_EQ(point_in_closed_surface(cube, {0.3, 0.4, 1.0}, 2.0), Containment::kUndecided);
  EXPECT_EQ(point_in_closed_surface(cube, {0, 0, 0}, 2.0), Containment::kUndecided);
}

// A crossing through an edge would be counted twice (once per triangle) without the
// margin; count_ray_crossings refuses it and the next direction decides.
TEST(PointInSurface, RayThroughAnEdgeIsRefusedAndAnotherDirectionDecides) {
  const TriSurface cube = box({0, 0, 0}, {1, 1, 1}, 1);
  const Vec3 p{0.5, 0.5, 0.5};
  // Towards the midpoint of a top face's edge shared by its two triangles, or a box
  // edge: either way within the margin of an edge.
  const Vec3 towards_edge = normalized(Vec3{1.0, 1.0, 1.0} - p);
  EXPECT_EQ(count_ray_crossings(cube, p, towards_edge, 2.0), -1);
  EXPECT_EQ(count_ray_crossings(cube, p, {0.0, 0.3, 1.0}, 2.0), 1);
  EXPECT_EQ(point_in_closed_surface(cube, p, 2.0), Containment::kInside);
}

TEST(PointInSurface, NonPositiveLengthScaleIsAProgrammerError) {
  EXPECT_THROW(point_in_closed_surface(icosphere(0), {0, 0, 0}, 0.0), std::logic_error);
}

}  // namespace
}  // namespace blayer
