// Fans of columns at sharp convex edges: the layout on analytic solids (counts and
// angles known in closed form), and extrusions with fans checked cell by cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <set>

#include "blayer/core/edge_topology.h"
#include "blayer/core/vertex_fans.h"
#include "blayer/extruder/column_heights.h"
#include "blayer/extruder/extrude_layers.h"
#include "blayer/extruder/fan_layout.h"
#include "blayer/extruder/layer_assembly.h"
#include "blayer/extruder/front_checker.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_planes.h"
#include "blayer/extruder/wall_topology.h"
#include "blayer/quality/layer_fidelity.h"
#include "lcg.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Directions built from unit face normals by slerp and normalisation: a few ulps.
constexpr double kAngleTol = 1e-12;

double degrees(double rad) { return rad * 180.0 / kPi; }

ColumnLayout layout_of(const TriSurface& s, double fan_angle = 60.0, double max_sector = 30.0) {
  return build_column_layout(s, build_vertex_fans(s), FanParams{fan_angle, max_sector}, NormalMethod::kMostNormal,
                             std::vector<char>(s.points.size(), 0));
}

std::map<int, std::vector<int>> columns_by_point(const ColumnLayout& l) {
  std::map<int, std::vector<int>> m;
  for (int c = 0; c < l.n_columns(); ++c) m[l.wall_point[c]].push_back(c);
  return m;
}

Vec3 unit_normal(const TriSurface& s, int f) { return normalized(triangle_area_vector(s, s.triangles[f])); }

