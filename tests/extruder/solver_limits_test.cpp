// The solver-acceptance limits in the per-layer check (front_checker.h): a cell that
// passes the exact test but breaks a limit fails like an invalid one, which face of a
// layer each limit judges, and the incremental re-checks with the limits on.
#include <gtest/gtest.h>

#include <vector>

#include "blayer/core/errors.h"
#include "blayer/extruder/front_checker.h"
#include "blayer/extruder/layer_cells.h"
#include "blayer/extruder/wall_topology.h"
#include "blayer/quality/cell_validity.h"
#include "blayer/quality/solver_acceptance.h"
#include "lcg.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

// Only the given limits.
ExtrusionParams limits(const AcceptanceLimits& l) {
  ExtrusionParams p;
  p.fan_angle_deg = 0.0;  // the limits apply to single columns (front_checker.h)
  p.solver_limits = l;
  return p;
}

AcceptanceLimits boundary_skewness(double x) {
  AcceptanceLimits l;
  l.max_boundary_skewness = x;
  return l;
}

// A flat 3 x 3 grid of unit squares split into right triangles with unit legs, facing
// +z, and one layer over it: every column moved by `step`.
struct Layer {
  TriSurface wall = test::square_plate(3, 3.0);
  std::vector<Vec3> top = wall.points, next = wall.points;
  std::vector<int> layers = std::vector<int>(wall.points.size(), 0);
  std::vector<char> grows = std::vector<char>(wall.points.size(), 1);
  explicit Layer(const Vec3& step) {
    for (Vec3& p : next) p += step;
  }
};

bool every_cell_valid(const TriSurface& wall, const std::vector<Vec3>& lo, const std::vector<Vec3>& hi) {
  for (const Triangle& t : wall.triangles) {
    LayerCell c;
    layer_cell({0, 1, 2}, {3, 4, 5}, {true, true, true}, &c);
    Vec3 corners[6];
    for (int i = 0; i < 6; ++i) corners[i] = c.nodes[i] < 3 ? lo[t[c.nodes[i]]] : hi[t[c.nodes[i] - 3]];
    if (cell_validity(c.type, corners) != Validity::kValid) return false;
  }
  return true;
}

FrontVerdict check_layer(FrontChecker* checker, int k, const std::vector<Vec3>& top, const std::vector<Vec3>& next,
                         const std::vector<int>& layers, const std::vector<char>& grows) {
  checker->begin_layer(k, top, layers);
  FrontVerdict v;
  checker->check(0, top, next, grows, &v);
  return v;
}

TEST(SolverLimits, ShearedFirstLayerPassesTheExactTestButNotTheWallSkewnessLimit) {
  // Every column leans by (6, 0, 1): an affine image of a right layer, so every cell is
  // valid. The centre of each cell projects s/2 = 3 beside its wall triangle's centroid,
  // whose extent along x is 2/3: boundary skewness 3 / (2/3) = 4.5.
  Layer l({6.0, 0.0, 1.0});
  ASSERT_TRUE(every_cell_valid(l.wall, l.top, l.next));
  FrontChecker exact_only(l.wall, build_wall_topology(l.wall), true);
  EXPECT_FALSE(check_layer(&exact_only, 0, l.top, l.next, l.layers, l.grows).any_bad);

  FrontChecker limited(l.wall, build_wall_topology(l.wall), limits(boundary_skewness(4.0)));
  const FrontVerdict v = check_layer(&limited, 0, l.top, l.next, l.layers, l.grows);
  ASSERT_TRUE(v.any_bad);
  for (std::size_t p = 0; p < l.top.size(); ++p) {
    EXPECT_TRUE(v.bad[p]) << p;
    EXPECT_EQ(v.reason[p], StopReason::kQuality) << p;
  }
  for (char b : v.bad_triangle) EXPECT_TRUE(b);

  FrontChecker looser(l.wall, build_wall_topology(l.wall), limits(boundary_skewness(4.6)));
  EXPECT_FALSE(check_layer(&looser, 0, l.top, l.next, l.layers, l.grows).any_bad);
}

TEST(SolverLimits, DefaultLimitsRefuseTheShearedLayer) {
  Layer l({6.0, 0.0, 1.0});
  FrontChecker defaults(l.wall, build_wall_topology(l.wall), ExtrusionParams{});
  EXPECT_TRUE(check_layer(&defaults, 0, l.top, l.next, l.layers, l.grows).any_bad);
}

