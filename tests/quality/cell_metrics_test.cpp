#include "blayer/quality/cell_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "blayer/quality/cell_validity.h"
#include "blayer/quality/orient3d.h"
#include "test_cells.h"

namespace blayer {
namespace {

// Metrics are a few dozen flops from exact inputs: 1e-12 absolute (on values of order
// 1 to 100) leaves room for rounding while catching any formula error.
constexpr double kMetricTol = 1e-12;
constexpr double kPi = 3.14159265358979323846;

CellMetrics metrics(CellType t, const std::vector<Vec3>& p) { return compute_cell_metrics(t, p.data()); }

// Right prism over a unit equilateral triangle, height h, VTK wedge order.
std::vector<Vec3> equilateral_prism(double h) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, std::sqrt(3.0) / 2, 0};
  const Vec3 up{0, 0, h};
  return {a, c, b, a + up, c + up, b + up};
}

// Top cap rotated by `angle` radians about the vertical axis through its centroid.
std::vector<Vec3> twisted(std::vector<Vec3> p, double angle) {
  const Vec3 centre = (p[3] + p[4] + p[5]) / 3.0;
  for (int i = 3; i < 6; ++i) {
    const Vec3 d = p[i] - centre;
    p[i] = centre + Vec3{std::cos(angle) * d[0] - std::sin(angle) * d[1],
                         std::sin(angle) * d[0] + std::cos(angle) * d[1], d[2]};
  }
  return p;
}

TEST(CellMetrics, RightPrismHasZeroOrthogonalityAndItsCapToHeightAspectRatio) {
  const double h = 0.1;
  const CellMetrics m = metrics(CellType::kWedge, test::right_prism(h));
  EXPECT_NEAR(m.orthogonality_deg, 0.0, kMetricTol);
  EXPECT_NEAR(m.twist_deg, 0.0, kMetricTol);
  // Caps with legs 1, 1 and hypotenuse sqrt 2; columns of length h.
  EXPECT_NEAR(m.aspect_ratio, (2.0 + std::sqrt(2.0)) / 3.0 / h, kMetricTol);
  EXPECT_NEAR(m.volume, 0.5 * h, kMetricTol);
  // Right isosceles caps: angles 90, 45, 45 degrees -> (90-60)/120 = (60-45)/60 = 0.25.
  EXPECT_NEAR(m.skewness, 0.25, kMetricTol);
  // Worst corner is a 45-degree cap corner with an orthogonal column: sin 45 * 2/sqrt 3.
  EXPECT_NEAR(m.scaled_jacobian, std::sqrt(0.5) * 2.0 / std::sqrt(3.0), kMetricTol);
}

TEST(CellMetrics, EquilateralRightPrismIsIdeal) {
  const CellMetrics m = metrics(CellType::kWedge, equilateral_prism(2.0));
  EXPECT_NEAR(m.scaled_jacobian, 1.0, kMetricTol);
  EXPECT_NEAR(m.skewness, 0.0, kMetricTol);
  EXPECT_NEAR(m.aspect_ratio, 0.5, kMetricTol);
  EXPECT_NEAR(m.volume, std::sqrt(3.0) / 4.0 * 2.0, kMetricTol);
}

TEST(CellMetrics, ShearedPrismOrthogonalityIsTheShearAngle) {
  const double h = 0.2, shift = 0.2 * std::tan(30.0 * kPi / 180.0);
  std::vector<Vec3> p = test::right_prism(h);
  for (int i = 3; i < 6; ++i) p[i][0] += shift;
  const CellMetrics m = metrics(CellType::kWedge, p);
  EXPECT_NEAR(m.orthogonality_deg, 30.0, 1e-10);
  EXPECT_NEAR(m.twist_deg, 0.0, kMetricTol);   // shear keeps the quads planar
  EXPECT_NEAR(m.volume, 0.5 * h, kMetricTol);  // and the volume
  EXPECT_EQ(cell_validity(CellType::kWedge, p.data()), Validity::kValid);
}

TEST(CellMetrics, TiltedTopCapCountsInOrthogonality) {
  // Column edges vertical, top cap tilted by raising node 5 (above b = (1,0,0)):
  // the top normal leans by atan(rise) from the columns.
  std::vector<Vec3> p = test::right_prism(1.0);
  p[5][2] += 0.5;
  const CellMetrics m = metrics(CellType::kWedge, p);
  EXPECT_NEAR(m.orthogonality_deg, std::atan(0.5) * 180.0 / kPi, 1e-10);
}