// A triangular prism along y (0..width, n_y segments) whose profile in x-z is the
// isosceles triangle with apex angle `apex_deg` at the origin, opening towards +x up to
// x = length: the apex edge is a sharp trailing edge. Normals point outward.
TriSurface wedge_prism(double apex_deg, double length, double width, int n_y) {
  const double half = 0.5 * apex_deg * kPi / 180.0;
  const std::array<Vec3, 3> profile{Vec3{0, 0, 0}, Vec3{length, 0, -length * std::tan(half)},
                                    Vec3{length, 0, length * std::tan(half)}};
  TriSurface s;
  for (int j = 0; j <= n_y; ++j)
    for (const Vec3& p : profile) s.points.push_back({p[0], width * j / n_y, p[2]});
  auto id = [](int j, int i) { return 3 * j + i; };
  const Vec3 centre{2.0 * length / 3.0, 0.5 * width, 0.0};
  auto add = [&](Triangle t) {
    const Vec3 c = (s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0;
    if (dot(triangle_area_vector(s, t), c - centre) < 0) std::swap(t[1], t[2]);
    s.triangles.push_back(t);
  };
  for (int j = 0; j < n_y; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = id(j, i), b = id(j, (i + 1) % 3), c = id(j + 1, (i + 1) % 3), d = id(j + 1, i);
      add({a, b, c});
      add({a, c, d});
    }
  add({id(0, 0), id(0, 1), id(0, 2)});
  add({id(n_y, 0), id(n_y, 1), id(n_y, 2)});
  return s;
}

// An L-shaped block: 2 x 2 x 1 voxels minus (1, 1, 0); its inner vertical edge is
// concave, and each of its ends is a corner of two convex edges and that concave one.
TriSurface l_block() {
  return test::voxel_surface({2, 2, 1}, [](int i, int j, int) { return !(i == 1 && j == 1); }, 1.0);
}

void expect_closed_and_oriented(const TriSurface& front) {
  EXPECT_TRUE(build_edge_topology(front).closed_manifold_oriented())
      << "front edges that are not shared by two oppositely wound triangles";
}

TEST(FanLayout, BoxEdgesGetTwoFaceColumnsAndCornersThreeWithExactNormals) {
  const int n = 3;
  const TriSurface box = test_surfaces::box({0, 0, 0}, {1, 1, 1}, n);
  const ColumnLayout l = layout_of(box);
  EXPECT_EQ(l.n_fan_points, 12 * (n - 1) + 8);
  EXPECT_EQ(l.n_ridge_edges, 12 * n);
  EXPECT_EQ(l.n_corners, 8);
  EXPECT_EQ(l.n_ridge_ends, 0);
  // 90 degrees between the faces, at most 30 per slice: 3 slices, 2 sub-normals.
  const auto by_point = columns_by_point(l);
  int n_edge = 0, n_corner = 0;
  for (const auto& [w, cols] : by_point) {
    int faces = 0;
    for (int c : cols) faces += !l.faceless[c];
    if (cols.size() == 1) continue;
    if (faces == 2) {
      ++n_edge;
      EXPECT_EQ(cols.size(), 4u);
    } else {
      ++n_corner;
      EXPECT_EQ(faces, 3);
      EXPECT_EQ(cols.size(), 10u);  // 3 sectors, 3 x 2 sub-normals, a centre
    }
  }
  EXPECT_EQ(n_edge, 12 * (n - 1));
  EXPECT_EQ(n_corner, 8);
  EXPECT_EQ(l.elements.size(), box.triangles.size() + 12 * n * 3 + 8 * 9);
  // Every face column leaves along its face's normal; every sub-normal lies in the plane
  // of the two normals, 30 or 60 degrees from one of them; a corner's centre is the
  // diagonal.
  for (std::size_t t = 0; t < l.front.triangles.size(); ++t) {
    if (l.wall_face[t] < 0) continue;
    const Vec3 fn = unit_normal(box, l.wall_face[t]);
    for (int c : l.front.triangles[t])
      if (l.in_fan[c]) {
        EXPECT_LE(angle_between(l.direction[c], fn), kAngleTol);
      }
  }
  for (int c = 0; c < l.n_columns(); ++c) {
    if (!l.faceless[c]) continue;
    const Vec3& d = l.direction[c];
    int zeros = 0;
    for (int i = 0; i < 3; ++i) zeros += std::fabs(d[i]) < 1e-15;
    if (zeros == 0) {  // corner centre
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(std::fabs(d[i]), 1.0 / std::sqrt(3.0), 1e-15);
      continue;
    }
    ASSERT_EQ(zeros, 1) << "a sub-normal leaves the plane of its two face normals";
    double largest = 0.0;
    for (int i = 0; i < 3; ++i) largest = std::max(largest, std::fabs(d[i]));
    const double off = degrees(std::acos(std::min(1.0, largest)));
    EXPECT_NEAR(off, 30.0, 1e-9);
  }
  expect_closed_and_oriented(l.front);
}

TEST(FanLayout, SharpTrailingEdgeGetsSubNormalsAtMostMaxSectorApart) {
  const double apex = 15.0;
  const TriSurface w = wedge_prism(apex, 4.0, 2.0, 4);
  const ColumnLayout l = layout_of(w);
  // The apex edge turns by 165 degrees: ceil(165 / 30) = 6 slices of 27.5 degrees.
  const auto by_point = columns_by_point(l);
  int n_apex = 0;
  for (const auto& [p, cols] : by_point) {
    const Vec3& x = w.points[p];
    if (!(x[0] == 0.0 && x[1] > 0.0 && x[1] < 2.0)) continue;
    ++n_apex;
    ASSERT_EQ(cols.size(), 7u);  // 2 face columns, 5 sub-normals
    // Fan order: consecutive columns along the fan list are 27.5 degrees apart; check
    // through the strips, whose q0 q1 are neighbours in a fan.
  }
  EXPECT_EQ(n_apex, 3);
  int n_checked = 0;
  for (const LayerElement& e : l.elements) {
    if (e.kind != ElementKind::kStrip) continue;
    const double a = degrees(angle_between(l.direction[e.column[0]], l.direction[e.column[1]]));
    const Vec3& x = w.points[l.wall_point[e.column[0]]];
    if (x[0] == 0.0 && w.points[l.wall_point[e.column[2]]][0] == 0.0) {
      EXPECT_NEAR(a, (180.0 - apex) / 6.0, 1e-9);
      ++n_checked;
    }
    EXPECT_LE(a, 30.0 + 1e-9);
  }
  EXPECT_EQ(n_checked, 4 * 6);
  expect_closed_and_oriented(l.front);
}

TEST(FanLayout, EachRidgeChainGetsTheSlicesItsOwnTurnNeeds) {
  // The wedge prism's ridges: the apex edge turns by 165 degrees (6 slices of at most
  // 30), the two back edges by 97.5 (4) and the end caps' rims by 90 (3). The apex and
  // back lines are chains of 4 edges between corners; each rim edge runs between two
  // corners. Corners separate chains, so no rim or back edge takes the apex's 6, and
  // no rim the back edges' 4.
  const TriSurface w = wedge_prism(15.0, 4.0, 2.0, 4);
  const ColumnLayout l = layout_of(w);
  std::map<std::pair<int, int>, int> slices;  // per ridge edge (wall points)
  for (const LayerElement& e : l.elements) {
    if (e.kind != ElementKind::kStrip) continue;
    const int a = l.wall_point[e.column[0]], b = l.wall_point[e.column[3]];
    ++slices[{std::min(a, b), std::max(a, b)}];
  }
  const EdgeTopology edges = build_edge_topology(w);
  int n_ridges = 0, n_three = 0, n_four = 0;
  for (const SurfaceEdge& e : edges.edges) {
    const double turn = degrees(angle_between(unit_normal(w, e.triangle[0]), unit_normal(w, e.triangle[1])));
    if (turn <= 60.0) continue;
    ++n_ridges;
    const int expected = static_cast<int>(std::ceil(turn / 30.0 - kFanAngleSlack));
    n_three += expected == 3;
    n_four += expected == 4;
    EXPECT_EQ(slices[std::make_pair(e.lo, e.hi)], expected) << "edge " << e.lo << "-" << e.hi << " turning " << turn;
  }
  EXPECT_EQ(n_ridges, 3 * 4 + 2 * 3);
  EXPECT_EQ(n_three, 2 * 3);
  EXPECT_EQ(n_four, 2 * 4);
  EXPECT_EQ(static_cast<int>(slices.size()), n_ridges);
  expect_closed_and_oriented(l.front);
}

// A surface's points turned to a generic attitude, moved away from the origin and
// rounded to float, as an STL file stores them: face normals move by ~1e-6 rad.
void turn_and_round_to_float(TriSurface* s) {
  const double a = 0.3, b = 0.7, c = 1.1;
  for (Vec3& p : s->points) {
    Vec3 q{p[0], std::cos(a) * p[1] - std::sin(a) * p[2], std::sin(a) * p[1] + std::cos(a) * p[2]};
    q = Vec3{std::cos(b) * q[0] + std::sin(b) * q[2], q[1], -std::sin(b) * q[0] + std::cos(b) * q[2]};
    q = Vec3{std::cos(c) * q[0] - std::sin(c) * q[1], std::sin(c) * q[0] + std::cos(c) * q[1], q[2]};
    for (int i = 0; i < 3; ++i) p[i] = static_cast<double>(static_cast<float>(q[i] + 10.0 * (i + 1)));
  }
}

// How many of the surface's edges that turn by `angle` degrees to within 1e-3 turn past
// it by more than 1e-12 of it.
int edges_past(const TriSurface& s, double angle) {
  int past = 0;
  for (const SurfaceEdge& e : build_edge_topology(s).edges) {
    const double turn = degrees(angle_between(unit_normal(s, e.triangle[0]), unit_normal(s, e.triangle[1])));
    if (std::fabs(turn - angle) <= 1e-3) past += turn > angle * (1.0 + 1e-12);
  }
  return past;
}

// Columns per point on the edges (two face columns) of a layout, in increasing order of
// the point's column count: {columns, points}.
std::map<std::size_t, int> edge_point_column_counts(const ColumnLayout& l) {
  std::map<std::size_t, int> counts;
  for (const auto& [w, cols] : columns_by_point(l)) {
    int faces = 0;
    for (int c : cols) faces += !l.faceless[c];
    if (faces == 2) ++counts[cols.size()];
  }
  return counts;
}

TEST(FanLayout, NinetyDegreeEdgesReadInSinglePrecisionKeepThreeSlices) {
  const int n = 3;
  TriSurface box = test_surfaces::box({0, 0, 0}, {1, 1, 1}, n);
  turn_and_round_to_float(&box);
  ASSERT_GT(edges_past(box, 90.0), 0) << "the rounding moved no edge past 90 degrees: the case tests nothing";
  const ColumnLayout l = layout_of(box);
  EXPECT_EQ(l.n_fan_points, 12 * (n - 1) + 8);
  // 2 face columns and 2 sub-normals at every edge point, as on the exact box.
  const std::map<std::size_t, int> expected{{4u, 12 * (n - 1)}};
  EXPECT_EQ(edge_point_column_counts(l), expected);
  expect_closed_and_oriented(l.front);
}

TEST(FanLayout, SixtyDegreeEdgesReadInSinglePrecisionAreNoRidgesAtTheSixtyDegreeFanAngle) {
  // A hexagonal prism, caps fanned from their centres: its side edges turn by exactly
  // 60 degrees, its rim edges by 90.
  TriSurface hex = test_surfaces::capped_cylinder(6, 1, 1.0, 1.0);
  turn_and_round_to_float(&hex);
  ASSERT_GT(edges_past(hex, 60.0), 0) << "the rounding moved no side edge past 60 degrees: the case tests nothing";
  const ColumnLayout l = layout_of(hex);
  // The two rims' 12 edges only, 3 slices each: every ring point has its two face
  // columns and 2 sub-normals.
  EXPECT_EQ(l.n_ridge_edges, 12);
  EXPECT_EQ(l.n_corners, 0);
  const std::map<std::size_t, int> expected{{4u, 12}};
  EXPECT_EQ(edge_point_column_counts(l), expected);
  expect_closed_and_oriented(l.front);
  // A fan angle 0.01 degrees lower (1.7e-4 of it, past the slack) takes the side edges
  // too: every ring point is then a corner of three ridges.
  const ColumnLayout lower = layout_of(hex, 59.99);
  EXPECT_EQ(lower.n_ridge_edges, 18);
  EXPECT_EQ(lower.n_corners, 12);
}

TEST(FanLayout, ATurnPastAMultipleOfTheSectorByMoreThanTheSlackTakesAnotherSlice) {
  // The apex edge of a wedge with a 89.9-degree apex turns by 90.1 degrees, past three
  // 30-degree sectors by 1/300 of one (the slack is 1/10,000): 4 slices, 3 sub-normals.
  const TriSurface w = wedge_prism(89.9, 4.0, 2.0, 4);
  const ColumnLayout l = layout_of(w);
  int n_apex = 0;
  for (const auto& [p, cols] : columns_by_point(l)) {
    const Vec3& x = w.points[p];
    if (!(x[0] == 0.0 && x[1] > 0.0 && x[1] < 2.0)) continue;
    ++n_apex;
    EXPECT_EQ(cols.size(), 5u);
  }
  EXPECT_EQ(n_apex, 3);
}

TEST(FanLayout, MixedCornerSplitsIntoTheFlatTopAndTheConcaveSides) {
  const TriSurface s = l_block();
  const ColumnLayout l = layout_of(s);
  expect_closed_and_oriented(l.front);
  const auto by_point = columns_by_point(l);
  // The ends of the concave edge, (1, 1, 0) and (1, 1, 1).
  int n_mixed = 0;
  for (const auto& [p, cols] : by_point) {
    const Vec3& x = s.points[p];
    if (!(x[0] == 1.0 && x[1] == 1.0)) continue;
    ++n_mixed;
    ASSERT_EQ(cols.size(), 4u);  // two sectors (90 degrees apart) and 2 sub-normals
    std::vector<Vec3> sector;
    for (int c : cols)
      if (!l.faceless[c]) sector.push_back(l.direction[c]);
    ASSERT_EQ(sector.size(), 2u);
    // One sector is the flat top (or bottom); the other the two concave side faces,
    // whose most normal direction is their bisector, horizontal.
    const Vec3& flat = std::fabs(sector[0][2]) > 0.5 ? sector[0] : sector[1];
    const Vec3& sides = std::fabs(sector[0][2]) > 0.5 ? sector[1] : sector[0];
    EXPECT_NEAR(std::fabs(flat[2]), 1.0, kAngleTol);
    EXPECT_NEAR(sides[2], 0.0, kAngleTol);
    EXPECT_NEAR(std::fabs(sides[0]), std::sqrt(0.5), kAngleTol);
    EXPECT_NEAR(std::fabs(sides[1]), std::sqrt(0.5), kAngleTol);
  }
  EXPECT_EQ(n_mixed, 2);
  // Points inside the concave edge have none (it is no ridge); there are none here
  // with one voxel of height, so check the ridge count: the L has 6 + 6 rim edges on
  // top and bottom (in unit segments 8 + 8) and 5 convex vertical edges; the inner
  // vertical edge is concave.
  EXPECT_EQ(l.n_ridge_edges, 8 + 8 + 5);
}

TEST(FanLayout, NoFansBelowTheAngleOrWhenDisabled) {
  const TriSurface box = test_surfaces::box({0, 0, 0}, {1, 1, 1}, 2);
  for (double angle : {0.0, 90.0}) {
    const ColumnLayout l = layout_of(box, angle);
    EXPECT_EQ(l.n_fan_points, 0) << angle;
    EXPECT_EQ(l.n_columns(), static_cast<int>(box.points.size()));
    EXPECT_EQ(l.front.triangles, box.triangles);
  }
}

TEST(FanLayout, RidgesEndingAtSingleColumnsGetEndTrianglesAndSplitNeighbours) {
  // With fan angle 120 only the 165-degree apex edge is a ridge: its two end points lie
  // on one ridge edge each and keep single columns. 40 degrees per slice: ceil(165 / 40)
  // = 5 slices.
  const TriSurface w = wedge_prism(15.0, 4.0, 2.0, 4);
  const ColumnLayout l = layout_of(w, 120.0, 40.0);
  EXPECT_EQ(l.n_ridge_edges, 4);
  EXPECT_EQ(l.n_ridge_ends, 2);
  EXPECT_EQ(l.n_fan_points, 3);
  EXPECT_EQ(l.n_corners, 0);
  int strips = 0, ends = 0;
  for (const LayerElement& e : l.elements) {
    strips += e.kind == ElementKind::kStrip;
    ends += e.kind == ElementKind::kStripEnd;
  }
  EXPECT_EQ(strips, 2 * 5);
  EXPECT_EQ(ends, 2 * 5);
  // The wall triangles at the two end points split there on the wall layer: at each,
  // the cap and three side triangles.
  int split = 0;
  for (const LayerElement& e : l.elements) split += e.split_at >= 0;
  EXPECT_EQ(split, 2 * 4);
  expect_closed_and_oriented(l.front);
}

// ---------------------------------------------------------------------------------------
// Extrusions with fans.

ExtrusionParams fan_params(int n, double h1, double r) {
  ExtrusionParams p = test::growth_params(n, h1, r);
  p.fan_angle_deg = 60.0;
  return p;
}

double distance_to_surface(const TriSurface& s, const Vec3& q) {
  double best = HUGE_VAL;
  for (const Triangle& t : s.triangles) {
    // Closest point by projection onto the plane when inside, else to the edges.
    const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    const Vec3 nrm = normalized(cross(b - a, c - a));
    const Vec3 p = q - dot(q - a, nrm) * nrm;
    auto inside = [&](const Vec3& x, const Vec3& y) { return dot(cross(y - x, p - x), nrm) >= 0.0; };
    double d;
    if (inside(a, b) && inside(b, c) && inside(c, a)) {
      d = std::fabs(dot(q - a, nrm));
    } else {
      d = HUGE_VAL;
      for (auto [x, y] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        const double u = std::clamp(dot(q - x, y - x) / norm2(y - x), 0.0, 1.0);
        d = std::min(d, norm(q - (x + u * (y - x))));
      }
    }
    best = std::min(best, d);
  }
  return best;
}

// Every cell valid, every face used by at most two cells, and the faces used once are
// the wall's triangles and the envelope's faces: its triangles on wall faces and
// patches, and one quad per grown strip.
// open_side: for an open wall, whether a free face of the mesh lies over its boundary
// (the layers' side faces there), given the face's points.
void expect_conforming_valid_layers(const TriSurface& wall, const ExtrusionResult& r,
                                    const std::function<bool(const std::vector<Vec3>&)>& open_side = {}) {
  const VolumeMesh& m = r.mesh;
  std::int64_t n_bad = 0;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const std::vector<Vec3> p = test::cell_corners(m, c);
    if (cell_validity(m.cell_types[c], p.data()) != Validity::kValid) ++n_bad;
  }
  EXPECT_EQ(n_bad, 0) << "cells failing the exact validity test";
  std::set<std::vector<std::int64_t>> free;
  for (const auto& [f, n] : test::face_use(m)) {
    EXPECT_LE(n, 2);
    if (n == 1) free.insert(f);
  }
  // Front triangle i is wall triangle wall_face[i] (or a strip half or patch) on the
  // column tops; where no column of it grew there is no cell on it.
  const std::int64_t nv = static_cast<std::int64_t>(wall.points.size());
  std::set<std::vector<std::int64_t>> expected;
  for (std::size_t i = 0; i < r.envelope.triangles.size(); ++i) {
    std::vector<std::int64_t> f;
    bool grown = false;
    for (int c : r.envelope.triangles[i]) {
      f.push_back(r.envelope_point_ids[c]);
      grown = grown || f.back() >= nv;
    }
    if (!grown) continue;
    std::sort(f.begin(), f.end());
    f.erase(std::unique(f.begin(), f.end()), f.end());
    if (f.size() == 3) expected.insert(f);
    const int wf = r.front_wall_face[i];
    if (wf < 0) continue;
    std::vector<std::int64_t> w(wall.triangles[wf].begin(), wall.triangles[wf].end());
    std::sort(w.begin(), w.end());
    expected.insert(w);
  }
  // Strip tops are quads: their two halves are not faces, the quad is.
  std::set<std::vector<std::int64_t>> expected_with_quads;
  for (const auto& f : expected) expected_with_quads.insert(f);
  std::set<std::vector<std::int64_t>> quads;
  for (const auto& f : free)
    if (f.size() == 4) quads.insert(f);
  for (const auto& q : quads)
    for (int skip = 0; skip < 4; ++skip) {
      std::vector<std::int64_t> tri;
      for (int i = 0; i < 4; ++i)
        if (i != skip) tri.push_back(q[i]);
      expected_with_quads.erase(tri);
    }
  for (const auto& q : quads) expected_with_quads.insert(q);
  if (open_side) {
    for (auto it = free.begin(); it != free.end();) {
      std::vector<Vec3> pts;
      for (std::int64_t i : *it) pts.push_back(m.points[i]);
      it = !expected_with_quads.count(*it) && open_side(pts) ? free.erase(it) : std::next(it);
    }
  }
  EXPECT_EQ(free, expected_with_quads);
}

