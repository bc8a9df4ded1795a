#include "blayer/extruder/extrude_layers.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <set>

#include "blayer/core/errors.h"
#include "blayer/extruder/triangle_intersections.h"
#include "blayer/quality/cell_metrics.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

// Sums of cell volumes and the two surface volumes differ only by rounding in the
// divergence sums (a few ulps per face over ~1e4 faces): 1e-9 relative to the layer
// volume is far above that and far below any missing or doubled cell.
constexpr double kVolumeSumRelTol = 1e-9;


std::set<std::vector<std::int64_t>> sorted_faces(const std::vector<IndexedTriangle>& tris) {
  std::set<std::vector<std::int64_t>> s;
  for (const auto& t : tris) {
    std::vector<std::int64_t> f(t.begin(), t.end());
    std::sort(f.begin(), f.end());
    s.insert(f);
  }
  return s;
}

// Independent checks every extrusion must pass: exact validity of every cell, no face
// shared by more than two cells, the free faces are exactly the wall and the envelope
// triangles that carry cells (closed input), cell volumes add up to the volume between
// wall and envelope, the envelope intersects neither itself nor the wall.
void expect_valid_extrusion(const TriSurface& wall, const ExtrusionResult& r, bool closed = true) {
  const VolumeMesh& m = r.mesh;
  ASSERT_GE(m.points.size(), wall.points.size());
  for (std::size_t v = 0; v < wall.points.size(); ++v) ASSERT_EQ(m.points[v], wall.points[v]) << "wall point " << v;

  std::int64_t n_bad = 0;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const std::vector<Vec3> p = test::cell_corners(m, c);
    if (cell_validity(m.cell_types[c], p.data()) != Validity::kValid) ++n_bad;
  }
  EXPECT_EQ(n_bad, 0) << "cells failing the exact corner-tet test";

  const auto use = test::face_use(m);
  std::set<std::vector<std::int64_t>> free_faces;
  for (const auto& [f, n] : use) {
    EXPECT_LE(n, 2) << "face shared by " << n << " cells";
    if (n == 1) free_faces.insert(f);
  }
  if (closed) {
    std::vector<IndexedTriangle> expected;
    for (std::size_t t = 0; t < wall.triangles.size(); ++t) {
      const Triangle& w = wall.triangles[t];
      const IndexedTriangle e = {r.envelope_point_ids[w[0]], r.envelope_point_ids[w[1]], r.envelope_point_ids[w[2]]};
      if (e[0] == w[0] && e[1] == w[1] && e[2] == w[2]) continue;  // no cell on this triangle
      expected.push_back({w[0], w[1], w[2]});
      expected.push_back(e);
    }
    EXPECT_TRUE(free_faces == sorted_faces(expected)) << "free faces are not exactly wall + envelope";

    double cells = 0.0;
    for (std::size_t c = 0; c < m.n_cells(); ++c) cells += test::cell_volume_divergence(m, c);
    TriSurface env = r.envelope;
    const double between = signed_volume(env) - signed_volume(wall);
    EXPECT_NEAR(cells, between, kVolumeSumRelTol * std::fabs(between));
  }
  EXPECT_TRUE(find_envelope_intersections(wall, r, 10).empty()) << "envelope intersects itself or the wall";

  ASSERT_NE(m.find_cell_array("layer"), nullptr);
  EXPECT_EQ(m.find_cell_array("layer")->values.size(), m.n_cells());
  for (const char* name : {"normal", "column_height", "stop_reason", "layers"}) {
    const DataArray* a = m.find_point_array(name);
    ASSERT_NE(a, nullptr) << name;
    EXPECT_EQ(a->values.size(), a->n_components * m.points.size()) << name;
  }
}

