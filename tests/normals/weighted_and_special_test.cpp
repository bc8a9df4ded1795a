// Weighted averages against the docs/normals.md table, the fallback branches
// (infeasible, folded, degenerate, boundary) and analytic surfaces.
#include <gtest/gtest.h>

#include <cmath>

#include "blayer/core/vertex_fans.h"
#include "blayer/normals/most_normal.h"
#include "blayer/normals/most_visible.h"
#include "blayer/normals/point_normals.h"
#include "blayer/normals/vertex_normal.h"
#include "blayer/normals/weighted_normal.h"
#include "analytic_surfaces.h"
#include "oracle.h"
#include "test_fans.h"

namespace blayer {
namespace {

using testing_fans::deg;

// The table gives V to 6 decimals and angles to 4 decimals of a degree.
constexpr double kTableV = 5e-7;
constexpr double kTableAngleDeg = 5e-5;

struct WeightedRow {
  int fan;
  NormalMethod method;
  double angle_to_mv_deg;
  double v;
};

TEST(WeightedAverage, MatchesPublishedTable) {
  const std::vector<WeightedRow> rows = {
      {1, NormalMethod::kUnit, 15.7932, 0.333333},     {1, NormalMethod::kAngle, 0, 0.577350},
      {3, NormalMethod::kArea, 2.3533, 0.677476},      {3, NormalMethod::kInverseArea, 1.2189, 0.691905},
      {3, NormalMethod::kMax, 3.8818, 0.657614},       {4, NormalMethod::kArea, 48.2299, -0.548000},
      {4, NormalMethod::kMax, 48.2299, -0.548000},     {5, NormalMethod::kArea, 4.0283, 0.655687},
      {5, NormalMethod::kInverseArea, 3.6642, 0.660471}, {5, NormalMethod::kMax, 5.0798, 0.641720},
      {6, NormalMethod::kUnit, 58.5158, -0.804021},    {6, NormalMethod::kArea, 25.8825, -0.356453},
      {6, NormalMethod::kInverseArea, 70.0027, -0.906328}, {6, NormalMethod::kAngle, 0, 0.087156},
      {8, NormalMethod::kUnit, 15.5803, 0.576263},     {8, NormalMethod::kArea, 14.3815, 0.713155},
      {8, NormalMethod::kInverseArea, 26.4352, 0.412044}, {8, NormalMethod::kAngle, 2.9180, 0.773592},
      {8, NormalMethod::kMax, 12.3242, 0.621754},      {9, NormalMethod::kUnit, 19.4712, 0.408248},
      {9, NormalMethod::kArea, 29.4962, 0.301511},     {9, NormalMethod::kInverseArea, 11.4218, 0.485071},
      {9, NormalMethod::kAngle, 29.4962, 0.301511},    {10, NormalMethod::kUnit, 50.9958, -0.459701},
      {10, NormalMethod::kArea, 48.9857, -0.545056},   {10, NormalMethod::kInverseArea, 57.4251, -0.318948},
      {10, NormalMethod::kAngle, 18.2687, 0.217605},   {10, NormalMethod::kMax, 28.5044, 0.189241},
  };
  const auto fans = testing_fans::public_fans();
  for (const WeightedRow& row : rows) {
    const FanGeometry g = testing_fans::geometry(fans[row.fan].ring);
    const VertexNormal vn = compute_vertex_normal(g, row.method);
    const MostVisibleResult mv = most_visible_normal(g.face_normals);
    const double angle = angle_between(vn.normal, mv.normal) * 180.0 / M_PI;
    EXPECT_NEAR(angle, row.angle_to_mv_deg, kTableAngleDeg) << fans[row.fan].name << " " << normal_method_name(row.method);
    EXPECT_NEAR(vn.visibility, row.v, kTableV) << fans[row.fan].name << " " << normal_method_name(row.method);
    EXPECT_EQ(vn.status, NormalStatus::kOk);
  }
}

TEST(WeightedAverage, ExactVectors) {
  const auto fans = testing_fans::public_fans();
  const double eps = 1e-12;  // closed-form vectors, double rounding only
  EXPECT_NEAR(norm(weighted_average_normal(testing_fans::geometry(fans[1].ring), NormalMethod::kUnit) -
                   Vec3{2.0 / 3, 1.0 / 3, 2.0 / 3}), 0.0, eps);
  EXPECT_NEAR(norm(weighted_average_normal(testing_fans::geometry(fans[6].ring), NormalMethod::kUnit) -
                   normalized(Vec3{7 * std::sin(deg(5)), 0, std::cos(deg(5))})), 0.0, eps);
  EXPECT_NEAR(norm(weighted_average_normal(testing_fans::geometry(fans[9].ring), NormalMethod::kAngle) -
                   normalized(Vec3{1, 1, 3})), 0.0, eps);
}

// Four triangles whose normals are the corners of a tetrahedron around the origin: each
// ring direction lies on the line shared by two consecutive face planes.
std::vector<Vec3> infeasible_ring() {
  const std::vector<Vec3> f = {normalized(Vec3{0, 0, 1}), normalized(Vec3{0.9, 0, -0.5}),
                               normalized(Vec3{-0.5, 0.8, -0.5}), normalized(Vec3{-0.5, -0.8, -0.5})};
  const double sign[4] = {1, -1, -1, 1};
  std::vector<Vec3> ring;
  for (int i = 0; i < 4; ++i) ring.push_back(sign[i] * cross(f[(i + 3) % 4], f[i]));
  return ring;
}

TEST(MostVisible, InfeasibleFanReportsNegativeMarginAndCertificate) {
  const FanGeometry g = testing_fans::geometry(infeasible_ring());
  const MostVisibleResult en = most_visible_by_enumeration(g.face_normals.data(), g.n_faces());
  const MostVisibleResult mv = most_visible_normal(g.face_normals);
  const MostVisibleResult margin = best_margin_direction(g.face_normals.data(), g.n_faces());
  for (int i = 0; i < 4; ++i) ASSERT_GT(dot(g.face_normals[i], g.face_normals[i]), 0.99);
  EXPECT_FALSE(mv.feasible);
  EXPECT_FALSE(en.feasible);
  EXPECT_LT(mv.visibility, 0.0);
  EXPECT_NEAR(mv.visibility, margin.visibility, 1e-12);
  // Certificate: the margin equals the direct minimum over faces at the returned normal,
  // and no sampled direction does better.
  const oracle::Link link = oracle::make_link(infeasible_ring());
  EXPECT_NEAR(oracle::visibility(link, mv.normal), mv.visibility, 1e-12);
  double sampled = -2.0;
  for (int i = 0; i < 20000; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / 20000;
    const double r = std::sqrt(1 - z * z);
    const Vec3 n{r * std::cos(2.39996 * i), r * std::sin(2.39996 * i), z};
    sampled = std::max(sampled, oracle::visibility(link, n));
  }
  EXPECT_LE(sampled, mv.visibility + 1e-12);
  EXPECT_GE(sampled, mv.visibility - 0.02);  // 20000 samples are ~0.025 rad apart
  const VertexNormal vn = compute_vertex_normal(g, NormalMethod::kMostNormal);
  EXPECT_EQ(vn.status, NormalStatus::kNoVisibleDirection);
  EXPECT_LT(vn.visibility, 0.0);
}

TEST(MostVisible, OppositeFacesHaveZeroMargin) {
  const std::vector<Vec3> f = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}};
  const MostVisibleResult mv = most_visible_normal(f);
  EXPECT_FALSE(mv.feasible);
  EXPECT_NEAR(mv.visibility, 0.0, 1e-15);
}