TEST(FanExtrusion, BoxLayersAreValidConformingAndExactlyWallNormalAtTheEdges) {
  const int n = 3, layers = 4;
  const double h1 = 0.01;
  const TriSurface box = test_surfaces::box({0, 0, 0}, {1, 1, 1}, n);
  const ExtrusionResult r = extrude_layers(box, fan_params(layers, h1, 1.2));
  expect_conforming_valid_layers(box, r);
  EXPECT_EQ(r.report.fans.points, 12 * (n - 1) + 8);
  EXPECT_EQ(r.report.fans.fallback_points, 0);
  EXPECT_DOUBLE_EQ(r.report.area_coverage, 1.0);
  // Cells: per layer a wedge per wall triangle; 3 x 12 n strips: fan wedges on the
  // wall, hexes above; 8 x 9 patch triangles: tets on the wall, wedges above.
  const std::int64_t nf = static_cast<std::int64_t>(box.triangles.size()), strips = 3 * 12 * n, patches = 8 * 9;
  EXPECT_EQ(r.report.n_wedges, layers * nf + strips + (layers - 1) * patches);
  EXPECT_EQ(r.report.n_hexes, (layers - 1) * strips);
  EXPECT_EQ(r.report.n_tets, patches);
  EXPECT_EQ(r.report.fans.cells, layers * (strips + patches));
  // First points: column c's first point is mesh point #wall + c (all grew). The
  // distance to the box is h1 for every column, and a face column leaves along its
  // face's normal.
  const std::size_t nv = box.points.size();
  // The mesh-only measure follows each face column of a fan (not the sub-normals,
  // which leave the wall through no column edge): every column exact in both measures.
  const double total = h1 * (std::pow(1.2, layers) - 1.0) / 0.2;
  const LayerFidelity f = measure_layer_fidelity(r.mesh, box, {h1, total, layers});
  int face_columns = 0;
  const ColumnLayout l = layout_of(box);
  for (int c = 0; c < l.n_columns(); ++c) face_columns += !l.faceless[c];
  EXPECT_EQ(f.n_columns, face_columns);
  EXPECT_EQ(f.n_fan_points, 12 * (n - 1) + 8);
  EXPECT_EQ(f.n_branching, 0);
  EXPECT_DOUBLE_EQ(f.first_within_1pct_planes, 1.0);
  EXPECT_DOUBLE_EQ(f.first_within_1pct_distance, 1.0);
  EXPECT_DOUBLE_EQ(f.complete_share, 1.0);
  EXPECT_DOUBLE_EQ(f.area_coverage, 1.0);
  for (std::size_t c = 0; c < r.column_layers.size(); ++c) {
    ASSERT_EQ(r.column_layers[c], layers);
    const Vec3& q = r.mesh.points[nv + c];
    Vec3 nearest;
    for (int i = 0; i < 3; ++i) nearest[i] = std::clamp(q[i], 0.0, 1.0);
    EXPECT_NEAR(norm(q - nearest), h1, 1e-12) << "column " << c;
  }
}

