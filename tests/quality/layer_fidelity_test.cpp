#include "blayer/quality/layer_fidelity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "../../quality/src/nearest_triangle.h"
#include "analytic_surfaces.h"
#include "blayer/core/surface_area_split.h"

namespace blayer {
namespace {

// Closed-form inputs evaluated in a few flops: rounding stays near 1e-16 relative.
constexpr double kExact = 1e-12;

constexpr double kH1 = 0.01, kRatio = 1.2;
constexpr int kLayers = 5;

// Cumulative heights of the geometric growth law h1, h1 r, ... (N entries).
std::vector<double> cumulative_heights(double h1, double r, int n) {
  std::vector<double> z;
  double h = h1, sum = 0.0;
  for (int k = 0; k < n; ++k) {
    sum += h;
    z.push_back(sum);
    h *= r;
  }
  return z;
}

double total_thickness() { return cumulative_heights(kH1, kRatio, kLayers).back(); }

LayerFidelityTargets targets() { return {kH1, total_thickness(), kLayers}; }

// A layer mesh over `wall` in VTK order: the wall points first, then the points of each
// column (column[w] lists the points above wall point w, bottom up). A triangle's layer
// L is a wedge (a, c, b, a', c', b') when its three columns reach L + 1, else a pyramid
// (y, y', z', z, x) when two grow or a tet (x, y, z, z') when one does, closed at the
// stopped columns' tops, in the extruder's closure order (extruder/layer_cells.h).
VolumeMesh layer_mesh(const TriSurface& wall, const std::vector<std::vector<Vec3>>& column) {
  VolumeMesh m;
  m.points = wall.points;
  std::vector<std::vector<std::int64_t>> ids(wall.points.size());
  for (std::size_t w = 0; w < wall.points.size(); ++w) {
    ids[w].push_back(static_cast<std::int64_t>(w));
    for (const Vec3& p : column[w]) {
      ids[w].push_back(static_cast<std::int64_t>(m.points.size()));
      m.points.push_back(p);
    }
  }
  auto at = [&](int w, std::size_t level) { return ids[w][std::min(level, ids[w].size() - 1)]; };
  for (const Triangle& t : wall.triangles) {
    const int a = t[0], b = t[2], c = t[1];  // VTK's wedge base faces away from its top
    const std::size_t top = std::max({column[a].size(), column[b].size(), column[c].size()});
    for (std::size_t l = 0; l < top; ++l) {
      const int v[3] = {a, b, c};
      int growing = 0;
      for (int x : v) growing += column[x].size() > l;
      if (growing == 3) {
        const std::int64_t n[6] = {at(a, l), at(b, l), at(c, l), at(a, l + 1), at(b, l + 1), at(c, l + 1)};
        m.add_cell(CellType::kWedge, n);
      } else if (growing == 2) {
        int s = 0;
        while (column[v[s]].size() > l) ++s;
        const int p = v[(s + 1) % 3], q = v[(s + 2) % 3];
        const std::int64_t n[5] = {at(p, l), at(p, l + 1), at(q, l + 1), at(q, l), at(v[s], l)};
        m.add_cell(CellType::kPyramid, n);
      } else if (growing == 1) {
        int g = 0;
        while (column[v[g]].size() <= l) ++g;
        const std::int64_t n[4] = {at(v[(g + 1) % 3], l), at(v[(g + 2) % 3], l), at(v[g], l), at(v[g], l + 1)};
        m.add_cell(CellType::kTet, n);
      }
    }
  }
  return m;
}

// Columns straight along direction[w] at the cumulative heights z (same for all).
std::vector<std::vector<Vec3>> straight_columns(const TriSurface& wall, const std::vector<Vec3>& direction,
                                                const std::vector<double>& z) {
  std::vector<std::vector<Vec3>> col(wall.points.size());
  for (std::size_t w = 0; w < wall.points.size(); ++w)
    for (double s : z) col[w].push_back(wall.points[w] + s * direction[w]);
  return col;
}

// Unit square [0,1]^2 at z = 0, n x n quads split into triangles facing +z.
TriSurface flat_plate(int n) { return test_surfaces::square_plate(n, 1.0); }

int plate_id(int n, int i, int j) { return test_surfaces::plate_index(n, i, j); }

std::vector<Vec3> up(const TriSurface& s) { return std::vector<Vec3>(s.points.size(), Vec3{0, 0, 1}); }

TEST(LayerFidelity, FlatPlateAtTheRequestedHeightsIsExactInBothMeasures) {
  const TriSurface wall = flat_plate(4);
  const VolumeMesh m = layer_mesh(wall, straight_columns(wall, up(wall), cumulative_heights(kH1, kRatio, kLayers)));
  const LayerFidelity f = measure_layer_fidelity(m, wall, targets());
  EXPECT_EQ(f.n_columns, 25);
  EXPECT_EQ(f.n_grown, 25);
  EXPECT_EQ(f.n_complete, 25);
  EXPECT_EQ(f.n_branching, 0);
  for (const FidelityDistribution* d : {&f.first_over_h1_planes, &f.first_over_h1_distance, &f.top_over_T_planes,
                                        &f.top_over_T_distance}) {
    EXPECT_NEAR(d->min, 1.0, kExact);
    EXPECT_NEAR(d->max, 1.0, kExact);
  }
  EXPECT_EQ(f.first_within_1pct_planes, 1.0);
  EXPECT_EQ(f.first_within_1pct_distance, 1.0);
  EXPECT_EQ(f.top_ge_90pct_distance, 1.0);
  EXPECT_EQ(f.complete_share, 1.0);
  EXPECT_NEAR(f.area_coverage, 1.0, kExact);
  for (const ColumnFidelity& c : f.columns) EXPECT_EQ(c.layers, kLayers);
}

TEST(LayerFidelity, OneColumnWithAWrongFirstHeightIsCaught) {
  const int n = 4;
  const TriSurface wall = flat_plate(n);
  auto col = straight_columns(wall, up(wall), cumulative_heights(kH1, kRatio, kLayers));
  const int wrong = plate_id(n, 2, 2), slightly = plate_id(n, 1, 3);
  col[wrong][0][2] = 1.05 * kH1;       // 5 % too high: outside 1 %, inside 10 %
  col[slightly][0][2] = 0.995 * kH1;   // 0.5 % low: inside 1 %
  const LayerFidelity f = measure_layer_fidelity(layer_mesh(wall, col), wall, targets());
  EXPECT_NEAR(f.columns[wrong].first_height_planes, 1.05 * kH1, kExact * kH1);
  EXPECT_NEAR(f.columns[wrong].first_distance, 1.05 * kH1, kExact * kH1);
  EXPECT_NEAR(f.first_over_h1_planes.max, 1.05, kExact);
  EXPECT_NEAR(f.first_over_h1_distance.max, 1.05, kExact);
  EXPECT_NEAR(f.first_over_h1_planes.min, 0.995, kExact);
  EXPECT_DOUBLE_EQ(f.first_within_1pct_planes, 24.0 / 25.0);
  EXPECT_DOUBLE_EQ(f.first_within_1pct_distance, 24.0 / 25.0);
  EXPECT_EQ(f.first_within_10pct_planes, 1.0);
  // The tops did not move.
  EXPECT_NEAR(f.top_over_T_planes.min, 1.0, kExact);
}

TEST(LayerFidelity, StoppedColumnLowersLayersTopAndCoverage) {
  const int n = 4;
  const TriSurface wall = flat_plate(n);
  const std::vector<double> z = cumulative_heights(kH1, kRatio, kLayers);
  auto col = straight_columns(wall, up(wall), z);
  const int stopped = plate_id(n, 1, 1);
  col[stopped].resize(3);
  const VolumeMesh m = layer_mesh(wall, col);
  const LayerFidelity f = measure_layer_fidelity(m, wall, targets());
  EXPECT_EQ(f.columns[stopped].layers, 3);
  EXPECT_NEAR(f.columns[stopped].top_height_planes, z[2], kExact * z[2]);
  EXPECT_NEAR(f.columns[stopped].top_distance, z[2], kExact * z[2]);
  EXPECT_EQ(f.n_complete, 24);
  EXPECT_DOUBLE_EQ(f.complete_share, 24.0 / 25.0);
  EXPECT_NEAR(f.top_over_T_planes.min, z[2] / z.back(), kExact);
  // z[2] / T = 0.0364 / 0.0744 < 0.9: one column of 25 misses 0.9 T.
  EXPECT_DOUBLE_EQ(f.top_ge_90pct_planes, 24.0 / 25.0);
  // An interior point of this split grid has 6 triangles of area 1 / (2 n^2) each.
  EXPECT_NEAR(f.area_coverage, 1.0 - 6.0 / (2.0 * n * n), kExact);
  // The pyramids and tets closing the column carry no column edge.
  EXPECT_EQ(f.n_branching, 0);
}

TEST(LayerFidelity, ColumnWithoutLayersCountsAsZeroTop) {
  const int n = 2;
  const TriSurface wall = flat_plate(n);
  auto col = straight_columns(wall, up(wall), cumulative_heights(kH1, kRatio, kLayers));
  const int bare = plate_id(n, 1, 1);
  col[bare].clear();
  const LayerFidelity f = measure_layer_fidelity(layer_mesh(wall, col), wall, targets());
  EXPECT_EQ(f.columns[bare].layers, 0);
  EXPECT_EQ(f.n_grown, 8);
  EXPECT_EQ(f.first_over_h1_planes.count, 8);
  EXPECT_EQ(f.top_over_T_planes.count, 9);
  EXPECT_EQ(f.top_over_T_planes.min, 0.0);
  // The centre touches 6 of the 8 triangles.
  EXPECT_NEAR(f.area_coverage, 0.25, kExact);
}

TEST(LayerFidelity, FillTetsAboveTheTopsDoNotExtendColumns) {
  // A hybrid mesh: tets of a fill on top of the layers, each with an edge (2-3) leaving
  // a column top upwards. The columns still end at the layer tops.
  const TriSurface wall = flat_plate(2);
  VolumeMesh m = layer_mesh(wall, straight_columns(wall, up(wall), cumulative_heights(kH1, kRatio, kLayers)));
  const std::int64_t n_before = static_cast<std::int64_t>(m.points.size());
  for (std::size_t w = 0; w < wall.points.size(); ++w) {
    const std::int64_t top = static_cast<std::int64_t>(wall.points.size() + w * kLayers + kLayers - 1);
    m.points.push_back(m.points[top] + Vec3{0, 0, 0.5});
    const std::int64_t n[4] = {0, 1, top, n_before + static_cast<std::int64_t>(w)};
    m.add_cell(CellType::kTet, n);
  }
  const LayerFidelity f = measure_layer_fidelity(m, wall, targets());
  EXPECT_EQ(f.n_complete, 9);
  EXPECT_NEAR(f.top_over_T_planes.max, 1.0, kExact);
  for (const ColumnFidelity& c : f.columns) EXPECT_EQ(c.layers, kLayers);
}

TEST(LayerFidelity, HexahedralColumnsAreFollowed) {
  // Quads of a 3 x 3 plate extruded as hexahedra (0-1-2-3 below 4-5-6-7); the wall
  // surface is the same quads split into triangles.
  const int n = 3;
  const TriSurface wall = flat_plate(n);
  const std::vector<double> z = cumulative_heights(kH1, kRatio, kLayers);
  VolumeMesh m;
  m.points = wall.points;
  const std::int64_t nw = static_cast<std::int64_t>(wall.points.size());
  for (double h : z)
    for (const Vec3& p : wall.points) m.points.push_back({p[0], p[1], h});
  auto level = [&](int w, int l) { return l == 0 ? std::int64_t{w} : nw * l + w; };
  for (int l = 0; l < kLayers; ++l)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int q[4] = {plate_id(n, i, j), plate_id(n, i + 1, j), plate_id(n, i + 1, j + 1), plate_id(n, i, j + 1)};
        const std::int64_t nodes[8] = {level(q[0], l),     level(q[1], l),     level(q[2], l),     level(q[3], l),
                                       level(q[0], l + 1), level(q[1], l + 1), level(q[2], l + 1), level(q[3], l + 1)};
        m.add_cell(CellType::kHex, nodes);
      }
  const LayerFidelity f = measure_layer_fidelity(m, wall, targets());
  EXPECT_EQ(f.n_complete, 16);
  EXPECT_NEAR(f.top_over_T_distance.min, 1.0, kExact);
  EXPECT_NEAR(f.top_over_T_distance.max, 1.0, kExact);
}

TEST(LayerFidelity, CubeCornerColumnsAreShorterAboveThePlanesThanAway) {
  // Columns of the unit cube along the mean of their distinct face normals: along the
  // face normal on faces, (n1 + n2)/sqrt 2 on edges, the diagonal at corners. A point s
  // along such a direction is exactly s from the cube (its nearest point is the column's
  // wall point), but only s / sqrt 2 (edges) or s / sqrt 3 (corners) above the planes.
  const TriSurface wall = test_surfaces::box({0, 0, 0}, {1, 1, 1}, 2);
  std::vector<Vec3> dir(wall.points.size());
  for (std::size_t w = 0; w < wall.points.size(); ++w) {
    Vec3 d{0, 0, 0};
    for (int k = 0; k < 3; ++k) d[k] = wall.points[w][k] == 1.0 ? 1.0 : (wall.points[w][k] == 0.0 ? -1.0 : 0.0);
    dir[w] = normalized(d);
  }
  const VolumeMesh m = layer_mesh(wall, straight_columns(wall, dir, cumulative_heights(kH1, kRatio, kLayers)));
  const LayerFidelity f = measure_layer_fidelity(m, wall, targets());
  EXPECT_EQ(f.n_columns, 26);
  EXPECT_NEAR(f.first_over_h1_distance.min, 1.0, kExact);
  EXPECT_NEAR(f.first_over_h1_distance.max, 1.0, kExact);
  EXPECT_NEAR(f.first_over_h1_planes.min, 1.0 / std::sqrt(3.0), kExact);
  EXPECT_NEAR(f.first_over_h1_planes.max, 1.0, kExact);
  EXPECT_NEAR(f.top_over_T_planes.min, 1.0 / std::sqrt(3.0), kExact);
  // 6 face centres of 26 columns keep the full height above their planes.
  EXPECT_DOUBLE_EQ(f.first_within_1pct_planes, 6.0 / 26.0);
  EXPECT_EQ(f.first_within_1pct_distance, 1.0);
  // 1/sqrt 2 = 0.707 and 1/sqrt 3 = 0.577 are both below 0.9: only the 6 face columns reach 0.9 T.
  EXPECT_DOUBLE_EQ(f.top_ge_90pct_planes, 6.0 / 26.0);
  EXPECT_EQ(f.top_ge_90pct_distance, 1.0);
}

TEST(LayerFidelity, RadialSphereColumnsAreExactlyTheirLengthFromAnInscribedWall) {
  // Every point of an inscribed triangulation has |q| <= 1, so the point (1 + s) w is at
  // least s from it, and exactly s from its vertex w. Above the planes it is s (w . n_t).
  const TriSurface wall = test_surfaces::icosphere(2);
  std::vector<Vec3> dir(wall.points.begin(), wall.points.end());
  const VolumeMesh m = layer_mesh(wall, straight_columns(wall, dir, cumulative_heights(kH1, kRatio, kLayers)));
  const LayerFidelity f = measure_layer_fidelity(m, wall, targets());
  EXPECT_NEAR(f.first_over_h1_distance.min, 1.0, kExact);
  EXPECT_NEAR(f.first_over_h1_distance.max, 1.0, kExact);
  EXPECT_NEAR(f.top_over_T_distance.min, 1.0, kExact);
  double min_cos = 1.0;
  for (const Triangle& t : wall.triangles)
    for (int v : t) min_cos = std::min(min_cos, dot(wall.points[v], normalized(triangle_area_vector(wall, t))));
  EXPECT_NEAR(f.first_over_h1_planes.min, min_cos, kExact);
  EXPECT_LT(f.first_over_h1_planes.min, 0.99);  // the measures differ on a coarse sphere
}

// Independent nearest point: the foot on the plane when inside the triangle, otherwise
// the nearest of the three edges (clamped segment projections).
Vec3 nearest_by_projection(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = normalized(cross(b - a, c - a));
  const Vec3 foot = p - dot(p - a, n) * n;
  const double s0 = dot(cross(b - a, foot - a), n), s1 = dot(cross(c - b, foot - b), n),
               s2 = dot(cross(a - c, foot - c), n);
  if (s0 >= 0 && s1 >= 0 && s2 >= 0) return foot;
  auto seg = [&](const Vec3& s, const Vec3& t) {
    const double u = std::clamp(dot(p - s, t - s) / norm2(t - s), 0.0, 1.0);
    return s + u * (t - s);
  };
  Vec3 best = seg(a, b);
  for (const Vec3& q : {seg(b, c), seg(c, a)})
    if (norm(q - p) < norm(best - p)) best = q;
  return best;
}

TEST(NearestTriangle, ClosestPointMatchesProjectionOracleInEveryRegion) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Vec3 q = detail::closest_point_on_triangle(p, a, b, c);
    const Vec3 r = nearest_by_projection(p, a, b, c);
    ASSERT_NEAR(norm(q - p), norm(r - p), 1e-12) << "trial " << trial;
  }
}