TEST(SolverLimits, FaceToTheCellBelowIsJudgedWithThatCellsCentre) {
  // Layer 0 leans by (s, 0, h), layer 1 returns over the wall (to (0, 0, 2h)). Their
  // centres are one above the other, so the line between them is vertical and crosses
  // the shared cap s/2 from its centroid: internal skewness (s/2) / (2/3) = 3s/4 = 4.5.
  const double s = 6.0, h = 1.0;
  Layer l({s, 0.0, h});
  std::vector<Vec3> second = l.wall.points;
  for (Vec3& p : second) p += Vec3{0.0, 0.0, 2 * h};
  ASSERT_TRUE(every_cell_valid(l.wall, l.next, second));
  AcceptanceLimits internal;
  internal.max_skewness = 4.0;
  const std::vector<int> one(l.top.size(), 1);

  FrontChecker marching(l.wall, build_wall_topology(l.wall), limits(internal));
  EXPECT_FALSE(check_layer(&marching, 0, l.top, l.next, l.layers, l.grows).any_bad);
  const FrontVerdict v = check_layer(&marching, 1, l.next, second, one, l.grows);
  EXPECT_TRUE(v.any_bad);
  for (char b : v.bad_triangle) EXPECT_TRUE(b);

  // A checker that did not see layer 0 does not know the cell below: the face is not
  // judged against it.
  FrontChecker fresh(l.wall, build_wall_topology(l.wall), limits(internal));
  EXPECT_FALSE(check_layer(&fresh, 1, l.next, second, one, l.grows).any_bad);

  internal.max_skewness = 4.6;
  FrontChecker looser(l.wall, build_wall_topology(l.wall), limits(internal));
  check_layer(&looser, 0, l.top, l.next, l.layers, l.grows);
  EXPECT_FALSE(check_layer(&looser, 1, l.next, second, one, l.grows).any_bad);
}

TEST(SolverLimits, SideFaceBetweenTwoNewCellsFailsBothCells) {
  // The right layer over this grid has no skewness (the line between the centroids of
  // two triangles crosses their shared edge at its middle). One column, at the interior
  // point 5 of the 4 x 4 points, leans along -y: the side faces around it skew; a cell
  // is refused when one of its faces is, and a refused shared face refuses both cells.
  Layer l({0.0, 0.0, 0.2});
  AcceptanceLimits internal;
  internal.max_skewness = 0.05;
  FrontChecker right(l.wall, build_wall_topology(l.wall), limits(internal));
  EXPECT_FALSE(check_layer(&right, 0, l.top, l.next, l.layers, l.grows).any_bad);
  l.next[5] += Vec3{0.3, -0.6, 0.0};
  ASSERT_TRUE(every_cell_valid(l.wall, l.top, l.next));
  FrontChecker checker(l.wall, build_wall_topology(l.wall), limits(internal));
  const FrontVerdict v = check_layer(&checker, 0, l.top, l.next, l.layers, l.grows);
  ASSERT_TRUE(v.any_bad);
  // Triangles not touching point 5 or its neighbours' cells keep their verdict: the far
  // corner triangle (the last one, at (2..3, 2..3)) is fine.
  EXPECT_FALSE(v.bad_triangle.back());
  // Every refused triangle shares a side face with another refused triangle or touches
  // point 5 (whose cells moved).
  for (std::size_t f = 0; f < l.wall.triangles.size(); ++f) {
    if (!v.bad_triangle[f]) continue;
    bool explained = false;
    for (int p : l.wall.triangles[f]) explained = explained || p == 5;
    for (std::size_t g = 0; g < l.wall.triangles.size() && !explained; ++g) {
      if (g == f || !v.bad_triangle[g]) continue;
      int shared = 0;
      for (int p : l.wall.triangles[f])
        for (int q : l.wall.triangles[g]) shared += p == q;
      explained = shared == 2;
    }
    EXPECT_TRUE(explained) << f;
  }
}