// The exact column directions of a fanned box: the fan points' own, and the face
// normal for the columns of a face's interior.
std::vector<Vec3> exact_directions(const TriSurface& box, const ColumnLayout& l) {
  std::vector<Vec3> dir(l.direction.begin(), l.direction.end());
  for (std::size_t f = 0; f < box.triangles.size(); ++f)
    for (int c : l.front.triangles[f])
      if (!l.in_fan[c]) dir[c] = unit_normal(box, static_cast<int>(f));
  return dir;
}

// The solver-acceptance limits judge the wall triangles' cells of a fanned front: on a
// box, one layer along the exact face and fan directions passes a tight boundary
// skewness limit (right prisms: 0); shearing the top face's own columns keeps every
// cell valid but fails the sheared cells: only columns on the top face are blamed.
TEST(FanExtrusion, SolverLimitsJudgeTheWallTrianglesCellsOfAFannedFront) {
  const TriSurface box = test_surfaces::box({0, 0, 0}, {1, 1, 1}, 3);
  const ColumnLayout l = layout_of(box);
  ASSERT_TRUE(l.has_fans());
  const int nc = l.n_columns();
  const std::vector<Vec3> dir = exact_directions(box, l);
  const double h = 0.01;
  auto layer = [&](double shear) {
    std::vector<Vec3> next(nc);
    for (int c = 0; c < nc; ++c) {
      next[c] = l.front.points[c] + h * dir[c];
      if (!l.in_fan[c] && l.front.points[c][2] == 1.0) next[c] += Vec3{shear, 0, 0};
    }
    return next;
  };
  ExtrusionParams p;
  p.check_collisions = false;
  p.solver_limits = AcceptanceLimits{};
  p.solver_limits.max_boundary_skewness = 0.05;
  const WallTopology topo = build_column_topology(l);
  const std::vector<int> layers(nc, 0);
  const std::vector<char> grows(nc, 1);
  auto run = [&](bool limited, double shear) {
    FrontChecker checker = limited ? FrontChecker(box, l, topo, p) : FrontChecker(box, l, topo, false);
    checker.begin_layer(0, l.front.points, layers);
    FrontVerdict v;
    checker.check(0, l.front.points, layer(shear), grows, &v);
    return v;
  };
  EXPECT_FALSE(run(true, 0.0).any_bad) << "right prisms and exact fan cells";
  EXPECT_FALSE(run(false, 0.05).any_bad) << "the sheared layer is valid";
  const FrontVerdict v = run(true, 0.05);
  ASSERT_TRUE(v.any_bad);
  int n_bad = 0;
  for (int c = 0; c < nc; ++c) {
    if (!v.bad[c]) continue;
    ++n_bad;
    EXPECT_EQ(v.reason[c], StopReason::kQuality);
    EXPECT_EQ(l.front.points[c][2], 1.0) << "column " << c << " is not on the sheared face";
  }
  EXPECT_GT(n_bad, 0);
}