TEST(NearestTriangle, TreeDistanceEqualsBruteForceMinimum) {
  const TriSurface surfaces[] = {test_surfaces::icosphere(3), test_surfaces::box({0, 0, 0}, {1, 2, 3}, 5),
                                 test_surfaces::uv_sphere(12, 20, 0.7, 0.1)};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.6, 3.4);
  for (const TriSurface& s : surfaces) {
    const detail::NearestTriangleTree tree(s);
    EXPECT_TRUE(tree.well_formed());
    for (int trial = 0; trial < 300; ++trial) {
      const Vec3 p{u(rng), u(rng), u(rng)};
      double brute = std::numeric_limits<double>::infinity();
      for (const Triangle& t : s.triangles)
        brute = std::min(brute, norm(nearest_by_projection(p, s.points[t[0]], s.points[t[1]], s.points[t[2]]) - p));
      const auto hit = tree.nearest(p);
      ASSERT_NEAR(hit.distance, brute, 1e-12) << "trial " << trial;
      ASSERT_NEAR(norm(hit.point - p), hit.distance, 1e-12);
    }
  }
}

// Above kParallelBuildItems triangles the tree's halves are built as parallel tasks and
// spliced (nearest_triangle.cpp): on a sphere of 20,480 triangles the nodes still form
// one tree whose leaves hold each triangle once, and with queries inside, outside and
// near the surface the distance is the brute-force minimum.
TEST(NearestTriangle, TreeBuiltFromParallelHalvesEqualsBruteForceMinimum) {
  const TriSurface s = test_surfaces::icosphere(5);
  ASSERT_GT(s.triangles.size(), 4u * kParallelBuildItems);
  const detail::NearestTriangleTree tree(s);
  EXPECT_TRUE(tree.well_formed());
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  for (int trial = 0; trial < 120; ++trial) {
    Vec3 p{u(rng), u(rng), u(rng)};
    if (trial % 3 == 0) p = (1.0 + 1e-3 * u(rng)) * normalized(p);  // near the surface
    double brute = std::numeric_limits<double>::infinity();
    for (const Triangle& t : s.triangles)
      brute = std::min(brute, norm(detail::closest_point_on_triangle(p, s.points[t[0]], s.points[t[1]],
                                                                     s.points[t[2]]) - p));
    ASSERT_EQ(tree.nearest(p).distance, brute) << "trial " << trial;
  }
}