TEST(CellMetrics, TwistedPrismHasWarpedQuadsAndTheTrilinearVolume) {
  const double angle = 10.0 * kPi / 180.0;
  const std::vector<Vec3> p = twisted(equilateral_prism(1.0), angle);
  const CellMetrics m = metrics(CellType::kWedge, p);
  EXPECT_GT(m.twist_deg, 1.0);
  EXPECT_EQ(cell_validity(CellType::kWedge, p.data()), Validity::kValid);
  // The cross-section at height z is the cap mapped by (1-z) I + z R(angle), whose
  // determinant (1-z)^2 + 2z(1-z)cos(angle) + z^2 integrates to (2 + cos(angle)) / 3.
  EXPECT_NEAR(m.volume, std::sqrt(3.0) / 4.0 * (2.0 + std::cos(angle)) / 3.0, kMetricTol);
}

TEST(CellValidity, HalfTurnTwistedPrismIsTwistedNotInvertedSinceEveryCornerIsPositive) {
  const std::vector<Vec3> p = twisted(equilateral_prism(1.0), kPi);
  // Each cap lies on the right side of each node of the other cap ...
  EXPECT_EQ(orient3d_sign(p[0], p[2], p[1], p[3]), 1);
  EXPECT_EQ(orient3d_sign(p[0], p[2], p[1], p[4]), 1);
  EXPECT_EQ(orient3d_sign(p[0], p[2], p[1], p[5]), 1);
  EXPECT_EQ(orient3d_sign(p[3], p[4], p[5], p[0]), 1);
  EXPECT_EQ(orient3d_sign(p[3], p[4], p[5], p[1]), 1);
  EXPECT_EQ(orient3d_sign(p[3], p[4], p[5], p[2]), 1);
  // ... but the column is folded, which the cap-edge tets see.
  EXPECT_EQ(cell_validity(CellType::kWedge, p.data()), Validity::kTwisted);
  EXPECT_FALSE(prism_is_valid(p.data()));
  // The corner Jacobians are the cap tets, so the scaled Jacobian stays positive here;
  // the twist metric shows the fold.
  const CellMetrics m = metrics(CellType::kWedge, p);
  EXPECT_GT(m.scaled_jacobian, 0.0);
  EXPECT_GT(m.twist_deg, 90.0);
}