// A repair attempt re-tests only what changed since the attempt before: the triangles
// and elements on the columns that moved or changed growing state, their neighbours'
// shared faces, the triangles that crossed before. In the second layer of a fanned box
// with a symmetry plane just below it, strict solver limits, columns jittered, pushed
// through the box and off the plane's side and put back, and a triangle's columns
// stopped and restarted, every attempt must end with the verdicts of a fresh check.
TEST(FanExtrusion, RepairAttemptsEndWithTheVerdictsOfAFreshCheck) {
  const TriSurface box = test_surfaces::box({0, 0, 0}, {1, 1, 1}, 4);
  const ColumnLayout l = layout_of(box);
  ASSERT_TRUE(l.has_fans());
  const int nc = l.n_columns();
  const std::vector<Vec3> dir = exact_directions(box, l);
  const double h = 0.01;
  std::vector<Vec3> top(nc), next(nc);
  for (int c = 0; c < nc; ++c) {
    top[c] = l.front.points[c] + h * dir[c];
    next[c] = top[c] + h * dir[c];
  }
  SymmetryPlane plane;  // z = -0.035, the model above: the bottom's new points at -0.02 pass
  plane.axis = 2;
  plane.offset = -0.035;
  const WallTopology topo = build_column_topology(l, plane);
  ExtrusionParams p;
  p.check_collisions = true;
  p.solver_limits = AcceptanceLimits{5.0, 0.1, 0.3, 10.0, true, true};
  const std::vector<int> layers(nc, 1);
  std::vector<char> grows(nc, 1);
  FrontChecker incremental(box, l, topo, p);
  incremental.begin_layer(1, top, layers);
  testing::Lcg rng(5);
  auto column = [&] { return std::min(nc - 1, static_cast<int>(rng.uniform() * nc)); };
  int below = 0;  // a column of the bottom face's interior
  while (l.in_fan[below] || l.front.points[below][2] != 0.0) ++below;
  std::vector<int> pushed;
  Triangle stopped{};  // the columns of a wall triangle's cell, stopped and restarted
  int attempts_with_collisions = 0, attempts_with_quality = 0;
  for (int attempt = 0; attempt < 16; ++attempt) {
    if (attempt > 0) {
      for (int m = 0; m < 8; ++m) {
        const int c = column();
        const Vec3 jitter{0.6 * (rng.uniform() - 0.5), 0.6 * (rng.uniform() - 0.5), 0.6 * (rng.uniform() - 0.5)};
        next[c] = top[c] + h * ((0.5 + 3.0 * rng.uniform()) * dir[c] + jitter);
      }
      if (!pushed.empty() && attempt % 2 == 0) {  // put the last pushed column back
        next[pushed.back()] = top[pushed.back()] + h * dir[pushed.back()];
        pushed.pop_back();
      } else {  // through the box, out past the opposite face
        pushed.push_back(column());
        next[pushed.back()] = top[pushed.back()] - 1.3 * dir[pushed.back()];
      }
      if (attempt == 2) next[below] = top[below] + 4.0 * h * dir[below];  // to z = -0.05
      if (attempt == 5) next[below] = top[below] + h * dir[below];
      if (attempt == 3)  // a stopped column's new point is its top (settle_layer)
        for (int c : stopped = l.front.triangles[column() % box.triangles.size()]) {
          grows[c] = 0;
          next[c] = top[c];
        }
      if (attempt == 7)
        for (int c : stopped) {
          grows[c] = 1;
          next[c] = top[c] + h * dir[c];
        }
    }
    FrontVerdict inc, fresh;
    incremental.check(attempt, top, next, grows, &inc);
    FrontChecker full(box, l, topo, p);
    full.begin_layer(1, top, layers);
    full.check(0, top, next, grows, &fresh);
    EXPECT_EQ(inc.bad, fresh.bad) << "attempt " << attempt;
    EXPECT_EQ(inc.reason, fresh.reason) << "attempt " << attempt;
    EXPECT_EQ(inc.bad_triangle, fresh.bad_triangle) << "attempt " << attempt;
    attempts_with_collisions +=
        std::count(fresh.reason.begin(), fresh.reason.end(), StopReason::kCollision) > 0;
    attempts_with_quality += std::count(fresh.reason.begin(), fresh.reason.end(), StopReason::kQuality) > 0;
  }
  EXPECT_GE(attempts_with_collisions, 5) << "the pushed columns must cross other triangles";
  EXPECT_GE(attempts_with_quality, 5) << "the limits must refuse some cells";
}

