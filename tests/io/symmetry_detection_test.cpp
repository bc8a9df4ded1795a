// Half models: the symmetry plane found from (or checked against) the open boundary,
// the boundary snapped onto it, orientation by the plane-closed volume, and the clear
// refusals.
#include <gtest/gtest.h>

#include "analytic_surfaces.h"
#include "blayer/core/errors.h"
#include "blayer/io/prepare_surface.h"

namespace blayer {
namespace {

PolygonSoup soup_of(const TriSurface& s) {
  PolygonSoup p;
  p.points = s.points;
  for (const Triangle& t : s.triangles) p.faces.push_back({t[0], t[1], t[2]});
  return p;
}

// The upper half of a latitude-longitude sphere: open along the equator z = 0.
TriSurface half_sphere() { return test_surfaces::cut_at_coordinate_plane(test_surfaces::uv_sphere(8, 16, 1.0, 0.0), 2); }

std::string error_of(const TriSurface& s, const PrepareOptions& opt) {
  try {
    prepare_surface(soup_of(s), "half.off", opt);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SymmetryDetection, AHalfSphereIsAHalfModelOfTheEquatorPlaneAndIsOrientedOutward) {
  TriSurface s = half_sphere();
  for (Triangle& t : s.triangles) std::swap(t[1], t[2]);  // wound inward: must be flipped
  for (Vec3& p : s.points)
    if (p[2] == 0.0) p[2] = 3e-9;  // a cut written with rounding noise
  const PreparedSurface p = prepare_surface(soup_of(s), "half.off", PrepareOptions{});
  ASSERT_TRUE(p.symmetry.has_value());
  EXPECT_EQ(p.symmetry->axis, 2);
  EXPECT_EQ(p.symmetry->offset, 0.0);       // the noise is within tolerance of 0: the plane z = 0
  EXPECT_EQ(p.symmetry->normal[2], 1.0);    // towards the model
  EXPECT_EQ(p.n_symmetry_points, 16);
  EXPECT_DOUBLE_EQ(p.symmetry_snap, 3e-9);
  for (const Vec3& q : p.surface.points) EXPECT_TRUE(q[2] > 0.0 || q[2] == 0.0);
  EXPECT_EQ(p.n_flipped_components, 1);
  // Outward: the volume closed by the plane is positive.
  EXPECT_GT(signed_volume(p.surface), 0.0);
}

TEST(SymmetryDetection, AGivenPlaneMustHoldTheWholeBoundary) {
  PrepareOptions opt;
  opt.symmetry.mode = SymmetryMode::kPlane;
  ASSERT_TRUE(parse_symmetry_plane("z=0.1", &opt.symmetry.plane));
  const std::string e = error_of(half_sphere(), opt);
  EXPECT_NE(e.find("from the symmetry plane z = 0.1"), std::string::npos) << e;
  EXPECT_NE(e.find("hole"), std::string::npos) << e;
  ASSERT_TRUE(parse_symmetry_plane("z=0", &opt.symmetry.plane));
  EXPECT_EQ(error_of(half_sphere(), opt), "");
}

TEST(SymmetryDetection, AHoleOffThePlaneIsStillAHole) {
  TriSurface s = half_sphere();
  s.triangles.erase(s.triangles.begin());  // a hole at the pole
  const std::string e = error_of(s, PrepareOptions{});
  EXPECT_NE(e.find("open boundary edges (holes)"), std::string::npos) << e;
}

TEST(SymmetryDetection, NoneTreatsTheCutAsHoles) {
  PrepareOptions opt;
  opt.symmetry.mode = SymmetryMode::kNone;
  const std::string e = error_of(half_sphere(), opt);
  EXPECT_NE(e.find("open boundary edges (holes)"), std::string::npos) << e;
}

TEST(SymmetryDetection, ATriangleInThePlaneIsRefused) {
  TriSurface s = half_sphere();
  // Part of the equator's disk: a triangle in the plane z = 0 on two equator points.
  const int centre = static_cast<int>(s.points.size());
  s.points.push_back({0.0, 0.0, 0.0});
  int a = -1, b = -1;
  for (const Triangle& t : s.triangles)
    for (int k = 0; k < 3 && a < 0; ++k)
      if (s.points[t[k]][2] == 0.0 && s.points[t[(k + 1) % 3]][2] == 0.0) {
        a = t[k];
        b = t[(k + 1) % 3];
      }
  ASSERT_GE(a, 0);
  s.triangles.push_back({b, a, centre});  // runs the edge the other way: consistent
  const std::string e = error_of(s, PrepareOptions{});
  EXPECT_NE(e.find("lies in the symmetry plane"), std::string::npos) << e;
}

TEST(SymmetryDetection, ASurfaceOnBothSidesOfThePlaneIsRefused) {
  TriSurface s = half_sphere();
  for (Vec3& p : s.points)
    if (p[2] > 0.5 && p[2] < 0.8) p[2] = -0.2;  // a ring pushed through the plane
  const std::string e = error_of(s, PrepareOptions{});
  EXPECT_NE(e.find("both sides of the symmetry plane"), std::string::npos) << e;
}

}  // namespace
}  // namespace blayer
