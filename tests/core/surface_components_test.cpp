#include "blayer/core/surface_components.h"

#include <gtest/gtest.h>

#include "analytic_surfaces.h"

namespace blayer {
namespace {

using test_surfaces::box;
using test_surfaces::flipped;
using test_surfaces::icosphere;
using test_surfaces::merged;

SurfaceComponents components_of(const TriSurface& s) { return edge_connected_components(s, build_edge_topology(s)); }

TEST(SurfaceComponents, OneClosedSurfaceIsOneComponentWithItsVolume) {
  const TriSurface cube = box({0, 0, 0}, {2, 1, 1}, 2);
  const SurfaceComponents c = components_of(cube);
  EXPECT_EQ(c.count, 1);
  const std::vector<double> v = component_signed_volumes(cube, c);
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NEAR(v[0], 2.0, 1e-12);
}

TEST(SurfaceComponents, SeparateBodiesAreNumberedByTheirFirstTriangleWithSignedVolumes) {
  const TriSurface a = box({0, 0, 0}, {1, 1, 1}, 1);
  const TriSurface b = flipped(box({3, 0, 0}, {5, 1, 1}, 1));  // inward: negative volume
  const TriSurface s = merged(merged(a, b), icosphere(1, 0.5, {0, 4, 0}));
  const SurfaceComponents c = components_of(s);
  ASSERT_EQ(c.count, 3);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const int expected = t < a.triangles.size() ? 0 : t < a.triangles.size() + b.triangles.size() ? 1 : 2;
    EXPECT_EQ(c.of_triangle[t], expected) << t;
  }
  const std::vector<double> v = component_signed_volumes(s, c);
  EXPECT_NEAR(v[0], 1.0, 1e-12);
  EXPECT_NEAR(v[1], -2.0, 1e-12);
  // The third is the sphere alone: same volume as measured on its own surface.
  EXPECT_NEAR(v[2], signed_volume(icosphere(1, 0.5, {0, 4, 0})), 1e-12);
}

TEST(SurfaceComponents, BodiesTouchingAtAVertexStaySeparate) {
  // Two tetrahedra sharing point 0 only.
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  s.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 4, 5}, {0, 6, 4}, {4, 6, 5}, {0, 5, 6}};
  const SurfaceComponents c = components_of(s);
  EXPECT_EQ(c.count, 2);
  const std::vector<double> v = component_signed_volumes(s, c);
  EXPECT_NEAR(v[0], 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(std::abs(v[1]), 1.0 / 6.0, 1e-15);
}

TEST(SurfaceComponents, VolumeDoesNotDependOnWhereTheBodyLies) {
  const double near = component_signed_volumes(icosphere(2), components_of(icosphere(2)))[0];
  const TriSurface far_away = icosphere(2, 1.0, {1e6, -2e6, 3e6});
  const double far = component_signed_volumes(far_away, components_of(far_away))[0];
  EXPECT_NEAR(far, near, 1e-9 * near);
}

}  // namespace
}  // namespace blayer