TEST(FanExtrusion, ThinSpanTrianglesOfACadWingSegmentKeepEveryFanAndLayer) {
  // Every point of the segment is on a 90 degree root or tip edge, and its side
  // triangles span the span (3.6e4 times as long as wide at the trailing edge), so the
  // faces between their cells are within 0.003 degree of 90 whatever the columns do.
  // With the default solver limits those faces are held to twice the wall's own lean,
  // and every fan keeps all its layers at exactly h1 from the wall.
  const TriSurface wing = test_surfaces::sliver_wing_segment(300);
  const double h1 = 2.84e-4;
  ExtrusionParams p;
  p.growth.layers = 10;
  p.growth.first_height = h1;
  p.growth.growth_ratio = 1.2;
  const ExtrusionResult r = extrude_layers(wing, p);
  EXPECT_EQ(r.report.fans.points, static_cast<int>(wing.points.size()));
  EXPECT_EQ(r.report.fans.fallback_points, 0);
  int short_columns = 0;
  for (int layers : r.column_layers) short_columns += layers != 10;
  EXPECT_EQ(short_columns, 0);
  expect_conforming_valid_layers(wing, r);
  // Measured on the mesh alone (quality/layer_fidelity.h): every face column's first
  // point within 1 % of h1 from the wall surface, and every column at full thickness.
  const double total = h1 * (std::pow(1.2, 10) - 1.0) / 0.2;
  const LayerFidelity f = measure_layer_fidelity(r.mesh, wing, {h1, total, 10});
  EXPECT_DOUBLE_EQ(f.first_within_1pct_distance, 1.0);
  EXPECT_DOUBLE_EQ(f.complete_share, 1.0);
  EXPECT_DOUBLE_EQ(f.area_coverage, 1.0);
}

// A box facing another across a gap that ends the layers of the facing face's columns
// (terminate policy): at the points on that face's edges one sector column faces the
// gap and the others do not, yet the plan gives every column of a fan point the same
// layers, those of its shortest (the straight-layer precheck and the strips need them).
TEST(FanExtrusion, PlanGivesEveryColumnOfAFanPointTheLayersOfItsShortest) {
  const double gap = 0.05;
  const TriSurface wall =
      test_surfaces::merged(test_surfaces::box({0, 0, 0}, {1, 1, 1}, 3), test_surfaces::box({1 + gap, 0, 0}, {2 + gap, 1, 1}, 3));
  const ColumnLayout l = layout_of(wall);
  ASSERT_TRUE(l.has_fans());
  const WallTopology wall_topo = build_wall_topology(wall);
  const WallTopology topo = build_column_topology(l);
  ExtrusionParams p = fan_params(5, 0.01, 1.5);  // T = 0.13 > 0.45 x gap
  p.limit_policy = LimitPolicy::kTerminate;
  p.height_smoothing_rings = 0;
  const WallPlanes planes(wall, l, topo);
  PrescribedDirections fan{l.direction, std::vector<double>(l.n_columns(), 0.0)};
  for (int c = 0; c < l.n_columns(); ++c)
    if (l.in_fan[c]) fan.visibility[c] = planes.visibility(c, fan.n[c]);
  const StepDirections d = compute_step_directions(l.front, topo, topo.used, p, &fan);
  FrontChecker checker(wall, l, topo, false);
  const ColumnPlan plan =
      plan_column_heights(wall, wall_topo, topo, resolve_growth_law(p.growth), p, d, checker.wall_rays());
  int limited_groups = 0;
  for (int i = 0; i < topo.group_columns.n_rows(); ++i) {
    const int first = *topo.group_columns.begin(i);
    bool limited = false, facing_away = false;
    for (const int* c = topo.group_columns.begin(i); c != topo.group_columns.end(i); ++c) {
      EXPECT_EQ(plan.planned_layers[*c], plan.planned_layers[first]) << "group " << i;
      limited = limited || plan.planned_layers[*c] < 5;
      facing_away = facing_away || std::fabs(d.n[*c][0]) < 0.5;
    }
    limited_groups += limited && facing_away;
  }
  EXPECT_GT(limited_groups, 0) << "no fan point has a column facing the gap and one facing away";
}

