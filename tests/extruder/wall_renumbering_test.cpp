// Extruding a wall renumbered along a space-filling curve gives the mesh of the wall as
// given, up to the numbering of columns, layer points and cells, and with the wall's own
// numbering back: its points at their indices, its triangles' envelope triangles at
// theirs, and every wall id in the result meaning the wall's point or triangle.
#include "blayer/extruder/wall_renumbering.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <vector>

#include "blayer/core/spatial_order.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

// Two boxes across a gap narrower than the layers, with fans at their edges, read in a
// shuffled order (so that the spatial order differs from the input's everywhere): fan
// strips in the envelope, and columns the gap limits or ends.
TriSurface facing_boxes_shuffled(double gap = 0.05) {
  return test::shuffled(test_surfaces::merged(test_surfaces::box({0, 0, 0}, {1, 1, 1}, 3),
                                              test_surfaces::box({1 + gap, 0, 0}, {2 + gap, 1, 1}, 3)),
                        3);
}

ExtrusionParams fan_params() {
  ExtrusionParams p = test::growth_params(5, 0.01, 1.5);  // T = 0.13, more than the gaps
  p.fan_angle_deg = 60.0;
  return p;
}

// For every point of a, the point of b within tol of it, or -1 (a hash grid of cell
// 4 tol: the neighbouring cells hold every candidate).
std::vector<int> matched_points(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double tol) {
  auto cell = [&](const Vec3& p, int a_) { return static_cast<long long>(std::floor(p[a_] / (4 * tol))); };
  std::map<std::array<long long, 3>, std::vector<int>> grid;
  for (int j = 0; j < static_cast<int>(b.size()); ++j) grid[{cell(b[j], 0), cell(b[j], 1), cell(b[j], 2)}].push_back(j);
  std::vector<int> match(a.size(), -1);
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::array<long long, 3> c{cell(a[i], 0), cell(a[i], 1), cell(a[i], 2)};
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid.end()) continue;
          for (int j : it->second)
            if (norm(a[i] - b[j]) <= tol) match[i] = j;
        }
  }
  return match;
}

// Each cell as its type, layer and sorted point ids (mapped through `map`).
std::multiset<std::vector<long long>> cell_set(const VolumeMesh& m, const std::vector<int>& map) {
  const DataArray* layer = m.find_cell_array("layer");
  std::multiset<std::vector<long long>> cells;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    std::vector<long long> key;
    for (int i = 0; i < corner_count(m.cell_types[c]); ++i) key.push_back(map.empty() ? m.cell_nodes(c)[i] : map[m.cell_nodes(c)[i]]);
    std::sort(key.begin(), key.end());
    key.push_back(static_cast<long long>(m.cell_types[c]));
    key.push_back(static_cast<long long>((*layer).values[c]));
    cells.insert(key);
  }
  return cells;
}

