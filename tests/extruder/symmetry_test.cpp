// Half models: the columns on the symmetry plane stay in it, and the half model's
// layers are the mirrored full model's, column for column.
#include <gtest/gtest.h>

#include <cmath>

#include "blayer/extruder/extrude_layers.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

SymmetryPlane coordinate_plane(int axis) {
  SymmetryPlane p;
  p.axis = axis;
  p.normal = {0.0, 0.0, 0.0};
  p.normal[axis] = 1.0;
  p.offset = 0.0;
  return p;
}

// Points of every column, wall point first (the extruder appends them layer by layer,
// columns in index order).
std::vector<std::vector<Vec3>> column_points(std::size_t n_wall, const ExtrusionResult& r) {
  std::vector<std::vector<Vec3>> c(n_wall);
  for (std::size_t v = 0; v < n_wall; ++v) c[v].push_back(r.mesh.points[v]);
  std::size_t next = n_wall;
  for (int k = 0; next < r.mesh.points.size(); ++k)
    for (std::size_t v = 0; v < n_wall; ++v)
      if (r.column_layers[v] > k) c[v].push_back(r.mesh.points[next++]);
  return c;
}

// The half model's columns equal the mirrored full model's (to rounding: the fans are
// the same up to their starting point), and the columns on the plane lie exactly in it.
void expect_half_matches_full(const TriSurface& half, int axis, const ExtrusionParams& law) {
  ExtrusionParams with_plane = law;
  with_plane.symmetry = coordinate_plane(axis);
  const ExtrusionResult h = extrude_layers(half, with_plane);
  const TriSurface full = test_surfaces::mirrored_about_coordinate_plane(half, axis);
  const ExtrusionResult f = extrude_layers(full, law);
  ASSERT_EQ(h.report.coverage, 1.0);
  ASSERT_EQ(f.report.coverage, 1.0);
  const auto hc = column_points(half.points.size(), h), fc = column_points(full.points.size(), f);
  int on_plane = 0;
  const double scale = law.growth.first_height;
  for (std::size_t v = 0; v < half.points.size(); ++v) {
    ASSERT_EQ(hc[v].size(), fc[v].size()) << v;
    for (std::size_t k = 0; k < hc[v].size(); ++k)
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(hc[v][k][i], fc[v][k][i], 1e-9 * scale) << "column " << v << " point " << k;
    if (half.points[v][axis] != 0.0) continue;
    ++on_plane;
    for (const Vec3& q : hc[v]) EXPECT_EQ(q[axis], 0.0) << "column " << v;
  }
  EXPECT_GT(on_plane, 0);
  EXPECT_EQ(h.report.n_symmetry_columns, on_plane);
  EXPECT_EQ(h.report.max_symmetry_distance, 0.0);
}

TEST(SymmetryPlane, HalfSphereColumnsAreTheFullSpheresAndThePlaneOnesStayInIt) {
  const TriSurface half = test_surfaces::cut_at_coordinate_plane(test_surfaces::uv_sphere(8, 16, 1.0, 0.0), 2);
  expect_half_matches_full(half, 2, test::growth_params(5, 0.01, 1.2));
}

TEST(SymmetryPlane, HalfCylinderCutAlongItsAxisMatchesTheFullCylinder) {
  // Cut by x = 0 through the axis: the cut runs along two generatrices and across both
  // caps (convex 90 degree edges at the corners).
  const TriSurface half = test_surfaces::cut_at_coordinate_plane(test_surfaces::capped_cylinder(16, 6, 0.5, 2.0), 0);
  expect_half_matches_full(half, 0, test::growth_params(4, 0.01, 1.2));
}

TEST(SymmetryPlane, ABodyNearThePlaneIsLimitedByIt) {
  // A sphere of radius 1 at height 1.05 over the plane z = 0: its bottom columns face
  // the plane 0.05 away, as if the mirrored sphere's layers grew towards them.
  TriSurface s = test::icosphere(3, 1.0);
  for (Vec3& p : s.points) p[2] += 1.05;
  ExtrusionParams p = test::growth_params(5, 0.004, 1.5);  // T = 0.0525 > 0.45 x 0.05
  p.symmetry = coordinate_plane(2);
  const ExtrusionResult r = extrude_layers(s, p);
  double lowest = HUGE_VAL;
  for (const Vec3& q : r.mesh.points) lowest = std::min(lowest, q[2]);
  EXPECT_GT(lowest, 0.0);
  EXPECT_GE(lowest, 0.05 * (1.0 - p.proximity_safety) - 1e-9);
  EXPECT_GT(r.report.limited_columns[static_cast<int>(StopReason::kWallGap)], 0);
}

}  // namespace
}  // namespace blayer