TEST(FanExtrusion, TrailingEdgeFaceColumnsLeaveAlongTheirFaceNormals) {
  const TriSurface w = wedge_prism(15.0, 4.0, 2.0, 4);
  const double h1 = 0.002;
  const ExtrusionResult r = extrude_layers(w, fan_params(5, h1, 1.2));
  expect_conforming_valid_layers(w, r);
  const ColumnLayout l = layout_of(w);
  ASSERT_EQ(static_cast<int>(r.column_layers.size()), l.n_columns());
  const std::size_t nv = w.points.size();
  for (std::size_t t = 0; t < l.front.triangles.size(); ++t) {
    if (l.wall_face[t] < 0) continue;
    const Vec3 fn = unit_normal(w, l.wall_face[t]);
    for (int c : l.front.triangles[t]) {
      ASSERT_GT(r.column_layers[c], 0);
      const Vec3 seg = r.mesh.points[nv + c] - w.points[l.wall_point[c]];
      if (l.in_fan[c]) {
        EXPECT_LE(degrees(angle_between(seg, fn)), 1e-9);
      }
      EXPECT_NEAR(distance_to_surface(w, r.mesh.points[nv + c]), h1, 1e-12);
    }
  }
}

TEST(FanExtrusion, LBlockMixedCornersAreValidAndConforming) {
  const TriSurface s = l_block();
  const ExtrusionResult r = extrude_layers(s, fan_params(4, 0.02, 1.2));
  expect_conforming_valid_layers(s, r);
  EXPECT_GT(r.report.fans.points, 0);
  EXPECT_EQ(r.report.fans.failed_points, 0);
}

// Layers almost as thick as the block (T = 0.81, the L's arms 1 wide): the columns of the
// faces at the concave edge, which leave along their faces' normals, meet in the top
// layer. Those cells stop their columns there, fans included; the fans keep their points
// (falling them back would give the convex edges' first cells a leaning column) and
// every column grows its first layer.
TEST(FanExtrusion, FansWhoseUpperLayersFoldKeepTheirPointsAndStopThere) {
  const TriSurface s = l_block();
  const ExtrusionResult r = extrude_layers(s, fan_params(6, 0.08, 1.3));
  expect_conforming_valid_layers(s, r);
  const ColumnLayout l = layout_of(s);
  EXPECT_EQ(r.report.fans.points, l.n_fan_points);
  EXPECT_EQ(r.report.fans.fallback_points, 0);
  ASSERT_EQ(r.report.columns_per_layer.size(), 6u);
  EXPECT_EQ(r.report.columns_per_layer.front(), l.n_columns());
  EXPECT_LT(r.report.columns_per_layer.back(), l.n_columns()) << "no upper layer folded: the case tests nothing";
}

TEST(FanExtrusion, RidgeEndsCloseWithSplitCellsThatConform) {
  const TriSurface w = wedge_prism(15.0, 4.0, 2.0, 4);
  ExtrusionParams p = fan_params(4, 0.002, 1.2);
  p.fan_angle_deg = 120.0;
  p.fan_max_sector_deg = 40.0;
  const ExtrusionResult r = extrude_layers(w, p);
  expect_conforming_valid_layers(w, r);
  EXPECT_EQ(r.report.fans.ridge_ends, 2);
  // 12 single columns and 3 fans of 2 + 4: all grow the wall layer. There, each end's
  // 5 slices are 2 tets each, and each end's 4 wall triangles a pyramid and a tet.
  ASSERT_FALSE(r.report.columns_per_layer.empty());
  EXPECT_EQ(r.report.columns_per_layer[0], 12 + 3 * 6);
  const DataArray* layer = r.mesh.find_cell_array("layer");
  ASSERT_NE(layer, nullptr);
  std::map<CellType, int> wall_layer;
  for (std::size_t c = 0; c < r.mesh.n_cells(); ++c)
    if (layer->values[c] == 0) ++wall_layer[r.mesh.cell_types[c]];
  EXPECT_EQ(wall_layer[CellType::kTet], 2 * 5 * 2 + 2 * 4);
  EXPECT_EQ(wall_layer[CellType::kPyramid], 2 * 4);
  EXPECT_EQ(wall_layer[CellType::kWedge], 26 - 2 * 4 + 2 * 5);  // other triangles, fan wedges
  EXPECT_EQ(wall_layer[CellType::kHex], 0);
}

// Split cells at ridge ends are two cells of nine nodes per layer: the room reserved for
// layers in which every column grows holds them, so the mesh's arrays never reallocate.
TEST(FanAssembly, ReservedLayersHoldTheSplitCellsOfRidgeEnds) {
  const TriSurface w = wedge_prism(15.0, 4.0, 2.0, 4);
  const ColumnLayout l = layout_of(w, 120.0, 40.0);
  int n_split = 0;
  for (const LayerElement& e : l.elements) n_split += e.kind == ElementKind::kStripEnd || e.split_at >= 0;
  ASSERT_GT(n_split, 0);
  const int nc = l.n_columns();
  const StepDirections d{{}, l.direction, std::vector<double>(nc, 1.0), std::vector<char>(nc, 1)};
  const WallTopology topo = build_column_topology(l);
  ColumnState columns = ColumnState::on_wall(l.front.points, topo.used, l.wall_point);
  const int layers = 3;
  LayerAssembler reserved_only(w, l, d);
  reserved_only.reserve_layers(layers);
  const VolumeMesh reserved = reserved_only.take_mesh();
  LayerAssembler a(w, l, d);
  a.reserve_layers(layers);
  for (int k = 0; k < layers; ++k) {
    std::vector<Vec3> next(nc);
    for (int c = 0; c < nc; ++c) next[c] = columns.top[c] + 0.01 * d.n[c];
    a.commit_layer(k, std::vector<char>(nc, 1), next, d, &columns);
  }
  const VolumeMesh m = a.take_mesh();
  ASSERT_GT(m.n_cells(), static_cast<std::size_t>(layers) * l.elements.size()) << "no element split in two";
  EXPECT_EQ(m.connectivity.capacity(), reserved.connectivity.capacity());
  EXPECT_EQ(m.offsets.capacity(), reserved.offsets.capacity());
  EXPECT_EQ(m.cell_types.capacity(), reserved.cell_types.capacity());
}