TEST(SolverLimits, FaceBetweenThinWallTrianglesIsHeldToTwiceTheWallsLean) {
  // A 5e-5 x 1 rectangle split along its diagonal (a CAD wall's thin triangles): the
  // face over the diagonal of a straight layer has the wall's own non-orthogonality,
  // acos(2 w L / (w^2 + L^2)) = acos(1e-4) = 89.9943 degrees, beyond the default limit
  // 89.99, and no column direction can lower it. It is held to acos(5e-5) instead, so
  // the layer is kept; a layer leaning the face further than that is still refused.
  const double w = 5e-5;
  TriSurface wall;
  wall.points = {{0, 0, 0}, {w, 0, 0}, {0, 1, 0}, {w, 1, 0}};
  wall.triangles = {{0, 1, 3}, {0, 3, 2}};
  std::vector<Vec3> next = wall.points;
  for (Vec3& p : next) p += Vec3{0.0, 0.0, 1e-5};
  const std::vector<int> layers(4, 0);
  const std::vector<char> grows(4, 1);
  ASSERT_TRUE(every_cell_valid(wall, wall.points, next));
  ASSERT_GT(wall_edge_non_orthogonality_deg({wall.points[0], wall.points[1], wall.points[3]},
                                            {wall.points[0], wall.points[3], wall.points[2]}, wall.points[0],
                                            wall.points[3]),
            ExtrusionParams{}.solver_limits.max_non_orthogonality_deg);
  FrontChecker defaults(wall, build_wall_topology(wall), ExtrusionParams{});
  EXPECT_FALSE(check_layer(&defaults, 0, wall.points, next, layers, grows).any_bad);

  // The columns of the diagonal's points lean by 2 h along +x: both cells' centres move
  // alike, but the face over the diagonal tilts towards the layer's top, and the cosine
  // between its normal and the centres' line drops by a factor 1 / sqrt(5) < 1 / 2.
  next[0] += Vec3{2e-5, 0.0, 0.0};
  next[3] += Vec3{2e-5, 0.0, 0.0};
  ASSERT_TRUE(every_cell_valid(wall, wall.points, next));
  FrontChecker leaning(wall, build_wall_topology(wall), ExtrusionParams{});
  EXPECT_TRUE(check_layer(&leaning, 0, wall.points, next, layers, grows).any_bad);
}

TEST(SolverLimits, IncrementalAttemptsGiveTheVerdictOfAFreshCheck) {
  // Random column moves over several attempts, with limits strict enough that some
  // cells fail: a cell's verdict also depends on its neighbours' columns, and every
  // attempt must end with the verdicts of a fresh check.
  Layer l({0.0, 0.0, 0.2});
  AcceptanceLimits strict{20.0, 0.3, 0.3, 10.0, true, true};
  FrontChecker incremental(l.wall, build_wall_topology(l.wall), limits(strict));
  incremental.begin_layer(0, l.top, l.layers);
  testing::Lcg rng(11);
  std::size_t n_bad_seen = 0;
  for (int attempt = 0; attempt < 6; ++attempt) {
    for (int moves = 0; moves < 3; ++moves) {
      const int p = static_cast<int>(rng.uniform() * l.top.size());
      l.next[p] = l.top[p] + Vec3{0.3 * (rng.uniform() - 0.5), 0.3 * (rng.uniform() - 0.5), 0.2};
    }
    if (attempt == 3) l.grows[6] = 0;  // a column stops: pyramids and tets around it
    FrontVerdict inc, fresh;
    incremental.check(attempt, l.top, l.next, l.grows, &inc);
    FrontChecker full(l.wall, build_wall_topology(l.wall), limits(strict));
    full.begin_layer(0, l.top, l.layers);
    full.check(0, l.top, l.next, l.grows, &fresh);
    EXPECT_EQ(inc.bad, fresh.bad) << "attempt " << attempt;
    EXPECT_EQ(inc.bad_triangle, fresh.bad_triangle) << "attempt " << attempt;
    for (char b : fresh.bad_triangle) n_bad_seen += b;
  }
  EXPECT_GT(n_bad_seen, 0u) << "the limits must refuse some cells for the test to mean anything";
}

TEST(SolverLimits, OutOfRangeLimitsAreInputErrors) {
  ExtrusionParams p = test::growth_params(3, 0.1, 1.2);
  p.solver_limits.max_skewness = -1.0;
  EXPECT_THROW(check_extrusion_params(p), InputError);
  p = test::growth_params(3, 0.1, 1.2);
  p.solver_limits.max_non_orthogonality_deg = 181.0;
  EXPECT_THROW(check_extrusion_params(p), InputError);
  p = test::growth_params(3, 0.1, 1.2);
  p.solver_limits.max_face_warp_deg = -5.0;
  EXPECT_THROW(check_extrusion_params(p), InputError);
  p = test::growth_params(3, 0.1, 1.2);
  EXPECT_NO_THROW(check_extrusion_params(p));
}

}  // namespace
}  // namespace blayer