TEST(ExtrudeLayers, SphereGetsAllLayersWithTheGrowthLawThickness) {
  const double radius = 1.0;
  const TriSurface wall = test::icosphere(3, radius);
  const ExtrusionParams p = test::growth_params(5, 0.01, 1.2);
  const ExtrusionResult r = extrude_layers(wall, p);
  expect_valid_extrusion(wall, r);
  const ExtrusionReport& rep = r.report;
  EXPECT_EQ(rep.coverage, 1.0);
  EXPECT_EQ(rep.n_wedges, 5 * static_cast<std::int64_t>(wall.triangles.size()));
  EXPECT_EQ(rep.n_pyramids + rep.n_tets, 0);
  const double total = rep.growth.total_thickness;
  // Heights above the wall planes: each step is h / V above the front's planes, and the
  // front planes turn by about one edge angle (e / R ~ 0.13) per vertex; the cos of that
  // tilt bounds the deviation: (e/R)^2 / 2 < 1 %.
  const double e = mean_edge_length(wall);
  const double tilt = 0.5 * (e / radius) * (e / radius);
  EXPECT_NEAR(rep.first_height.min, 0.01, tilt * 0.01);
  EXPECT_NEAR(rep.total_thickness.mean, total, tilt * total);
  EXPECT_NEAR(rep.total_thickness.min, total, tilt * total);
  // Layer volume against the sphere's closed form: the inscribed polyhedron's area is
  // below the sphere's by O((e/R)^2), here ~1-2 %; allow (e/R)^2.
  double vol = 0.0;
  for (std::size_t c = 0; c < r.mesh.n_cells(); ++c) vol += test::cell_volume_divergence(r.mesh, c);
  const double exact = 4.0 / 3.0 * M_PI * (std::pow(radius + total, 3) - std::pow(radius, 3));
  EXPECT_NEAR(vol, exact, (e / radius) * (e / radius) * exact);
  const DataArray* layer = r.mesh.find_cell_array("layer");
  const std::vector<std::int32_t>& layers = layer->values.as<std::int32_t>();
  EXPECT_EQ(*std::max_element(layers.begin(), layers.end()), 4);
}

TEST(ExtrudeLayers, CubeConvexEdgesAndCornersAreCovered) {
  const TriSurface wall = test::voxel_surface({4, 4, 4}, [](int, int, int) { return true; }, 0.25);
  const ExtrusionResult r = extrude_layers(wall, test::growth_params(5, 0.01, 1.2));
  expect_valid_extrusion(wall, r);
  EXPECT_EQ(r.report.coverage, 1.0);
  double min_jacobian = 1.0;
  for (std::size_t c = 0; c < r.mesh.n_cells(); ++c) {
    const std::vector<Vec3> p = test::cell_corners(r.mesh, c);
    min_jacobian = std::min(min_jacobian, compute_cell_metrics(r.mesh.cell_types[c], p.data()).scaled_jacobian);
  }
  EXPECT_GT(min_jacobian, 0.0);
  // Corner columns move diagonally: at least the flat-face height above every face.
  EXPECT_GE(r.report.total_thickness.min, 0.99 * r.report.growth.total_thickness);
}

TEST(ExtrudeLayers, StoppedColumnsCloseWithPyramidsAndTets) {
  // With min_visibility 0.75 the cube's edge (V = cos 45) and corner (V = cos 54.7)
  // columns cannot start; the face columns grow, and the layer closes conformingly.
  const TriSurface wall = test::voxel_surface({4, 4, 4}, [](int, int, int) { return true; }, 0.25);
  ExtrusionParams p = test::growth_params(3, 0.01, 1.2);
  p.min_visibility = 0.75;
  const ExtrusionResult r = extrude_layers(wall, p);
  expect_valid_extrusion(wall, r);
  const int n_edge_and_corner = 12 * 3 + 8;
  EXPECT_EQ(r.report.stopped_columns[static_cast<int>(StopReason::kVisibility)], n_edge_and_corner);
  for (std::size_t v = 0; v < wall.points.size(); ++v) {
    const Vec3& q = wall.points[v];
    int on_faces = 0;
    for (int i = 0; i < 3; ++i) on_faces += (q[i] == 0.0 || q[i] == 1.0);
    EXPECT_EQ(r.column_layers[v], on_faces >= 2 ? 0 : 3) << "vertex " << v;
  }
  EXPECT_GT(r.report.n_pyramids, 0);
  EXPECT_GT(r.report.n_tets, 0);
  EXPECT_LT(r.report.coverage, 1.0);
  const DataArray* reason = r.mesh.find_point_array("stop_reason");
  ASSERT_NE(reason, nullptr);
  EXPECT_EQ(reason->values[0], static_cast<double>(r.stop_reason[0]));
}

TEST(ExtrudeLayers, LBlockConcaveEdgeStaysValid) {
  const TriSurface wall =
      test::voxel_surface({4, 2, 4}, [](int i, int, int k) { return !(i >= 2 && k >= 2); }, 0.25);
  const ExtrusionResult r = extrude_layers(wall, test::growth_params(5, 0.01, 1.2));
  expect_valid_extrusion(wall, r);
  EXPECT_GE(r.report.coverage, 0.95);
}

TEST(ExtrudeLayers, BoxInteriorConcaveCornersStayValid) {
  const TriSurface wall = test::flipped(test::voxel_surface({4, 4, 4}, [](int, int, int) { return true; }, 0.25));
  const ExtrusionResult r = extrude_layers(wall, test::growth_params(5, 0.01, 1.2));
  expect_valid_extrusion(wall, r);
  EXPECT_GE(r.report.coverage, 0.95);
}