// A flat strip whose triangles shrink 16-fold in width towards x = 0, 500 of them (the
// narrowest 2^-996 wide): all centroids but the widest pair's share a bin, so the
// surface-area split peels off one pair per level, and without the depth cap the tree
// would be about 250 levels deep and overflow the query's fixed stack of 128 entries.
// The tree must still return the minimum over all triangles of the same closest-point
// function (its own accuracy is tested above).
TEST(NearestTriangle, StripGradedOverHundredsOfOrdersKeepsTheTreeShallowAndExact) {
  TriSurface s;
  const int n = 250;
  for (int k = 0; k <= n; ++k) {
    const double x = std::ldexp(1.0, -4 * k);
    s.points.push_back({x, 0.0, 0.0});
    s.points.push_back({x, 1.0, 0.0});
  }
  for (int k = 0; k < n; ++k) {
    s.triangles.push_back({2 * k, 2 * k + 2, 2 * k + 1});
    s.triangles.push_back({2 * k + 1, 2 * k + 2, 2 * k + 3});
  }
  const detail::NearestTriangleTree tree(s);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 p{trial % 2 ? std::ldexp(u(rng) + 0.5, -4 * (trial % 250)) : u(rng), u(rng), 1e-3 * u(rng)};
    double brute = std::numeric_limits<double>::infinity();
    for (const Triangle& t : s.triangles)
      brute = std::min(brute, norm(detail::closest_point_on_triangle(p, s.points[t[0]], s.points[t[1]],
                                                                     s.points[t[2]]) - p));
    ASSERT_EQ(tree.nearest(p).distance, brute) << "trial " << trial;
  }
}