std::vector<Vec3> centroids_of(const TriSurface& s) {
  std::vector<Vec3> c;
  for (const Triangle& t : s.triangles) c.push_back((s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0);
  return c;
}

TEST(WallRenumbering, RenumberedWallListsTheSameTrianglesWoundAlike) {
  const TriSurface wall = facing_boxes_shuffled();
  const WallRenumbering r = spatial_renumbering(wall);
  ASSERT_FALSE(r.keeps_input_order) << "a shuffled wall gains on its own order";
  ASSERT_EQ(r.point_source, morton_order(wall.points));
  const TriSurface w = renumbered_wall(wall, r);
  const TriSurface back = wall_in_input_order(w, r);
  EXPECT_EQ(back.points, wall.points);
  EXPECT_EQ(back.triangles, wall.triangles);
  ASSERT_EQ(w.points.size(), wall.points.size());
  ASSERT_EQ(w.triangles.size(), wall.triangles.size());
  for (std::size_t j = 0; j < w.triangles.size(); ++j)
    for (int i = 0; i < 3; ++i)
      ASSERT_EQ(w.points[w.triangles[j][i]], wall.points[wall.triangles[r.triangle_source[j]][i]]) << j;
  // Consecutive triangles of the renumbered wall lie closer together than in the
  // shuffled input: the point of the order.
  auto mean_step = [](const TriSurface& s) {
    double sum = 0.0;
    for (std::size_t j = 1; j < s.triangles.size(); ++j) sum += norm(s.points[s.triangles[j][0]] - s.points[s.triangles[j - 1][0]]);
    return sum / static_cast<double>(s.triangles.size() - 1);
  };
  EXPECT_LT(mean_step(w), 0.5 * mean_step(wall));
}

// Oracle for the spread: every pair of triangles compared for a shared edge.
double spread_by_all_pairs(const TriSurface& s, const std::vector<int>& source) {
  std::vector<int> position(source.size());
  for (std::size_t i = 0; i < source.size(); ++i) position[source[i]] = static_cast<int>(i);
  double sum = 0.0;
  int n = 0;
  for (std::size_t j = 0; j < s.triangles.size(); ++j)
    for (std::size_t k = j + 1; k < s.triangles.size(); ++k) {
      int shared = 0;
      for (int a : s.triangles[j])
        for (int b : s.triangles[k]) shared += a == b;
      if (shared != 2) continue;
      sum += std::log2(1.0 + std::abs(position[j] - position[k]));
      ++n;
    }
  return sum / n;
}

// A plate numbered row by row is numbered along its surface already: its own order is
// kept. Shuffled, it is renumbered, and the curve brings neighbours closer by the bar.
TEST(WallRenumbering, AWallNumberedAlongItsSurfaceKeepsItsOrder) {
  const TriSurface plate = test::square_plate(40, 1.0);
  const WallRenumbering kept = spatial_renumbering(plate);
  EXPECT_TRUE(kept.keeps_input_order);
  std::vector<int> identity(plate.triangles.size());
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(kept.triangle_source, identity);
  EXPECT_NEAR(kept.input_spread_bits, spread_by_all_pairs(plate, identity), 1e-12);
  EXPECT_NEAR(kept.spatial_spread_bits, spread_by_all_pairs(plate, morton_order(centroids_of(plate))), 1e-12);

  const TriSurface shuffled = test::shuffled(plate, 5);
  const WallRenumbering moved = spatial_renumbering(shuffled);
  EXPECT_FALSE(moved.keeps_input_order);
  EXPECT_NEAR(moved.input_spread_bits, spread_by_all_pairs(shuffled, identity), 1e-12);
  EXPECT_NEAR(moved.spatial_spread_bits, spread_by_all_pairs(shuffled, moved.triangle_source), 1e-12);
  EXPECT_LE(moved.spatial_spread_bits, moved.input_spread_bits - kMinSpreadGainBits);
  // Kept, the march is extrude_layers' own: the same mesh, bit for bit.
  TriSurface marched = plate;
  const ExtrusionParams p = test::growth_params(3, 0.01, 1.2);
  const ExtrusionResult a = extrude_layers(plate, p);
  const ExtrusionResult b = extrude_layers_in_spatial_order(&marched, p);
  EXPECT_EQ(a.mesh.points, b.mesh.points);
  EXPECT_EQ(a.mesh.connectivity, b.mesh.connectivity);
}

TEST(WallRenumbering, SpatialExtrusionGivesTheSameCellsWithTheWallsOwnNumbering) {
  const TriSurface wall = facing_boxes_shuffled();
  const ExtrusionParams p = fan_params();
  const ExtrusionResult base = extrude_layers(wall, p);
  ASSERT_FALSE(spatial_renumbering(wall).keeps_input_order);
  TriSurface marched = wall;
  const ExtrusionResult spatial = extrude_layers_in_spatial_order(&marched, p);
  ASSERT_EQ(marched.points, wall.points) << "the wall is given back in its own numbering";
  ASSERT_EQ(marched.triangles, wall.triangles) << "the wall is given back in its own numbering";
  ASSERT_GT(base.report.fans.points, 0);
  const std::size_t nv = wall.points.size();

  // The wall's points at their own indices, exactly.
  ASSERT_EQ(spatial.mesh.points.size(), base.mesh.points.size());
  for (std::size_t v = 0; v < nv; ++v) ASSERT_EQ(spatial.mesh.points[v], wall.points[v]) << v;

  // Every point matched (to rounding: sums over neighbours run in another order), the
  // wall's to themselves; then the same cells on the matched points.
  const std::vector<int> match = matched_points(spatial.mesh.points, base.mesh.points, 1e-12);
  for (std::size_t q = 0; q < match.size(); ++q) {
    ASSERT_GE(match[q], 0) << "point " << q << " has no counterpart";
    if (q < nv) ASSERT_EQ(match[q], static_cast<int>(q));
  }
  EXPECT_EQ(cell_set(spatial.mesh, match), cell_set(base.mesh, {}));

  // Point arrays follow their points. A fan point's wall row shows one of its columns,
  // the first in column order, which the numbering decides: left out.
  const DataArray* fan = spatial.mesh.find_point_array("fan_column");
  for (const char* name : {"stop_reason", "layers", "column_height", "normal"}) {
    const DataArray* a = spatial.mesh.find_point_array(name);
    const DataArray* b = base.mesh.find_point_array(name);
    const int nc = a->n_components;
    for (std::size_t q = 0; q < match.size(); ++q) {
      if (q < nv && fan->values[q] != 0) continue;
      for (int k = 0; k < nc; ++k)
        ASSERT_NEAR(a->values[q * nc + k], b->values[match[q] * nc + k], 1e-6) << name << " at point " << q;
    }
  }
}

TEST(WallRenumbering, RestoredIdsNameTheWallsOwnPointsAndTriangles) {
  // A gap of one first height: the columns across it end on the wall.
  const TriSurface wall = facing_boxes_shuffled(0.01);
  const ExtrusionParams p = fan_params();
  ASSERT_FALSE(spatial_renumbering(wall).keeps_input_order);
  TriSurface marched = wall;
  const ExtrusionResult r = extrude_layers_in_spatial_order(&marched, p);
  const std::size_t nf = wall.triangles.size();
  ASSERT_GT(r.envelope.triangles.size(), nf);  // fan strips follow the wall's triangles
  const int n_columns = static_cast<int>(r.envelope.points.size());
  // The growth law's total thickness: 0.01 (1.5^5 - 1) / 0.5. A column bends, so its
  // top may lie a little farther from its wall point; twice T still tells its own wall
  // point from any other (the boxes' points lie 1/3 apart).
  const double total = 0.01 * (std::pow(1.5, 5) - 1.0) / 0.5;
  int on_wall = 0;
  for (int c = 0; c < n_columns; ++c) {
    // A column's top is the mesh point envelope_point_ids names; one that did not grow
    // is its wall point.
    ASSERT_EQ(r.mesh.points[r.envelope_point_ids[c]], r.envelope.points[c]) << "column " << c;
    const Vec3& base = wall.points[r.column_wall_point[c]];
    ASSERT_LE(norm(r.envelope.points[c] - base), 2 * total) << "column " << c << " far from its wall point";
    if (r.column_layers[c] == 0) {
      ++on_wall;
      ASSERT_EQ(r.envelope_point_ids[c], r.column_wall_point[c]);
    }
  }
  EXPECT_GT(on_wall, 0) << "the gap should end some columns on the wall";
  // Envelope triangle j < F stands on wall triangle j: its columns' wall points are
  // that triangle's corners, in order.
  for (std::size_t j = 0; j < nf; ++j) {
    ASSERT_EQ(r.front_wall_face[j], static_cast<int>(j));
    for (int i = 0; i < 3; ++i) ASSERT_EQ(r.column_wall_point[r.envelope.triangles[j][i]], wall.triangles[j][i]) << j;
  }
  for (std::size_t j = nf; j < r.front_wall_face.size(); ++j) ASSERT_EQ(r.front_wall_face[j], -1) << j;
}

// A march that throws (here: a growth law it refuses) leaves the wall as it was given.
TEST(WallRenumbering, AThrowingMarchGivesTheWallBackInItsOwnNumbering) {
  const TriSurface wall = facing_boxes_shuffled();
  ExtrusionParams p = fan_params();
  p.growth.first_height = -1.0;
  TriSurface marched = wall;
  EXPECT_THROW(extrude_layers_in_spatial_order(&marched, p), InputError);
  EXPECT_EQ(marched.points, wall.points);
  EXPECT_EQ(marched.triangles, wall.triangles);
}

}  // namespace
}  // namespace blayer