// A layout lives through the whole march: its arrays hold no idle capacity from
// growing by doubling.
TEST(FanLayout, BuiltLayoutsArraysHoldNoIdleCapacity) {
  const ColumnLayout l = layout_of(wedge_prism(15.0, 4.0, 2.0, 4), 120.0, 40.0);
  ASSERT_TRUE(l.has_fans());
  EXPECT_EQ(l.front.points.capacity(), l.front.points.size());
  EXPECT_EQ(l.front.triangles.capacity(), l.front.triangles.size());
  EXPECT_EQ(l.wall_point.capacity(), l.wall_point.size());
  EXPECT_EQ(l.wall_face.capacity(), l.wall_face.size());
  EXPECT_EQ(l.elements.capacity(), l.elements.size());
  EXPECT_EQ(l.element_of_triangle.capacity(), l.element_of_triangle.size());
  EXPECT_EQ(l.direction.capacity(), l.direction.size());
  EXPECT_EQ(l.in_fan.capacity(), l.in_fan.size());
  EXPECT_EQ(l.faceless.capacity(), l.faceless.size());
}

// The march's assembler reads the layout the checker shares rather than a copy of its
// elements; each point's direction is written in single precision.
TEST(FanAssembly, AssemblerSharesTheLayoutAndWritesSinglePrecisionDirections) {
  const TriSurface w = wedge_prism(15.0, 4.0, 2.0, 4);
  const auto l = std::make_shared<const ColumnLayout>(layout_of(w, 120.0, 40.0));
  const int nc = l->n_columns();
  const StepDirections d{{}, l->direction, std::vector<double>(nc, 1.0), std::vector<char>(nc, 1)};
  const WallTopology topo = build_column_topology(*l);
  ColumnState columns = ColumnState::on_wall(l->front.points, topo.used, l->wall_point);
  LayerAssembler a(w, l, d);
  EXPECT_EQ(l.use_count(), 2);
  std::vector<Vec3> next(nc);
  for (int c = 0; c < nc; ++c) next[c] = columns.top[c] + 0.01 * d.n[c];
  a.commit_layer(0, std::vector<char>(nc, 1), next, d, &columns);
  VolumeMesh m = a.take_mesh();
  a.attach_arrays(columns, &m);
  const DataArray* normal = m.find_point_array("normal");
  ASSERT_NE(normal, nullptr);
  ASSERT_EQ(normal->values.type(), ValueType::kFloat32);
  const std::vector<int>& column_of = a.point_column();
  ASSERT_EQ(normal->values.size(), 3 * m.points.size());
  for (std::size_t p = w.points.size(); p < m.points.size(); ++p)
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(normal->values[3 * p + i], static_cast<double>(static_cast<float>(d.n[column_of[p]][i]))) << p;
}

TEST(FanExtrusion, AnOpenBoxsFansEndAtItsRim) {
  // The top face removed: the vertical edges' top points are boundary points, single
  // columns; the fans of the points below end there.
  const TriSurface box = test_surfaces::box({0, 0, 0}, {1, 1, 1}, 3);
  TriSurface open;
  open.points = box.points;
  for (const Triangle& t : box.triangles) {
    bool top = true;
    for (int v : t) top = top && box.points[v][2] == 1.0;
    if (!top) open.triangles.push_back(t);
  }
  const ExtrusionResult r = extrude_layers(open, fan_params(3, 0.01, 1.2));
  // The rim's columns grow horizontally, in the plane z = 1.
  expect_conforming_valid_layers(open, r, [](const std::vector<Vec3>& pts) {
    for (const Vec3& x : pts)
      if (std::fabs(x[2] - 1.0) > 1e-12) return false;
    return true;
  });
  EXPECT_EQ(r.report.fans.ridge_ends, 4);
  EXPECT_EQ(r.report.fans.fallback_points, 0);
  EXPECT_DOUBLE_EQ(r.report.area_coverage, 1.0);
  EXPECT_EQ(r.report.fans.points, 4 * 2 + 4 * 2 + 4);  // vertical edges, bottom edges, bottom corners
}

TEST(FanExtrusion, AFanThatCannotGrowFallsBackToOneColumn) {
  // A hexagonal prism: its caps meet the sides at 90 degree ridges; the side edges turn
  // by exactly 60 degrees and are no ridges, so each rim point's side sector holds two
  // faces 60 degrees apart, visibility cos 30 = 0.866. Asking for 0.9 stops those
  // sector columns on the wall: the rims fall back to single columns.
  const TriSurface s = test_surfaces::capped_cylinder(6, 2, 1.0, 1.0);
  ExtrusionParams p = fan_params(3, 0.01, 1.2);
  p.fan_angle_deg = 65.0;  // the side edges turn by 60 degrees to rounding: keep them out
  p.min_visibility = 0.9;
  const ExtrusionResult r = extrude_layers(s, p);
  EXPECT_EQ(r.report.fans.fallback_points, 12);
  EXPECT_EQ(r.report.fans.points, 0);
  EXPECT_EQ(r.report.fans.attempts, 1);  // found before marching: no rerun
  expect_conforming_valid_layers(s, r);
  // With the default visibility floor the rims keep their fans.
  p.min_visibility = ExtrusionParams{}.min_visibility;
  const ExtrusionResult ok = extrude_layers(s, p);
  EXPECT_EQ(ok.report.fans.points, 12);
  EXPECT_EQ(ok.report.fans.fallback_points, 0);
  expect_conforming_valid_layers(s, ok);
}

}  // namespace
}  // namespace blayer