TEST(NearestTriangle, DistanceToABoxMatchesItsClosedForm) {
  // Outside an axis-aligned box the distance is the length of the per-axis excess.
  const Vec3 lo{0, 0, 0}, hi{1, 2, 3};
  const detail::NearestTriangleTree tree(test_surfaces::box(lo, hi, 3));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 5.0);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    double e2 = 0.0, inside = std::numeric_limits<double>::infinity();
    bool outside = false;
    for (int k = 0; k < 3; ++k) {
      const double e = std::max({lo[k] - p[k], 0.0, p[k] - hi[k]});
      outside |= e > 0.0;
      e2 += e * e;
      inside = std::min({inside, p[k] - lo[k], hi[k] - p[k]});
    }
    ASSERT_NEAR(tree.nearest(p).distance, outside ? std::sqrt(e2) : inside, 1e-12) << "trial " << trial;
  }
}

TEST(LayerFidelity, AForeignMeshWithShuffledAndRoundedPointsMeasuresAsTheOriginal) {
  // Another mesher's output: the same cells with the points in another order and their
  // coordinates read by another parser (here: rounded to float).
  const TriSurface wall = flat_plate(4);
  const VolumeMesh m = layer_mesh(wall, straight_columns(wall, up(wall), cumulative_heights(kH1, kRatio, kLayers)));
  const std::size_t np = m.points.size();
  std::vector<std::int64_t> order(np);
  for (std::size_t p = 0; p < np; ++p) order[p] = static_cast<std::int64_t>((p * 7919) % np);  // 7919 prime, np = 275
  ASSERT_NE(np % 7919, 0u);
  std::vector<std::int64_t> where(np);
  VolumeMesh foreign;
  foreign.points.resize(np);
  for (std::size_t p = 0; p < np; ++p) {
    where[order[p]] = static_cast<std::int64_t>(p);
    for (int i = 0; i < 3; ++i) foreign.points[p][i] = static_cast<float>(m.points[order[p]][i]);
  }
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    std::int64_t nodes[8];
    for (int i = 0; i < corner_count(m.cell_types[c]); ++i) nodes[i] = where[m.connectivity[m.offsets[c] + i]];
    foreign.add_cell(m.cell_types[c], nodes);
  }
  const LayerFidelity a = measure_layer_fidelity(m, wall, targets());
  const LayerFidelity b = measure_layer_fidelity(with_wall_points_first(foreign, wall), wall, targets());
  EXPECT_EQ(b.n_complete, a.n_complete);
  EXPECT_EQ(b.first_within_1pct_planes, a.first_within_1pct_planes);
  // Float rounding of the layer points: 1e-7 relative of coordinates ~1, i.e. ~1e-5 of h1.
  EXPECT_NEAR(b.first_over_h1_planes.min, a.first_over_h1_planes.min, 1e-4);
  EXPECT_NEAR(b.top_over_T_distance.p50, a.top_over_T_distance.p50, 1e-4);
  TriSurface moved = wall;
  moved.points[3][0] += 0.0123;  // no mesh point there
  EXPECT_THROW(with_wall_points_first(foreign, moved), std::invalid_argument);
}

