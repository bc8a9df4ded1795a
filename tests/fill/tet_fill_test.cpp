#include "blayer/fill/tet_fill.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <iostream>

#include "blayer/core/errors.h"
#include "blayer/quality/mesh_check.h"
#include "mesh_checks.h"
#include "analytic_surfaces.h"

namespace blayer {
namespace {

using test_surfaces::box;
using fill_test::check_fill;
using test_surfaces::flipped;
using test_surfaces::icosphere;
using test_surfaces::merged;

// Summing a few thousand tet volumes in long double loses far less than this relative
// amount; a missing or extra tet changes the sum by much more.
constexpr double kVolumeRel = 1e-9;

double box_volume(const std::vector<Vec3>& pts, std::size_t begin) {
  Vec3 lo = pts[begin], hi = lo;
  for (std::size_t i = begin; i < pts.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], pts[i][k]);
      hi[k] = std::max(hi[k], pts[i][k]);
    }
  return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
}

Vec3 centroid(const VolumeMesh& m, std::size_t c) {
  const PointId* n = m.cell_nodes(c);
  return (m.points[n[0]] + m.points[n[1]] + m.points[n[2]] + m.points[n[3]]) / 4.0;
}

// True when p lies strictly inside the convex closed surface s (outward normals).
bool inside_convex(const TriSurface& s, const Vec3& p) {
  for (const Triangle& t : s.triangles)
    if (dot(triangle_area_vector(s, t), p - s.points[t[0]]) >= 0) return false;
  return true;
}

void print_figures(const char* name, const FillResult& r) {
  const FillStats& s = r.stats;
  std::cout << "[fill] " << name << ": tets " << s.n_tets << ", steiner " << s.n_steiner_points
            << ", farfield points " << s.n_farfield_points << ", min dihedral "
            << s.min_dihedral_deg << " deg, max radius-edge " << s.max_radius_edge << ", check "
            << s.seconds_check << " s, tetgen " << s.seconds_tetgen << " s, total "
            << s.seconds_total << " s\n";
}

void expect_envelope_prefix(const FillResult& r, const TriSurface& env) {
  ASSERT_GE(r.tets.points.size(), env.points.size());
  for (std::size_t i = 0; i < env.points.size(); ++i)
    EXPECT_EQ(r.tets.points[i], env.points[i]) << i;
  ASSERT_GE(r.boundary.triangles.size(), env.triangles.size());
  for (std::size_t t = 0; t < env.triangles.size(); ++t) {
    EXPECT_EQ(r.boundary.triangles[t], env.triangles[t]);
    EXPECT_EQ(r.boundary_marker[t], kEnvelopeMarker);
  }
  for (std::size_t t = env.triangles.size(); t < r.boundary.triangles.size(); ++t)
    EXPECT_EQ(r.boundary_marker[t], kFarfieldMarker);
}