TEST(MostNormal, FoldedLinkIsDegenerate) {
  // The ring winds twice around the vertex: a fold-over fan with visible faces.
  std::vector<Vec3> ring;
  for (int j = 0; j < 10; ++j) {
    const double a = deg(144.0 * j);
    ring.push_back({std::cos(a), std::sin(a), -0.2});
  }
  const FanGeometry g = testing_fans::geometry(ring);
  const VertexNormal vn = compute_vertex_normal(g, NormalMethod::kMostNormal);
  EXPECT_EQ(vn.status, NormalStatus::kDegenerateFan);
  EXPECT_NEAR(norm(vn.normal - weighted_average_normal(g, NormalMethod::kAngle)), 0.0, 1e-15);
}

TEST(VertexNormal, ZeroAreaTriangleFallsBackToAngleAverage) {
  std::vector<Vec3> ring = {{1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  const VertexNormal vn = compute_vertex_normal(testing_fans::geometry(ring), NormalMethod::kMostNormal);
  EXPECT_EQ(vn.status, NormalStatus::kDegenerateFan);
  EXPECT_NEAR(vn.normal[2], 1.0, 1e-15);
}

TEST(VertexNormal, OpenFanUsesMostVisibleOfHalfFan) {
  std::vector<Vec3> ring = {{1, 0, 0}, {0, 1, 0.2}, {-1, 0, 0}};
  const FanGeometry g = testing_fans::geometry(ring, false);
  const VertexNormal vn = compute_vertex_normal(g, NormalMethod::kMostNormal);
  EXPECT_EQ(vn.status, NormalStatus::kBoundary);
  const MostVisibleResult mv = most_visible_normal(g.face_normals);
  EXPECT_NEAR(norm(vn.normal - mv.normal), 0.0, 1e-15);
  EXPECT_GT(vn.visibility, 0.9);
}

TriSurface uv_sphere(int n_lat, int n_lon, double radius) {
  return test_surfaces::uv_sphere(n_lat, n_lon, radius, 0.37);
}

TEST(PointNormals, MaxWeightsAreExactOnSphere) {
  const TriSurface s = uv_sphere(9, 13, 2.0);
  ASSERT_GT(signed_volume(s), 0.0);
  const VertexFans fans = build_vertex_fans(s);
  ASSERT_TRUE(fans.non_manifold.empty());
  const PointNormals mx = compute_point_normals(s, fans, NormalMethod::kMax);
  const PointNormals mn = compute_point_normals(s, fans, NormalMethod::kMostNormal);
  const PointNormals mv = compute_point_normals(s, fans, NormalMethod::kMostVisible);
  double worst_max = 0, worst_mn = 0;
  for (std::size_t v = 0; v < s.points.size(); ++v) {
    const Vec3 exact = normalized(s.points[v]);
    worst_max = std::max(worst_max, angle_between(mx.normal[v], exact));
    worst_mn = std::max(worst_mn, angle_between(mn.normal[v], exact));
    EXPECT_GT(mv.visibility[v], 0.0);
    EXPECT_GE(mn.visibility[v], 0.5 * mv.visibility[v] - 1e-12);
    EXPECT_GE(mn.normality[v], mv.normality[v] - 1e-9);
  }
  EXPECT_LT(worst_max, 1e-12);  // Max 1999 is exact for vertices on a sphere
  EXPECT_LT(worst_mn, deg(10));  // MN optimises extrusion, not fidelity
}

TEST(PointNormals, CylinderNormalsAreRadialWithinLooseBound) {
  TriSurface s;
  const int n = 12, m = 5;
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = 2 * M_PI * (j + 0.5 * (i % 2)) / n;
      s.points.push_back({std::cos(a), std::sin(a), 0.3 * i});
    }
  for (int i = 0; i + 1 < m; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * n + j, b = i * n + (j + 1) % n, c = (i + 1) * n + j, d = (i + 1) * n + (j + 1) % n;
      s.triangles.push_back({a, b, d});
      s.triangles.push_back({a, d, c});
    }
  const VertexFans fans = build_vertex_fans(s);
  for (NormalMethod method : {NormalMethod::kMostNormal, NormalMethod::kMostVisible, NormalMethod::kAngle}) {
    const PointNormals pn = compute_point_normals(s, fans, method);
    for (int i = 1; i + 1 < m; ++i)
      for (int j = 0; j < n; ++j) {
        const int v = i * n + j;
        const Vec3 radial = normalized(Vec3{s.points[v][0], s.points[v][1], 0});
        EXPECT_LT(angle_between(pn.normal[v], radial), deg(10)) << normal_method_name(method);
        EXPECT_GT(pn.visibility[v], 0.0);
      }
  }
}

TEST(PointNormals, ParallelRunIsDeterministic) {
  const TriSurface s = uv_sphere(40, 60, 1.0);
  const VertexFans fans = build_vertex_fans(s);
  const PointNormals a = compute_point_normals(s, fans, NormalMethod::kMostNormal);
  const PointNormals b = compute_point_normals(s, fans, NormalMethod::kMostNormal);
  EXPECT_EQ(a.normal, b.normal);
  EXPECT_EQ(a.normality, b.normality);
  EXPECT_EQ(a.status, b.status);
}

TEST(PointNormals, MethodNamesRoundTrip) {
  for (const std::string& name : normal_method_names()) {
    NormalMethod m;
    ASSERT_TRUE(parse_normal_method(name, &m));
    EXPECT_EQ(name, normal_method_name(m));
  }
  NormalMethod m;
  EXPECT_FALSE(parse_normal_method("average", &m));
}

}  // namespace
}  // namespace blayer