TEST(LayerFidelity, PercentilesInterpolateBetweenOrderStatistics) {
  std::vector<double> v;
  for (int i = 100; i >= 0; --i) v.push_back(i);  // 0..100, unsorted
  const FidelityDistribution d = describe_distribution(v);
  EXPECT_EQ(d.count, 101);
  EXPECT_DOUBLE_EQ(d.p1, 1.0);
  EXPECT_DOUBLE_EQ(d.p5, 5.0);
  EXPECT_DOUBLE_EQ(d.p50, 50.0);
  EXPECT_DOUBLE_EQ(d.p99, 99.0);
  const FidelityDistribution two = describe_distribution({0.0, 10.0});
  EXPECT_DOUBLE_EQ(two.p5, 0.5);
  EXPECT_DOUBLE_EQ(two.p95, 9.5);
  EXPECT_EQ(describe_distribution({}).count, 0);
}

TEST(LayerFidelity, RejectsNonPositiveTargetsAndForeignWallPoints) {
  const TriSurface wall = flat_plate(1);
  const VolumeMesh m = layer_mesh(wall, straight_columns(wall, up(wall), {kH1}));
  EXPECT_THROW(measure_layer_fidelity(m, wall, {0.0, 1.0, 1}), std::invalid_argument);
  EXPECT_THROW(measure_layer_fidelity(m, wall, {kH1, 1.0, 0}), std::invalid_argument);
  TriSurface bigger = wall;
  bigger.points.resize(m.points.size() + 1);
  EXPECT_THROW(measure_layer_fidelity(m, bigger, targets()), std::invalid_argument);
}

}  // namespace
}  // namespace blayer