TEST(ExtrudeLayers, ThinSlotFrontsStopBeforeMeeting) {
  // A block with a slot one cell (0.25) wide; the requested thickness (0.2 per side)
  // would make the two fronts in the slot overlap.
  const double cell = 0.25;
  const TriSurface wall =
      test::voxel_surface({5, 3, 3}, [](int i, int, int k) { return !(i == 2 && k >= 1); }, cell);
  ExtrusionParams p;
  p.fan_angle_deg = 0.0;  // single columns, indexed by wall point below
  p.growth.layers = 5;
  p.growth.total_thickness = 0.2;
  p.growth.growth_ratio = 1.2;
  const ExtrusionResult r = extrude_layers(wall, p);
  expect_valid_extrusion(wall, r);
  // Slot walls are the planes x = 2 cell and x = 3 cell; deep inside the slot (away
  // from its rim and floor) the column tops must keep the two fronts apart.
  double max_left = -1.0, min_right = 10.0;
  for (std::size_t v = 0; v < wall.points.size(); ++v) {
    const Vec3& w = wall.points[v];
    const Vec3& t = r.envelope.points[v];
    if (w[2] <= 1.5 * cell || w[2] >= 2.5 * cell) continue;  // mid depth only
    if (w[0] == 2 * cell) max_left = std::max(max_left, t[0]);
    if (w[0] == 3 * cell) min_right = std::min(min_right, t[0]);
  }
  ASSERT_GT(max_left, 0.0);
  EXPECT_LT(max_left, min_right) << "fronts in the slot met";
  EXPECT_LE(max_left - 2 * cell, 0.5 * cell);
  EXPECT_GT(r.report.limited_columns[static_cast<int>(StopReason::kWallGap)], 0);
}

TEST(ExtrudeLayers, RelativeHeightsScaleWithTheLocalEdgeLength) {
  const TriSurface wall = test::icosphere(2, 1.0);
  ExtrusionParams p = test::growth_params(3, 0.1, 1.2);
  p.growth.relative = true;
  const ExtrusionResult r = extrude_layers(wall, p);
  expect_valid_extrusion(wall, r);
  const double e = mean_edge_length(wall);
  // Icosphere edges vary by ~20 % around the mean.
  EXPECT_NEAR(r.report.first_height.mean, 0.1 * e, 0.2 * 0.1 * e);
  EXPECT_NEAR(r.report.thickness_fraction.mean, 1.0, 0.05);
}

TEST(ExtrudeLayers, ResultDoesNotDependOnTheThreadCount) {
  const TriSurface wall = test::voxel_surface({4, 2, 4}, [](int i, int, int k) { return !(i >= 2 && k >= 2); }, 0.25);
  const ExtrusionParams p = test::growth_params(4, 0.02, 1.3);
  ExtrusionResult a;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    a = extrude_layers(wall, p);
  }
  const ExtrusionResult b = extrude_layers(wall, p);
  EXPECT_EQ(a.mesh.points, b.mesh.points);
  EXPECT_EQ(a.mesh.connectivity, b.mesh.connectivity);
  EXPECT_EQ(a.mesh.cell_types, b.mesh.cell_types);
}

TEST(ExtrudeLayers, ProgressIsReportedPerLayer) {
  const TriSurface wall = test::icosphere(1, 1.0);
  std::vector<int> seen;
  extrude_layers(wall, test::growth_params(3, 0.01, 1.2), [&](int k, int n) {
    EXPECT_EQ(n, 3);
    seen.push_back(k);
  });
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3}));
}

TEST(ExtrudeLayers, RejectsBadParameters) {
  const TriSurface wall = test::icosphere(1, 1.0);
  ExtrusionParams p = test::growth_params(3, 0.01, 1.2);
  p.proximity_safety = 0.8;
  EXPECT_THROW(extrude_layers(wall, p), InputError);
  p = test::growth_params(3, 0.01, 1.2);
  p.min_visibility = 0.0;
  EXPECT_THROW(extrude_layers(wall, p), InputError);
  p = ExtrusionParams{};  // no height given
  EXPECT_THROW(extrude_layers(wall, p), InputError);
}

TEST(ExtrudeLayers, ReportNamesTheFigures) {
  const TriSurface wall = test::icosphere(1, 1.0);
  const ExtrusionResult r = extrude_layers(wall, test::growth_params(2, 0.01, 1.2));
  const std::string s = format_extrusion_report(r.report);
  for (const char* key : {"coverage", "first height", "total thickness", "wedges", "stopped", "time"})
    EXPECT_NE(s.find(key), std::string::npos) << key;
}

}  // namespace
}  // namespace blayer