TEST(CellMetrics, UnitCubeIsIdealAndRegularTetScoresOne) {
  const CellMetrics cube = metrics(CellType::kHex, test::unit_hex());
  EXPECT_NEAR(cube.scaled_jacobian, 1.0, kMetricTol);
  EXPECT_NEAR(cube.skewness, 0.0, kMetricTol);
  EXPECT_NEAR(cube.aspect_ratio, 1.0, kMetricTol);
  EXPECT_NEAR(cube.orthogonality_deg, 0.0, kMetricTol);
  EXPECT_NEAR(cube.volume, 1.0, kMetricTol);
  const std::vector<Vec3> regular{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  // (0,1,2) of this tet has its normal toward node 3 only after a swap.
  const std::vector<Vec3> tet{regular[0], regular[2], regular[1], regular[3]};
  ASSERT_EQ(cell_validity(CellType::kTet, tet.data()), Validity::kValid);
  const CellMetrics t = metrics(CellType::kTet, tet);
  EXPECT_NEAR(t.scaled_jacobian, 1.0, kMetricTol);
  EXPECT_NEAR(t.skewness, 0.0, kMetricTol);
  EXPECT_NEAR(t.aspect_ratio, 1.0, kMetricTol);
  EXPECT_NEAR(t.volume, 8.0 / 3.0, kMetricTol);
  EXPECT_TRUE(std::isnan(t.orthogonality_deg));
}

TEST(CellMetrics, EqualEdgePyramidScoresOneAndHasItsVolume) {
  const double h = std::sqrt(0.5);
  const CellMetrics m = metrics(CellType::kPyramid, test::unit_pyramid(h));
  EXPECT_NEAR(m.scaled_jacobian, 1.0, kMetricTol);
  EXPECT_NEAR(m.aspect_ratio, 1.0, kMetricTol);
  EXPECT_NEAR(m.volume, h / 3.0, kMetricTol);
  EXPECT_NEAR(m.skewness, 0.0, kMetricTol);
}

TEST(CellMetrics, MirroredCellsHaveNegativeJacobianAndVolume) {
  for (const auto& [t, p] : std::vector<std::pair<CellType, std::vector<Vec3>>>{
           {CellType::kTet, test::unit_tet()},
           {CellType::kPyramid, test::unit_pyramid()},
           {CellType::kWedge, test::right_prism()},
           {CellType::kHex, test::unit_hex()}}) {
    const CellMetrics m = metrics(t, test::mirrored(p));
    EXPECT_LT(m.scaled_jacobian, 0.0) << cell_type_name(t);
    EXPECT_LT(m.volume, 0.0) << cell_type_name(t);
  }
}

TEST(CellMetrics, WarpedHexFaceTwistIsTheAngleBetweenItsSplitNormals) {
  std::vector<Vec3> p = test::unit_hex();
  p[6][2] += 0.5;  // lift one top corner: top face (4,5,6,7) warps
  const CellMetrics m = metrics(CellType::kHex, p);
  // Split along 4-6: normals of (4,5,6) = (0,-0.5,1) and (4,6,7) = (-0.5,0,1); the side
  // faces stay planar (x = 1 and y = 1).
  const double split46 = std::acos(1.0 / 1.25) * 180.0 / kPi;
  // Split along 5-7: normals of (5,6,7) = (-0.5,-0.5,1) and (5,7,4) = (0,0,1).
  const double split57 = std::acos(1.0 / std::sqrt(1.5)) * 180.0 / kPi;
  EXPECT_NEAR(m.twist_deg, std::max(split46, split57), 1e-10);
}

// Equiangle skewness from every corner angle of the given faces (atan2 at each corner),
// the definition in cell_metrics.h without picking corners or faces by cosine.
double reference_skewness(const std::vector<Vec3>& p, const std::vector<std::vector<int>>& faces) {
  double skew = 0.0;
  for (const std::vector<int>& f : faces) {
    const int n = static_cast<int>(f.size());
    const double ideal = n == 3 ? 60.0 : 90.0;
    double lo = 180.0, hi = 0.0;
    for (int i = 0; i < n; ++i) {
      const Vec3& b = p[f[i]];
      const double a = angle_between(p[f[(i + n - 1) % n]] - b, p[f[(i + 1) % n]] - b) * 180.0 / kPi;
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
    skew = std::max({skew, (hi - ideal) / (180.0 - ideal), (ideal - lo) / ideal});
  }
  return std::min(skew, 1.0);
}

// The cell under a random affine map (identity plus entries in [-0.3, 0.3]), each node
// then moved by up to `moved` times 0.3 along each axis.
std::vector<Vec3> random_affine_image(const std::vector<Vec3>& ref, double moved, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  double a[3][3];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) a[r][c] = (r == c ? 1.0 : 0.0) + u(rng);
  std::vector<Vec3> p;
  for (const Vec3& x : ref) {
    Vec3 y;
    for (int r = 0; r < 3; ++r) y[r] = a[r][0] * x[0] + a[r][1] * x[1] + a[r][2] * x[2] + moved * u(rng);
    p.push_back(y);
  }
  return p;
}

// Affine images of the reference cells (congruent opposite faces, so nearly tied face
// skewness) with some nodes moved: the faces and corners that decide the skewness are
// picked by cosine, and the largest over all faces must still be found.
TEST(CellMetrics, SkewnessIsTheLargestOverFacesOfEveryCornerAngle) {
  const std::vector<std::vector<int>> tet_faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  const std::vector<std::vector<int>> pyramid_faces = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const std::vector<std::vector<int>> wedge_caps = {{0, 1, 2}, {3, 5, 4}};
  const std::vector<std::vector<int>> hex_faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  const std::vector<std::tuple<CellType, std::vector<Vec3>, std::vector<std::vector<int>>>> cells = {
      {CellType::kTet, test::unit_tet(), tet_faces},
      {CellType::kPyramid, test::unit_pyramid(0.7), pyramid_faces},
      {CellType::kWedge, test::right_prism(0.3), wedge_caps},
      {CellType::kHex, test::unit_hex(), hex_faces}};
  std::mt19937 rng(7);
  for (const auto& [t, ref, faces] : cells) {
    for (int k = 0; k < 2000; ++k) {
      // Every other cell also has its nodes moved.
      const std::vector<Vec3> p = random_affine_image(ref, k % 2 == 0 ? 0.0 : 0.2, rng);
      EXPECT_NEAR(metrics(t, p).skewness, reference_skewness(p, faces), 1e-9) << cell_type_name(t) << " " << k;
    }
  }
}

double degrees_between(const Vec3& a, const Vec3& b) { return angle_between(a, b) * 180.0 / kPi; }

// Twist from every quad face and both of its diagonal splits, with atan2 for each pair
// of split normals: the definition in cell_metrics.h without picking pairs by cosine.
double reference_twist(const std::vector<Vec3>& p, const std::vector<std::vector<int>>& quads) {
  double twist = 0.0;
  for (const std::vector<int>& q : quads) {
    const Vec3 &a = p[q[0]], &b = p[q[1]], &c = p[q[2]], &d = p[q[3]];
    twist = std::max(twist, degrees_between(cross(b - a, c - a), cross(c - a, d - a)));
    twist = std::max(twist, degrees_between(cross(c - b, d - b), cross(d - b, a - b)));
  }
  return twist;
}

// Orthogonality from every column edge against both cap normals (a triangle cap's
// normal from its corners, a quad cap's from its diagonals), atan2 for each pair.
double reference_orthogonality(const std::vector<Vec3>& p, const std::vector<int>& bottom,
                               const std::vector<int>& top) {
  auto cap_normal = [&](const std::vector<int>& v) {
    return v.size() == 3 ? cross(p[v[1]] - p[v[0]], p[v[2]] - p[v[0]]) : cross(p[v[2]] - p[v[0]], p[v[3]] - p[v[1]]);
  };
  const Vec3 nb = cap_normal(bottom), nt = cap_normal(top);
  double worst = 0.0;
  for (std::size_t i = 0; i < bottom.size(); ++i) {
    const Vec3 column = p[top[i]] - p[bottom[i]];
    worst = std::max({worst, degrees_between(column, nb), degrees_between(column, nt)});
  }
  return worst;
}

// Affine images of the reference cells with their nodes moved, half of them far enough
// for angles beyond 90 degrees (folded faces, columns leaning past their caps): the
// pairs that decide twist and orthogonality are picked by cosine_key, and the largest
// angle over all pairs must still be found.
TEST(CellMetrics, TwistAndOrthogonalityAreTheLargestAnglesOverEveryPair) {
  struct Case {
    CellType type;
    std::vector<Vec3> ref;
    std::vector<std::vector<int>> quads;
    std::vector<int> bottom, top;  // empty for types without caps
  };
  const std::vector<Case> cases = {
      {CellType::kPyramid, test::unit_pyramid(0.7), {{0, 3, 2, 1}}, {}, {}},
      {CellType::kWedge, test::right_prism(0.3), {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}}, {0, 2, 1}, {3, 5, 4}},
      {CellType::kHex,
       test::unit_hex(),
       {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}},
       {0, 1, 2, 3},
       {4, 5, 6, 7}}};
  std::mt19937 rng(11);
  int n_obtuse = 0;
  for (const Case& c : cases) {
    for (int k = 0; k < 2000; ++k) {
      const std::vector<Vec3> p = random_affine_image(c.ref, k % 2 == 0 ? 0.2 : 1.5, rng);
      const CellMetrics m = metrics(c.type, p);
      const double twist = reference_twist(p, c.quads);
      n_obtuse += twist > 90.0;
      EXPECT_NEAR(m.twist_deg, twist, 1e-9) << cell_type_name(c.type) << " " << k;
      if (c.bottom.empty()) continue;
      const double ortho = reference_orthogonality(p, c.bottom, c.top);
      n_obtuse += ortho > 90.0;
      EXPECT_NEAR(m.orthogonality_deg, ortho, 1e-9) << cell_type_name(c.type) << " " << k;
    }
  }
  // Obtuse angles, where a key without the cosine's sign would pick the smallest angle.
  EXPECT_GT(n_obtuse, 200);
}

}  // namespace
}  // namespace blayer