std::string error_of(const TriSurface& env, const FillOptions& opt) {
  try {
    fill_with_tets(env, opt);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

TEST(TetFill, SphereInBoxGivesPositiveConformingTetsOutsideTheBody) {
  const TriSurface sphere = icosphere(2);
  const FillResult r = fill_with_tets(sphere, FillOptions{});
  print_figures("sphere 320 triangles", r);
  expect_envelope_prefix(r, sphere);
  const auto fig = check_fill(r);
  EXPECT_EQ(r.stats.n_holes, 1);
  EXPECT_GT(r.stats.n_steiner_points, 0);
  EXPECT_EQ(r.stats.n_tets, static_cast<std::int64_t>(r.tets.n_cells()));
  const double expected = box_volume(r.tets.points, sphere.points.size()) - signed_volume(sphere);
  EXPECT_NEAR(static_cast<double>(fig.volume), expected, kVolumeRel * expected);
  for (std::size_t c = 0; c < r.tets.n_cells(); ++c)
    EXPECT_FALSE(inside_convex(sphere, centroid(r.tets, c))) << "tet " << c << " inside the body";
  // The default box: each side 10 times the envelope's extent (2).
  EXPECT_NEAR(box_volume(r.tets.points, sphere.points.size()), 20.0 * 20.0 * 20.0, 1e-9);
  EXPECT_GT(r.stats.min_dihedral_deg, 0.0);
}

TEST(TetFill, SphereFillPassesTheQualityModulesMeshCheck) {
  const TriSurface sphere = icosphere(2);
  const FillResult r = fill_with_tets(sphere, FillOptions{});
  const MeshCheckReport report = check_volume_mesh(r.tets);
  EXPECT_TRUE(report.ok()) << format_check_report(report);
  EXPECT_EQ(report.totals.by_type[0], r.tets.n_cells());
  EXPECT_EQ(report.boundary_faces, r.boundary.triangles.size());
}

TEST(TetFill, CubeInBoxKeepsEveryCubeTriangleAsATetFace) {
  const TriSurface cube = box({0, 0, 0}, {1, 1, 1}, 4);
  const FillResult r = fill_with_tets(cube, FillOptions{});
  print_figures("cube 192 triangles", r);
  expect_envelope_prefix(r, cube);
  const auto fig = check_fill(r);
  const double expected = box_volume(r.tets.points, cube.points.size()) - 1.0;
  EXPECT_NEAR(static_cast<double>(fig.volume), expected, kVolumeRel * expected);
  for (std::size_t c = 0; c < r.tets.n_cells(); ++c) {
    const Vec3 p = centroid(r.tets, c);
    const bool in_cube = p[0] > 0 && p[0] < 1 && p[1] > 0 && p[1] < 1 && p[2] > 0 && p[2] < 1;
    EXPECT_FALSE(in_cube) << "tet " << c << " inside the body";
  }
}

TEST(TetFill, InsideRegionFillsAnInwardOrientedCube) {
  const TriSurface cube = box({0, 0, 0}, {3, 1, 1}, 3, /*inward=*/true);
  FillOptions opt;
  opt.region = FillOptions::Region::kInside;
  const FillResult r = fill_with_tets(cube, opt);
  print_figures("inside duct 3x1x1", r);
  expect_envelope_prefix(r, cube);
  EXPECT_EQ(r.boundary.triangles.size(), cube.triangles.size());
  EXPECT_EQ(r.stats.n_farfield_points, 0);
  EXPECT_EQ(r.stats.n_holes, 0);
  const auto fig = check_fill(r);
  EXPECT_NEAR(static_cast<double>(fig.volume), 3.0, kVolumeRel * 3.0);
}

TEST(TetFill, InsideRegionLeavesAnInnerBodyEmpty) {
  const TriSurface pipe = box({0, 0, 0}, {4, 2, 2}, 4, /*inward=*/true);
  const TriSurface rod = box({1, 0.75, 0.75}, {3, 1.25, 1.25}, 2);
  const TriSurface env = merged(pipe, rod);
  FillOptions opt;
  opt.region = FillOptions::Region::kInside;
  const FillResult r = fill_with_tets(env, opt);
  EXPECT_EQ(r.stats.n_holes, 1);
  const auto fig = check_fill(r);
  const double expected = 16.0 - 0.5;
  EXPECT_NEAR(static_cast<double>(fig.volume), expected, kVolumeRel * expected);
}

TEST(TetFill, TwoBodiesGetOneHoleEach) {
  const TriSurface env = merged(icosphere(1, 1.0, {-2, 0, 0}), icosphere(1, 0.5, {2, 0, 0}));
  const FillResult r = fill_with_tets(env, FillOptions{});
  EXPECT_EQ(r.stats.n_holes, 2);
  const auto fig = check_fill(r);
  const double expected = box_volume(r.tets.points, env.points.size()) - signed_volume(env);
  EXPECT_NEAR(static_cast<double>(fig.volume), expected, kVolumeRel * expected);
}

TEST(TetFill, UserFarfieldIsAcceptedInEitherOrientationAndReportedFacingTheDomain) {
  const TriSurface sphere = icosphere(2);
  for (bool flip : {false, true}) {
    SCOPED_TRACE(flip ? "farfield facing inward" : "farfield facing outward");
    const TriSurface far = flip ? flipped(icosphere(2, 8.0)) : icosphere(2, 8.0);
    FillOptions opt;
    opt.farfield = &far;
    const FillResult r = fill_with_tets(sphere, opt);
    expect_envelope_prefix(r, sphere);
    EXPECT_EQ(r.stats.n_farfield_points, static_cast<std::int64_t>(far.points.size()));
    for (std::size_t i = 0; i < far.points.size(); ++i)
      EXPECT_EQ(r.tets.points[sphere.points.size() + i], far.points[i]);
    const auto fig = check_fill(r);
    const double expected = std::abs(signed_volume(far)) - signed_volume(sphere);
    EXPECT_NEAR(static_cast<double>(fig.volume), expected, kVolumeRel * expected);
    for (std::size_t t = sphere.triangles.size(); t < r.boundary.triangles.size(); ++t) {
      const Triangle& tri = r.boundary.triangles[t];
      EXPECT_LT(dot(triangle_area_vector(r.boundary, tri), r.boundary.points[tri[0]]), 0.0)
          << "farfield triangle " << t << " does not face the domain";
    }
  }
}

TEST(TetFill, UnusedEnvelopePointsKeepTheirIndexAndStayUnreferenced) {
  TriSurface sphere = icosphere(1);
  // One unused point in front, one at the end; triangles shifted to match.
  sphere.points.insert(sphere.points.begin(), Vec3{0.1, 0.2, 0.3});
  for (Triangle& t : sphere.triangles)
    for (int& v : t) ++v;
  sphere.points.push_back({5, 5, 5});
  const FillResult r = fill_with_tets(sphere, FillOptions{});
  expect_envelope_prefix(r, sphere);
  check_fill(r);
  const std::int64_t last = static_cast<std::int64_t>(sphere.points.size()) - 1;
  for (std::int64_t v : r.tets.connectivity) {
    EXPECT_NE(v, 0);
    EXPECT_NE(v, last);
  }
}

TEST(TetFill, SizeGradesFromTheEnvelopeEdgeLengthToTheFarfield) {
  const TriSurface sphere = icosphere(2);
  const double h = mean_edge_length(sphere);
  const FillResult r = fill_with_tets(sphere, FillOptions{});
  double near_sum = 0, far_sum = 0;
  int near_n = 0, far_n = 0;
  for (std::size_t c = 0; c < r.tets.n_cells(); ++c) {
    const PointId* n = r.tets.cell_nodes(c);
    double longest = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        longest = std::max(longest, norm(r.tets.points[n[i]] - r.tets.points[n[j]]));
    const double dist = norm(centroid(r.tets, c)) - 1.0;
    if (dist < 0.5 * h) {
      near_sum += longest;
      ++near_n;
    } else if (dist > 6.0) {
      far_sum += longest;
      ++far_n;
    }
  }
  ASSERT_GT(near_n, 0);
  ASSERT_GT(far_n, 0);
  const double near_mean = near_sum / near_n, far_mean = far_sum / far_n;
  std::cout << "[fill] envelope edge " << h << ", longest tet edge near " << near_mean << ", far "
            << far_mean << ", farfield size " << r.stats.farfield_size << "\n";
  // Next to the envelope the tets are about as large as its triangles (quality-bound
  // tets on a given triangle have their longest edge within a small factor of it).
  EXPECT_GT(near_mean, 0.7 * h);
  EXPECT_LT(near_mean, 2.0 * h);
  // s(x) = h + 0.3 d reaches about 2 h + 1.8 at d = 6,
  EXPECT_GT(far_mean, 4.0 * near_mean);
  // Slower growth keeps more tets.
  FillOptions slow;
  slow.growth = 1.15;
  EXPECT_GT(fill_with_tets(sphere, slow).stats.n_tets, r.stats.n_tets);
}

// Failure messages check_fill reports for r, captured instead of failing this test.
std::string check_fill_failures(const FillResult& r) {
  testing::TestPartResultArray failures;
  {
    testing::ScopedFakeTestPartResultReporter reporter(
        testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
    check_fill(r);
  }
  std::string all;
  for (int i = 0; i < failures.size(); ++i)
    all += failures.GetTestPartResult(i).message() + std::string("\n");
  return all;
}

// The independent checks must be able to fail: corrupt a good fill and see them fire.
TEST(TetFillChecks, DetectInvertedAndMissingTets) {
  const FillResult good = fill_with_tets(box({0, 0, 0}, {1, 1, 1}, 1), FillOptions{});
  EXPECT_EQ(check_fill_failures(good), "");
  FillResult inverted = good;
  std::swap(inverted.tets.connectivity[1], inverted.tets.connectivity[2]);
  EXPECT_NE(check_fill_failures(inverted).find("n_nonpositive"), std::string::npos);
  FillResult missing = good;
  missing.tets.cell_types.pop_back();
  missing.tets.offsets.pop_back();
  missing.tets.connectivity.resize(missing.tets.connectivity.size() - 4);
  EXPECT_NE(check_fill_failures(missing).find("not an input triangle"), std::string::npos);
}

TEST(TetFill, SelfIntersectingEnvelopeIsAnInputErrorNotACrash) {
  const TriSurface env = merged(icosphere(1, 1.0, {0, 0, 0}), icosphere(1, 1.0, {0.5, 0.1, 0.05}));
  const std::string msg = error_of(env, FillOptions{});
  EXPECT_NE(msg.find("intersects itself"), std::string::npos) << msg;
}

TEST(TetFill, EnvelopeTouchingTheUserFarfieldIsAnInputError) {
  const TriSurface sphere = icosphere(1);
  const TriSurface far = box({-1.5, -1.5, -1.5}, {0.6, 1.5, 1.5}, 2);
  FillOptions opt;
  opt.farfield = &far;
  const std::string msg = error_of(sphere, opt);
  EXPECT_NE(msg.find("intersects itself"), std::string::npos) << msg;
}

TEST(TetFill, TetgenTimeoutIsAnInputErrorAndTheCallerContinues) {
  FillOptions opt;
  opt.timeout_seconds = 1e-9;
  const std::string msg = error_of(icosphere(2), opt);
  EXPECT_NE(msg.find("tetgen failed"), std::string::npos) << msg;
  EXPECT_NE(msg.find("(signal 9)"), std::string::npos) << msg;
  EXPECT_GT(fill_with_tets(icosphere(1), FillOptions{}).stats.n_tets, 0);
}

TEST(TetFill, OpenEnvelopeIsAnInputError) {
  TriSurface sphere = icosphere(1);
  sphere.triangles.pop_back();
  const std::string msg = error_of(sphere, FillOptions{});
  EXPECT_NE(msg.find("envelope is open: 3 boundary edges"), std::string::npos) << msg;
}

TEST(TetFill, InconsistentlyOrientedEnvelopeIsAnInputError) {
  TriSurface sphere = icosphere(1);
  std::swap(sphere.triangles[0][1], sphere.triangles[0][2]);
  const std::string msg = error_of(sphere, FillOptions{});
  EXPECT_NE(msg.find("not consistently oriented"), std::string::npos) << msg;
}

TEST(TetFill, InwardEnvelopeWithOutsideRegionPointsToInternalFlow) {
  const std::string msg = error_of(flipped(icosphere(1)), FillOptions{});
  EXPECT_NE(msg.find("region inside"), std::string::npos) << msg;
}

TEST(TetFill, OutwardEnvelopeWithInsideRegionPointsToExternalFlow) {
  FillOptions opt;
  opt.region = FillOptions::Region::kInside;
  const std::string msg = error_of(icosphere(1), opt);
  EXPECT_NE(msg.find("use region outside"), std::string::npos) << msg;
}

TEST(TetFill, FarfieldNotEnclosingTheEnvelopeIsAnInputError) {
  const TriSurface sphere = icosphere(1);
  const TriSurface far = box({3, 3, 3}, {5, 5, 5}, 1);
  FillOptions opt;
  opt.farfield = &far;
  const std::string msg = error_of(sphere, opt);
  EXPECT_NE(msg.find("farfield does not enclose"), std::string::npos) << msg;
}

TEST(TetFill, DuplicatePointsAndBadOptionsAreInputErrors) {
  TriSurface sphere = icosphere(1);
  sphere.points[0] = sphere.points[1];
  EXPECT_NE(error_of(sphere, FillOptions{}).find("two boundary points coincide"),
            std::string::npos);

  FillOptions opt;
  opt.growth = 0.9;
  EXPECT_NE(error_of(icosphere(1), opt).find("growth"), std::string::npos);
  opt = FillOptions{};
  opt.quality_radius_edge = 1.0;
  EXPECT_NE(error_of(icosphere(1), opt).find("quality_radius_edge"), std::string::npos);
  opt = FillOptions{};
  opt.region = FillOptions::Region::kInside;
  const TriSurface far = icosphere(1, 5.0);
  opt.farfield = &far;
  EXPECT_NE(error_of(flipped(icosphere(1)), opt).find("only used with region outside"),
            std::string::npos);
}

}  // namespace
}  // namespace blayer
