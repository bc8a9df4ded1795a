// Tests of the marching stages on their own: each pins one rule of extrude_layers.h on
// a small analytic surface, with the expected figure derived in the test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "blayer/extruder/column_heights.h"
#include "blayer/extruder/column_plan.h"
#include "blayer/extruder/wall_planes.h"
#include "blayer/extruder/fan_layout.h"
#include "blayer/extruder/front_checker.h"
#include "blayer/extruder/height_smoothing.h"
#include "blayer/extruder/layer_assembly.h"
#include "blayer/extruder/layer_cells.h"
#include "blayer/extruder/layer_steps.h"
#include "blayer/extruder/proximity_rays.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_topology.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

// The law without smoothing, direction repair or height ramps: the settling tests see
// the checker's verdict acted on directly.
ExtrusionParams unrepaired_params(int n, double h1, double r) {
  ExtrusionParams p = test::growth_params(n, h1, r);
  p.normal_smoothing_iterations = 0;
  p.direction_repair_passes = 0;
  p.height_smoothing_rings = 0;
  return p;
}

// A flat n x n grid of squares of the given spacing in z = 0, facing +z.
TriSurface flat_grid(int n, double spacing = 1.0) { return test::square_plate(n, n * spacing); }


TEST(WallTopology, GridTablesAreSortedAndComplete) {
  const TriSurface s = flat_grid(2);
  const WallTopology t = build_wall_topology(s);
  // Centre point 4 of the 3x3 grid: 6 triangles, 6 neighbours (the diagonal split adds 2).
  EXPECT_EQ(t.vertex_triangles.count(4), 6);
  EXPECT_EQ(t.vertex_neighbours.count(4), 6);
  EXPECT_TRUE(std::is_sorted(t.vertex_neighbours.begin(4), t.vertex_neighbours.end(4)));
  EXPECT_EQ(t.vertex_triangles.count(2), 1);  // corner (2,0): one triangle
  for (int v = 0; v < t.n_points(); ++v) EXPECT_TRUE(t.used[v]);
}

TEST(HeightSmoothing, LowSpotRampsBackByOneOverRingsPlusOnePerRing) {
  const TriSurface s = flat_grid(8);
  const WallTopology t = build_wall_topology(s);
  std::vector<double> f(t.n_points(), 1.0);
  std::vector<StopReason> why(t.n_points(), StopReason::kNone);
  const int centre = 4 * 9 + 4;
  f[centre] = 0.2;
  why[centre] = StopReason::kProximity;
  smooth_downward(t.vertex_neighbours, t.used, 3, &f, &why);
  // Ring distance 1 -> 0.2 + 0.25, 2 -> 0.7, 3 -> 0.95, beyond: untouched.
  EXPECT_DOUBLE_EQ(f[centre], 0.2);
  EXPECT_DOUBLE_EQ(f[centre + 1], 0.45);
  EXPECT_DOUBLE_EQ(f[centre + 2], 0.7);
  EXPECT_DOUBLE_EQ(f[centre + 3], 0.95);
  EXPECT_DOUBLE_EQ(f[centre + 4], 1.0);
  EXPECT_EQ(why[centre + 3], StopReason::kProximity);
  EXPECT_EQ(why[centre + 4], StopReason::kNone);
  for (double x : f) EXPECT_LE(x, 1.0);
}

// Two low spots either side of a point lower it to the same value; the reason it takes
// is the lower one whichever spot holds which reason (its neighbours are listed by
// point number, so the first one must not win the tie).
TEST(HeightSmoothing, TiedLowSpotsGiveTheLowestReasonWhicheverNeighbourComesFirst) {
  const TriSurface s = flat_grid(8);
  const WallTopology t = build_wall_topology(s);
  const int centre = 4 * 9 + 4, left = centre - 1, right = centre + 1;
  for (const bool collision_left : {true, false}) {
    std::vector<double> f(t.n_points(), 1.0);
    std::vector<StopReason> why(t.n_points(), StopReason::kNone);
    f[left] = f[right] = 0.2;
    why[left] = collision_left ? StopReason::kCollision : StopReason::kProximity;
    why[right] = collision_left ? StopReason::kProximity : StopReason::kCollision;
    smooth_downward(t.vertex_neighbours, t.used, 3, &f, &why);
    EXPECT_DOUBLE_EQ(f[centre], 0.45);
    EXPECT_EQ(why[centre], StopReason::kCollision) << "collision on the " << (collision_left ? "left" : "right");
  }
}

// A limited point whose own value a neighbour's bound only ties keeps its own reason,
// even a higher one.
TEST(HeightSmoothing, ANeighbourThatOnlyTiesAPointsOwnValueLeavesItsReason) {
  const TriSurface s = flat_grid(8);
  const WallTopology t = build_wall_topology(s);
  const int centre = 4 * 9 + 4;
  std::vector<double> f(t.n_points(), 1.0);
  std::vector<StopReason> why(t.n_points(), StopReason::kNone);
  f[centre - 1] = 0.2;
  why[centre - 1] = StopReason::kCollision;
  f[centre] = f[centre - 1] + 1.0 / 4;  // the neighbour's bound over 3 rings, to the bit
  why[centre] = StopReason::kProximity;
  smooth_downward(t.vertex_neighbours, t.used, 3, &f, &why);
  EXPECT_EQ(why[centre], StopReason::kProximity);
}

// The smoothing by its definition: `rings` passes over every masked point, each from
// the values and reasons of the pass before (the oracle of the passes that visit only
// the points around the low ones).
void smooth_every_point(const Csr& nbr, const std::vector<char>& mask, int rings, std::vector<double>* f,
                        std::vector<StopReason>* reason) {
  const double slope = 1.0 / (rings + 1);
  for (int r = 0; r < rings; ++r) {
    std::vector<double> g = *f;
    std::vector<StopReason> rg = *reason;
    for (int v = 0; v < static_cast<int>(f->size()); ++v) {
      if (!mask[v]) continue;
      bool lowered = false;
      for (const int* u = nbr.begin(v); u != nbr.end(v); ++u) {
        if (!mask[*u]) continue;
        const double bound = (*f)[*u] + slope;
        if (bound < g[v]) {
          g[v] = bound;
          rg[v] = (*reason)[*u];
          lowered = true;
        } else if (lowered && bound == g[v] && (*reason)[*u] < rg[v]) {
          rg[v] = (*reason)[*u];
        }
      }
    }
    *f = g;
    *reason = rg;
  }
}

// Few low spots (the repair attempts' case: only their rings are visited) and many (every
// point is), on values in steps of the slope so that ties are frequent, with points
// left out of the mask, a value above the others and NaN: to the bit as the oracle.
TEST(HeightSmoothing, FewOrManyLowSpotsSmoothExactlyAsPassesOverEveryPoint) {
  const TriSurface s = flat_grid(30);
  const WallTopology t = build_wall_topology(s);
  const int n = t.n_points();
  std::mt19937 rng(47);
  for (const int rings : {1, 3})
    for (const int low_spots : {0, 1, 5, 40, 400}) {
      const double slope = 1.0 / (rings + 1);
      std::vector<double> f(n, 1.0);
      std::vector<StopReason> why(n, StopReason::kNone);
      std::vector<char> mask(n, 1);
      std::uniform_int_distribution<int> at(0, n - 1), steps(1, 2 * rings + 2), reason(1, 5);
      for (int i = 0; i < low_spots; ++i) {
        const int v = at(rng);
        f[v] = 1.0 - slope * steps(rng);
        why[v] = static_cast<StopReason>(reason(rng));
      }
      for (int i = 0; i < n / 20; ++i) mask[at(rng)] = 0;
      f[at(rng)] = std::nan("");
      // A point above the others by less than the slope, lowered by a neighbour one slope
      // below the others, which is low against it only.
      const int high = at(rng), below = *t.vertex_neighbours.begin(high);
      f[high] = 1.0 + slope / 2;
      f[below] = 1.0 - slope;
      mask[high] = mask[below] = 1;
      std::vector<double> expected = f;
      std::vector<StopReason> expected_why = why;
      smooth_every_point(t.vertex_neighbours, mask, rings, &expected, &expected_why);
      smooth_downward(t.vertex_neighbours, mask, rings, &f, &why);
      int changed = 0, differ = 0;
      for (int v = 0; v < n; ++v) {
        const bool same_value = std::isnan(expected[v]) ? std::isnan(f[v]) : expected[v] == f[v];
        differ += !same_value || expected_why[v] != why[v];
        changed += expected[v] < 1.0;
      }
      EXPECT_EQ(differ, 0) << rings << " rings, " << low_spots << " low spots";
      EXPECT_LE(f[high], 1.0);  // lowered by its neighbour at least
      if (low_spots > 0) {
        EXPECT_GT(changed, low_spots / 2);
      }
    }
}

TEST(ProximityRays, RayTriangleDistanceIsExactAndMissesOutside) {
  const Vec3 a{0, 0, 1}, b{1, 0, 1}, c{0, 1, 1};
  EXPECT_DOUBLE_EQ(ray_triangle_distance({0.2, 0.2, 0}, {0, 0, 1}, a, b, c, 10.0), 1.0);
  EXPECT_EQ(ray_triangle_distance({0.2, 0.2, 0}, {0, 0, 1}, a, b, c, 0.5), HUGE_VAL);   // beyond t_max
  EXPECT_EQ(ray_triangle_distance({0.8, 0.8, 0}, {0, 0, 1}, a, b, c, 10.0), HUGE_VAL);  // outside
  EXPECT_EQ(ray_triangle_distance({0.2, 0.2, 0}, {1, 0, 0}, a, b, c, 10.0), HUGE_VAL);  // parallel
}

// Two parallel plates facing each other across a gap: the lower one faces +z, the
// upper one -z.
TriSurface facing_plates(double gap) {
  TriSurface lower = flat_grid(4);
  TriSurface upper = flat_grid(4);
  for (Vec3& p : upper.points) p[2] = gap;
  for (Triangle& t : upper.triangles) std::swap(t[1], t[2]);
  const int base = static_cast<int>(lower.points.size());
  for (const Vec3& p : upper.points) lower.points.push_back(p);
  for (Triangle t : upper.triangles) lower.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  return lower;
}

TEST(ColumnHeights, WallGapFitsColumnsFacingAnotherWallIntoTheSafetyShare) {
  const double gap = 1.0;
  const TriSurface wall = facing_plates(gap);
  const WallTopology topo = build_wall_topology(wall);
  ExtrusionParams p = test::growth_params(4, 0.05, 2.0);  // 0.05 0.1 0.2 0.4: T = 0.75 > 0.45 x gap
  p.height_smoothing_rings = 0;
  const ResolvedGrowthLaw law = resolve_growth_law(p.growth);
  const StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  FrontChecker checker(wall, build_wall_topology(wall), true);
  const ColumnPlan plan = plan_column_heights(wall, topo, topo, law, p, d, checker.wall_rays());
  const int centre = 2 * 5 + 2;
  EXPECT_EQ(plan.limit[centre], StopReason::kWallGap);
  EXPECT_EQ(plan.planned_layers[centre], 4);
  EXPECT_DOUBLE_EQ(plan.height(centre, 0), 0.05);
  EXPECT_NEAR(plan.remaining(centre, 0), p.proximity_safety * gap, 1e-12);
}

// The plan's rays against the previous attempt's: a column whose ray is the same takes
// the remembered gap, one whose direction changed casts its own, and the plan is the one
// computed without a memo either way.
TEST(ColumnHeights, RememberedWallGapsGiveThePlanOfFreshRays) {
  const TriSurface wall = facing_plates(1.0);
  const WallTopology topo = build_wall_topology(wall);
  ExtrusionParams p = test::growth_params(4, 0.05, 2.0);
  p.height_smoothing_rings = 0;  // the centre's own gap decides its limit
  const ResolvedGrowthLaw law = resolve_growth_law(p.growth);
  const StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  FrontChecker checker(wall, build_wall_topology(wall), true);
  auto same_plan = [](const ColumnPlan& a, const ColumnPlan& b) {
    return a.planned_layers == b.planned_layers && a.limit == b.limit && a.target_total == b.target_total &&
           a.heights == b.heights;
  };
  WallGapMemo memo;
  const ColumnPlan first = plan_column_heights(wall, topo, topo, law, p, d, checker.wall_rays(), &memo);
  EXPECT_EQ(memo.reused, 0);
  EXPECT_TRUE(same_plan(first, plan_column_heights(wall, topo, topo, law, p, d, checker.wall_rays())));

  // The centre column of the lower plate turned away from the upper one: its gap is
  // cast again and differs (no wall ahead), the others are remembered.
  const int centre = 2 * 5 + 2;
  StepDirections tilted = d;
  tilted.n[centre] = normalized(Vec3{1.0, 0.0, 0.05});
  const ColumnPlan second = plan_column_heights(wall, topo, topo, law, p, tilted, checker.wall_rays(), &memo);
  const long ok = std::count(d.ok.begin(), d.ok.end(), 1);
  EXPECT_EQ(memo.reused, ok - 1);
  EXPECT_TRUE(same_plan(second, plan_column_heights(wall, topo, topo, law, p, tilted, checker.wall_rays())));
  EXPECT_EQ(first.limit[centre], StopReason::kWallGap);
  EXPECT_NE(second.limit[centre], StopReason::kWallGap);
}

TEST(ColumnPlan, CompressionSolvesTheLargestRatioThatFits) {
  ResolvedGrowthLaw law = resolve_growth_law(GrowthLaw{5, 1.0, 2.0, 0.0, 0.0, false});  // 1 2 4 8 16
  ColumnPlan plan = plan_columns(law, {1.0});
  ASSERT_TRUE(compress_from(&plan, 0, 2, 12.0, StopReason::kProximity));  // layers 2..4 from p = 2
  // 2 (r + r^2 + r^3) = 12 -> r^3 + r^2 + r - 6 = 0 -> r = 1.5761...
  const double r = plan.height(0, 2) / 2.0;
  EXPECT_NEAR(r * r * r + r * r + r, 6.0, 1e-12);
  EXPECT_NEAR(plan.remaining(0, 2), 12.0, 1e-12);
  EXPECT_NEAR(plan.height(0, 3), 2.0 * r * r, 1e-12);
  EXPECT_EQ(plan.height(0, 0), 1.0);
  EXPECT_EQ(plan.height(0, 1), 2.0);
  EXPECT_EQ(plan.planned_layers[0], 5);
  EXPECT_EQ(plan.limit[0], StopReason::kProximity);
  EXPECT_FALSE(compress_from(&plan, 0, 2, 20.0, StopReason::kQuality)) << "fits: no change";
}

TEST(ColumnPlan, UniformLayersAreTheLastResortBeforeEnding) {
  ResolvedGrowthLaw law = resolve_growth_law(GrowthLaw{5, 1.0, 2.0, 0.0, 0.0, false});
  ColumnPlan plan = plan_columns(law, {1.0});
  ASSERT_TRUE(compress_from(&plan, 0, 0, 3.5, StopReason::kWallGap));  // 5 x 1 > 3.5
  EXPECT_EQ(plan.planned_layers[0], 3);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(plan.height(0, k), 1.0);
  ColumnPlan tiny = plan_columns(law, {1.0});
  ASSERT_TRUE(compress_from(&tiny, 0, 0, 0.9, StopReason::kWallGap));  // below the first height
  EXPECT_EQ(tiny.planned_layers[0], 0);
}

TEST(ColumnPlan, LoweringALayerRestartsTheGrowthFromIt) {
  ResolvedGrowthLaw law = resolve_growth_law(GrowthLaw{4, 1.0, 2.0, 0.0, 0.0, false});  // 1 2 4 8
  ColumnPlan plan = plan_columns(law, {1.0});
  lower_layer(&plan, 0, 2, 1.5, StopReason::kQuality);
  EXPECT_EQ(plan.height(0, 2), 1.5);
  EXPECT_EQ(plan.height(0, 3), 3.0);
  EXPECT_EQ(plan.limit[0], StopReason::kQuality);
  EXPECT_EQ(plan.target_total[0], 15.0);
}

// A fan point of three columns, two of which stop in the same step for different
// reasons: the third, and the report, take the lower reason whichever column comes first.
TEST(FanGroups, ColumnsStoppedTogetherPassOnTheLowestReasonWhicheverComesFirst) {
  ResolvedGrowthLaw law = resolve_growth_law(GrowthLaw{4, 1.0, 2.0, 0.0, 0.0, false});
  for (const bool quality_first : {true, false}) {
    WallTopology topo;
    topo.group_columns.start = {0, 3};
    topo.group_columns.items = {0, 1, 2};
    ColumnPlan plan = plan_columns(law, {1.0, 1.0, 1.0});
    ColumnState columns = ColumnState::on_wall(std::vector<Vec3>(3, Vec3{0, 0, 0}), std::vector<char>(3, 1));
    columns.stop(quality_first ? 0 : 1, StopReason::kQuality);
    columns.stop(quality_first ? 1 : 0, StopReason::kProximity);
    std::vector<char> grows{0, 0, 1};
    stop_fan_groups(2, topo, &plan, &columns, &grows);
    EXPECT_TRUE(columns.stopped[2]);
    EXPECT_EQ(grows[2], 0);
    EXPECT_EQ(columns.reason[2], StopReason::kQuality) << (quality_first ? "quality first" : "proximity first");
    EXPECT_EQ(plan.planned_layers[2], 2);
  }
}

TEST(StepDirections, SmoothingNeverLowersVisibilityBelowTheRawDirection) {
  const TriSurface wall = test::icosphere(2, 1.0);
  const WallTopology topo = build_wall_topology(wall);
  ExtrusionParams raw = test::growth_params(1, 0.01, 1.0), smooth = raw;
  raw.normal_smoothing_iterations = 0;
  smooth.normal_smoothing_iterations = 3;
  const StepDirections a = compute_step_directions(wall, topo, topo.used, raw);
  const StepDirections b = compute_step_directions(wall, topo, topo.used, smooth);
  for (int v = 0; v < topo.n_points(); ++v) {
    ASSERT_TRUE(b.ok[v]);
    EXPECT_GE(b.visibility[v], a.visibility[v]) << v;
    EXPECT_NEAR(visibility_of(b, topo, v, b.n[v]), b.visibility[v], 1e-15);
  }
}

// The memo of a run's wall normals: a point's stored normal is taken while its fan is
// bitwise unchanged, and solved again (to the memo-free answer) once a point of its fan
// moves. Every fan is stored; drop_cheap keeps only those of kMemoMinValence or more
// triangles: the uv sphere's two poles (16).
TEST(StepDirections, MemoReusesAPointsNormalOnlyWhileItsFanIsUnchanged) {
  TriSurface wall = test_surfaces::uv_sphere(8, 16, 1.0, 0.0);
  const WallTopology topo = build_wall_topology(wall);
  const ExtrusionParams p = test::growth_params(1, 0.01, 1.0);
  std::vector<int> poles;
  for (int v = 0; v < topo.n_points(); ++v)
    if (topo.fans.fans[v].ring.size() >= kMemoMinValence) poles.push_back(v);
  ASSERT_EQ(poles.size(), 2u);
  auto same = [](const StepDirections& a, const StepDirections& b) {
    return a.n == b.n && a.visibility == b.visibility && a.ok == b.ok;
  };
  const long n = topo.n_points();
  WallNormalMemo memo;
  EXPECT_TRUE(same(compute_step_directions(wall, topo, topo.used, p, nullptr, &memo),
                   compute_step_directions(wall, topo, topo.used, p)));
  EXPECT_EQ(memo.reused, 0);
  EXPECT_EQ(memo.solved, n);
  EXPECT_TRUE(same(compute_step_directions(wall, topo, topo.used, p, nullptr, &memo),
                   compute_step_directions(wall, topo, topo.used, p)));
  EXPECT_EQ(memo.reused, n);
  // One ring point of the first pole moves: the fans that hold it (its own, the pole's
  // and those of its other neighbours) are solved again, every other one is reused.
  const int moved_point = topo.fans.fans[poles[0]].ring[0];
  const long holding = 1 + static_cast<long>(topo.fans.fans[moved_point].ring.size());
  wall.points[moved_point][2] *= 1.01;
  const long solved = memo.solved;
  const StepDirections moved = compute_step_directions(wall, topo, topo.used, p, nullptr, &memo);
  EXPECT_TRUE(same(moved, compute_step_directions(wall, topo, topo.used, p)));
  EXPECT_EQ(memo.solved - solved, holding);
  EXPECT_EQ(memo.reused, 2 * n - holding);
  // Only the poles survive drop_cheap.
  memo.drop_cheap();
  const long reused = memo.reused;
  EXPECT_TRUE(same(compute_step_directions(wall, topo, topo.used, p, nullptr, &memo),
                   compute_step_directions(wall, topo, topo.used, p)));
  EXPECT_EQ(memo.reused - reused, 2);
}

TEST(StepDirections, RepairTurnsAFailingColumnTowardsItsNeighbours) {
  const TriSurface wall = flat_grid(2);
  const WallTopology topo = build_wall_topology(wall);
  ExtrusionParams p = test::growth_params(1, 0.1, 1.0);
  p.normal_smoothing_iterations = 0;
  StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  const int centre = 4;
  d.n[centre] = normalized(Vec3{0.5, 0.0, 1.0});  // leans sideways
  d.visibility[centre] = visibility_of(d, topo, centre, d.n[centre]);
  std::vector<char> bad(topo.n_points(), 0), grows(topo.n_points(), 1);
  std::vector<char> bad_tri(wall.triangles.size(), 1);
  bad[centre] = 1;
  const std::vector<char> turned = turn_failing_columns(wall.triangles, topo, bad, bad_tri, grows, 0.05, &d);
  EXPECT_TRUE(turned[centre]);
  EXPECT_EQ(std::count(turned.begin(), turned.end(), 1), 1);
  // The new direction is the normalised sum over the incident triangles' columns, which
  // lean less than the failing one.
  EXPECT_GT(d.n[centre][2], normalized(Vec3{0.5, 0.0, 1.0})[2]);
}

// A first layer on a flat grid: every column on the wall, all grown 0.1 up.
struct FlatFirstLayer {
  TriSurface wall;
  std::vector<Vec3> top, next;
  std::vector<int> layers;
  std::vector<char> grows;
  explicit FlatFirstLayer(int n) : wall(flat_grid(n)), top(wall.points), next(wall.points) {
    layers.assign(top.size(), 0);
    grows.assign(top.size(), 1);
    for (Vec3& p : next) p[2] = 0.1;
  }
};

TEST(FrontChecker, FlagsAnInvertedCellAndOnlyItsColumns) {
  FlatFirstLayer f(2);
  auto& [wall, top, next, layers, grows] = f;
  FrontChecker checker(wall, build_wall_topology(wall), true);
  checker.begin_layer(0, top, layers);
  FrontVerdict v;
  checker.check(0, top, next, grows, &v);
  EXPECT_FALSE(v.any_bad);
  next[4] = {1.0, 1.0, -0.1};  // the centre column dips below the wall
  checker.check(1, top, next, grows, &v);
  EXPECT_TRUE(v.any_bad);
  EXPECT_TRUE(v.bad[4]);
  EXPECT_EQ(v.reason[4], StopReason::kQuality);
  // Only the columns of the six triangles around the centre are flagged; corner (0,0)
  // shares no triangle with it... except through the diagonal split: point 0's only
  // triangles are (0,1,4) and (0,4,3), so it is flagged; point 2's is (1,2,5): not.
  EXPECT_FALSE(v.bad[2]);
  EXPECT_FALSE(v.bad[6]);
}

TEST(FrontChecker, IncrementalAttemptsGiveTheVerdictOfAFreshCheck) {
  FlatFirstLayer f(3);
  auto& [wall, top, next, layers, grows] = f;
  next[5] = {1.0, 1.0, -0.05};
  FrontChecker incremental(wall, build_wall_topology(wall), true);
  incremental.begin_layer(0, top, layers);
  FrontVerdict first, second, fresh;
  incremental.check(0, top, next, grows, &first);
  ASSERT_TRUE(first.any_bad);
  next[5] = {1.0, 1.0, 0.1};  // repaired
  next[10] = {2.0, 2.0, -0.05};  // and another column broken
  incremental.check(1, top, next, grows, &second);
  FrontChecker full(wall, build_wall_topology(wall), true);
  full.begin_layer(0, top, layers);
  full.check(0, top, next, grows, &fresh);
  EXPECT_EQ(second.bad, fresh.bad);
  EXPECT_EQ(second.bad_triangle, fresh.bad_triangle);
}

// Lower plate centre of facing_plates(0.5), pushed through the upper plate alone.
constexpr int kPlateCentre = 2 * 5 + 2;

FrontVerdict push_plate_centre_through_the_other(const TriSurface& wall, FrontChecker* checker) {
  std::vector<Vec3> top = wall.points, next = wall.points;
  std::vector<int> layers(top.size(), 0);
  std::vector<char> grows(top.size(), 0);
  grows[kPlateCentre] = 1;
  next[kPlateCentre][2] = 0.8;
  checker->begin_layer(0, top, layers);
  FrontVerdict v;
  checker->check(0, top, next, grows, &v);
  return v;
}

TEST(FrontChecker, FlagsANewFrontThatCrossesTheOtherWall) {
  const TriSurface wall = facing_plates(0.5);
  FrontChecker checker(wall, build_wall_topology(wall), true);
  const FrontVerdict v = push_plate_centre_through_the_other(wall, &checker);
  EXPECT_TRUE(v.bad[kPlateCentre]);
  EXPECT_EQ(v.reason[kPlateCentre], StopReason::kCollision);
}

// The run's wall tree, shared by the fan attempts: a checker borrowing it finds the
// crossing that only the wall's triangles can reveal (the upper plate does not grow),
// and releasing the checker leaves the tree to its owner.
TEST(FrontChecker, ABorrowedWallTreeFindsTheCrossingAndOutlivesTheChecker) {
  const TriSurface wall = facing_plates(0.5);
  const WallTree shared(wall);
  FrontChecker checker(wall, single_column_layout(wall), build_wall_topology(wall), true, &shared);
  const FrontVerdict v = push_plate_centre_through_the_other(wall, &checker);
  EXPECT_TRUE(v.bad[kPlateCentre]);
  EXPECT_EQ(v.reason[kPlateCentre], StopReason::kCollision);
  checker.release();
  const ProximityRays rays = wall_proximity_rays(wall.triangles, wall.points, shared);
  EXPECT_DOUBLE_EQ(rays.first_hit(kPlateCentre, wall.points[kPlateCentre], {0.0, 0.0, 1.0}, 1.0), 0.5);
}

TEST(LayerSteps, StepsReachThePlannedHeightAboveTheWallPlanes) {
  const TriSurface wall = test::icosphere(2, 1.0);
  const WallTopology topo = build_wall_topology(wall);
  const WallPlanes planes(wall, single_column_layout(wall), topo);
  const ExtrusionParams p = test::growth_params(3, 0.01, 1.2);
  const ResolvedGrowthLaw law = resolve_growth_law(p.growth);
  const StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  const ColumnPlan plan = plan_columns(law, std::vector<double>(wall.points.size(), 1.0));
  const ColumnState c = ColumnState::on_wall(wall.points, topo.used);
  const std::vector<double> s = layer_steps(0, plan, planes, d, c, p);
  for (int v = 0; v < topo.n_points(); ++v)
    EXPECT_NEAR(planes.height_above(v, wall.points[v] + s[v] * d.n[v]), 0.01, 1e-15) << v;
}

TEST(LayerSteps, ProximityCompressesTheRemainingLayersIntoTheGapShare) {
  const double gap = 1.0;
  const TriSurface wall = facing_plates(gap);
  const WallTopology topo = build_wall_topology(wall);
  const WallPlanes planes(wall, single_column_layout(wall), topo);
  ExtrusionParams p = test::growth_params(3, 0.3, 1.0);  // T = 0.9 > 0.45
  p.height_smoothing_rings = 0;
  const ResolvedGrowthLaw law = resolve_growth_law(p.growth);
  const StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  ColumnPlan plan = plan_columns(law, std::vector<double>(wall.points.size(), 1.0));
  ColumnState c = ColumnState::on_wall(wall.points, topo.used);
  FrontChecker checker(wall, build_wall_topology(wall), true);
  checker.begin_layer(0, c.top, c.layers);
  limit_by_proximity(0, checker.front_rays(), topo, planes, d, p, &plan, &c);
  const int centre = 2 * 5 + 2;
  // 3 x 0.3 does not fit into 0.45 with ratio >= 1: one layer of 0.3 remains.
  EXPECT_EQ(plan.planned_layers[centre], 1);
  EXPECT_EQ(plan.limit[centre], StopReason::kProximity);
  EXPECT_FALSE(c.stopped[centre]);
  p.limit_policy = LimitPolicy::kTerminate;
  ColumnPlan plan2 = plan_columns(law, std::vector<double>(wall.points.size(), 1.0));
  ColumnState c2 = ColumnState::on_wall(wall.points, topo.used);
  limit_by_proximity(0, checker.front_rays(), topo, planes, d, p, &plan2, &c2);
  EXPECT_EQ(plan2.planned_layers[centre], 1);
}

TEST(LayerSteps, AFirstLayerThatCannotBeMadeValidIsNotGrown) {
  const TriSurface wall = flat_grid(4);
  const WallTopology topo = build_wall_topology(wall);
  const WallPlanes planes(wall, single_column_layout(wall), topo);
  ExtrusionParams p = unrepaired_params(2, 0.5, 1.0);
  const ResolvedGrowthLaw law = resolve_growth_law(p.growth);
  StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  const int centre = 2 * 5 + 2;
  // Leans so far that a step 0.5 above the wall moves it 1.5 sideways, past its
  // neighbour one unit away.
  d.n[centre] = normalized(Vec3{3.0, 0.0, 1.0});
  ColumnPlan plan = plan_columns(law, std::vector<double>(wall.points.size(), 1.0));
  ColumnState c = ColumnState::on_wall(wall.points, topo.used);
  FrontChecker checker(wall, build_wall_topology(wall), true);
  checker.begin_layer(0, c.top, c.layers);
  std::vector<Vec3> next(wall.points.size());
  const std::vector<char> grows = settle_layer(0, wall.triangles, topo, planes, p, &checker, &d, &plan, &c, &next);
  EXPECT_FALSE(grows[centre]);
  EXPECT_EQ(c.reason[centre], StopReason::kQuality);
  EXPECT_EQ(plan.planned_layers[centre], 0);
  // The first height is never lowered: every column that grows stands at h1.
  for (int v = 0; v < topo.n_points(); ++v) {
    if (grows[v]) {
      EXPECT_NEAR(planes.height_above(v, next[v]), 0.5, 1e-15) << v;
    }
  }
}

TEST(LayerSteps, AFailingUpperLayerIsLoweredBeforeTheColumnEnds) {
  const TriSurface wall = flat_grid(4);
  const WallTopology topo = build_wall_topology(wall);
  const WallPlanes planes(wall, single_column_layout(wall), topo);
  ExtrusionParams p = unrepaired_params(2, 0.1, 4.0);  // layer 1 planned at 0.4
  const ResolvedGrowthLaw law = resolve_growth_law(p.growth);
  StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  const int centre = 2 * 5 + 2;
  ColumnPlan plan = plan_columns(law, std::vector<double>(wall.points.size(), 1.0));
  ColumnState c = ColumnState::on_wall(wall.points, topo.used);
  for (int v = 0; v < topo.n_points(); ++v) {  // after a first layer of 0.1
    c.top[v] = wall.points[v] + Vec3{0.0, 0.0, 0.1};
    c.layers[v] = 1;
  }
  // The centre column leans by 45 degrees: a step of 0.4 x sqrt 2 moves it 0.4 sideways,
  // across its neighbour one unit away only at heights above ~1; make the neighbour
  // spacing effectively 0.25 by leaning harder.
  d.n[centre] = normalized(Vec3{4.0, 0.0, 1.0});
  FrontChecker checker(wall, build_wall_topology(wall), true);
  checker.begin_layer(1, c.top, c.layers);
  std::vector<Vec3> next(wall.points.size());
  const std::vector<char> grows = settle_layer(1, wall.triangles, topo, planes, p, &checker, &d, &plan, &c, &next);
  ASSERT_TRUE(grows[centre]) << "lowered, not ended";
  EXPECT_LT(plan.height(centre, 1), 0.4);
  EXPECT_GE(plan.height(centre, 1), 0.1);
  EXPECT_EQ(plan.limit[centre], StopReason::kQuality);
  EXPECT_NEAR(planes.height_above(centre, next[centre]), 0.1 + plan.height(centre, 1), 1e-12);
}

// A repair attempt recomputes only the steps of the columns it turned, lowered or
// stopped; the front it settles on must still be every column's step from its final
// direction and heights (its top for the columns that stopped), to the bit. Leaning
// columns get turned; under a slanted plate above the wall (which does not grow) the
// columns are lowered, and those at their first height stopped.
TEST(LayerSteps, TheSettledFrontIsEveryColumnsStepFromItsFinalDirectionAndHeights) {
  TriSurface wall = flat_grid(10);
  const int plate = static_cast<int>(wall.points.size());
  for (const Vec3& q : {Vec3{5.5, 5.5, 0.12}, Vec3{8.5, 5.5, 0.5}, Vec3{8.5, 8.5, 0.5}, Vec3{5.5, 8.5, 0.12}})
    wall.points.push_back(q);
  wall.triangles.push_back({plate, plate + 2, plate + 1});
  wall.triangles.push_back({plate, plate + 3, plate + 2});
  const WallTopology topo = build_wall_topology(wall);
  const WallPlanes planes(wall, single_column_layout(wall), topo);
  ExtrusionParams p = unrepaired_params(3, 0.1, 2.0);  // layer 1 planned at 0.2, first height 0.1
  p.direction_repair_passes = 2;
  p.height_smoothing_rings = 2;
  const ResolvedGrowthLaw law = resolve_growth_law(p.growth);
  StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  ColumnPlan plan = plan_columns(law, std::vector<double>(wall.points.size(), 1.0));
  ColumnState c = ColumnState::on_wall(wall.points, topo.used);
  for (int v = 0; v < plate; ++v) {  // after a first layer of 0.1
    c.top[v] = wall.points[v] + Vec3{0.0, 0.0, 0.1};
    c.layers[v] = 1;
  }
  for (int v = plate; v < plate + 4; ++v) c.stop(v, StopReason::kQuality);
  d.n[2 * 11 + 2] = normalized(Vec3{20.0, 3.0, 1.0});
  d.n[2 * 11 + 7] = normalized(Vec3{0.0, -6.0, 1.0});
  const StepDirections before = d;
  FrontChecker checker(wall, build_wall_topology(wall), true);
  checker.begin_layer(1, c.top, c.layers);
  std::vector<Vec3> next(wall.points.size());
  const std::vector<char> grows = settle_layer(1, wall.triangles, topo, planes, p, &checker, &d, &plan, &c, &next);
  const std::vector<double> step = layer_steps(1, plan, planes, d, c, p);
  int turned = 0, lowered = 0, stopped = 0;
  for (int v = 0; v < plate; ++v) {
    // A turn that mends a column lets it grow at its planned height.
    turned += !(d.n[v] == before.n[v]) && grows[v] && plan.height(v, 1) == 0.2;
    lowered += grows[v] && plan.height(v, 1) < 0.2;
    stopped += !grows[v];
    const Vec3 expected = grows[v] ? c.top[v] + step[v] * d.n[v] : c.top[v];
    EXPECT_TRUE(next[v] == expected) << v;
  }
  EXPECT_GT(turned, 0);
  EXPECT_GT(lowered, 0);
  EXPECT_GT(stopped, 0);
}

TEST(LayerAssembly, CellTypesFollowHowManyColumnsGrow) {
  const TriSurface wall = flat_grid(1);  // 4 points, 2 triangles (0,1,3) and (0,3,2)
  const WallTopology topo = build_wall_topology(wall);
  ExtrusionParams p = test::growth_params(1, 0.1, 1.0);
  const StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  ColumnState c = ColumnState::on_wall(wall.points, topo.used);
  LayerAssembler a(wall, d);
  std::vector<Vec3> next = wall.points;
  for (Vec3& q : next) q[2] = 0.1;
  a.commit_layer(0, {1, 1, 0, 1}, next, d, &c);  // (0,1,3) wedge; (0,3,2) pyramid
  EXPECT_EQ(c.layers, (std::vector<int>{1, 1, 0, 1}));
  EXPECT_EQ(c.top_id[3], 6);
  VolumeMesh m = a.take_mesh();
  a.attach_arrays(c, &m);
  ASSERT_EQ(m.n_cells(), 2u);
  EXPECT_EQ(m.cell_types[0], CellType::kWedge);
  EXPECT_EQ(m.cell_types[1], CellType::kPyramid);
  EXPECT_EQ(m.points.size(), 7u);
  EXPECT_EQ(a.columns_per_layer(), std::vector<int>{3});
  EXPECT_NE(m.find_point_array("column_height"), nullptr);
  EXPECT_DOUBLE_EQ(m.find_point_array("column_height")->values[4], 0.1);  // point 4 = top of column 0
}

TEST(LayerAssembly, CellsOfAFrontOfManyElementsFollowTheElementOrder) {
  // 39,200 wall triangles: the layer's cells are built in blocks of elements, a few
  // blocks at a time, and the mesh must be the one an element-by-element loop builds
  // (the oracle below).
  const TriSurface wall = flat_grid(140);
  const WallTopology topo = build_wall_topology(wall);
  const ExtrusionParams p = test::growth_params(3, 0.1, 1.0);
  StepDirections d = compute_step_directions(wall, topo, topo.used, p);
  // Every column a direction of its own, so that the normals show whose they are.
  for (std::size_t v = 0; v < d.n.size(); ++v) d.n[v] = normalized(Vec3{0.01 * (v % 7), 0.01 * (v % 5), 1.0});
  const ColumnLayout layout = single_column_layout(wall);
  ColumnState c = ColumnState::on_wall(wall.points, topo.used);
  LayerAssembler a(wall, d);
  std::mt19937 rng(7);
  std::vector<char> grows(wall.points.size(), 1);
  std::vector<CellType> types;
  std::vector<std::int64_t> ids, offsets{0};
  std::vector<double> layer;
  std::int64_t n_points = static_cast<std::int64_t>(wall.points.size());
  std::vector<Vec3> points = wall.points;
  std::vector<int> point_column(wall.points.size());
  std::iota(point_column.begin(), point_column.end(), 0);
  for (int k = 0; k < 3; ++k) {
    // Columns stop at random, a fifth of those still growing per layer.
    for (char& g : grows) g = g && rng() % 5 != 0;
    std::vector<std::int64_t> new_top(grows.size(), -1);
    for (std::size_t v = 0; v < grows.size(); ++v)
      if (grows[v]) {
        new_top[v] = n_points++;
        points.push_back(c.top[v] + Vec3{0.0, 0.0, 0.1});
        point_column.push_back(static_cast<int>(v));
      }
    for (const LayerElement& e : layout.elements) {
      LayerCell cells[2];
      const int n = element_layer_cells(
          e, [&](int col) { return c.top_id[col]; }, [&](int col) { return new_top[col]; },
          [&](int col) { return grows[col] != 0; }, cells);
      for (int i = 0; i < n; ++i) {
        types.push_back(cells[i].type);
        for (int j = 0; j < corner_count(cells[i].type); ++j) ids.push_back(cells[i].nodes[j]);
        offsets.push_back(static_cast<std::int64_t>(ids.size()));
        layer.push_back(k);
      }
    }
    std::vector<Vec3> next = c.top;
    for (Vec3& q : next) q[2] += 0.1;
    a.commit_layer(k, grows, next, d, &c);
  }
  VolumeMesh m = a.take_mesh();
  a.attach_arrays(c, &m);
  ASSERT_GT(layout.elements.size(), 2u * 8u * 2048u);  // more than two waves of eight blocks a layer
  EXPECT_EQ(m.cell_types, types);
  EXPECT_EQ(m.offsets, offsets);
  ASSERT_EQ(m.connectivity.size(), ids.size());
  EXPECT_TRUE(std::equal(ids.begin(), ids.end(), m.connectivity.begin()));
  EXPECT_EQ(static_cast<std::int64_t>(m.points.size()), n_points);
  EXPECT_TRUE(m.points == points);
  EXPECT_EQ(a.point_column(), point_column);
  const DataArray* normal = m.find_point_array("normal");
  ASSERT_NE(normal, nullptr);
  ASSERT_EQ(normal->values.size(), 3 * points.size());
  for (std::size_t q = 0; q < points.size(); ++q)
    for (int i = 0; i < 3; ++i)
      ASSERT_EQ(normal->values[3 * q + i], static_cast<float>(d.n[point_column[q]][i])) << q;
  const DataArray* cell_layer = m.find_cell_array("layer");
  ASSERT_NE(cell_layer, nullptr);
  ASSERT_EQ(cell_layer->values.size(), layer.size());
  for (std::size_t i = 0; i < layer.size(); ++i) ASSERT_EQ(cell_layer->values[i], layer[i]) << i;
  EXPECT_EQ(a.fan_cells(), 0);
}

}  // namespace
}  // namespace blayer

namespace blayer {
namespace {

TEST(TriangleBvh, SegmentsWithNegativeZeroComponentsFindBoxesOnTheirOriginsPlane) {
  // Boxes whose y range ends exactly at the ray's origin y: the ray runs along their
  // face. A direction of (-1, -0, 0) must see them as (-1, +0, 0) does.
  std::vector<Box> boxes{{{0.0, 0.5, 0.0}, {0.1, 0.75, 1.0}}, {{0.0, 0.75, 0.0}, {0.1, 1.0, 1.0}}};
  TriangleBvh tree;
  tree.build(boxes);
  for (const Vec3& dir : {Vec3{-1.0, 0.0, 0.0}, Vec3{-1.0, -0.0, 0.0}, Vec3{-1.0, 0.0, -0.0}}) {
    int seen = 0;
    tree.for_each_on_segment({1.0, 0.75, 0.5}, dir, 2.0, [&](int, double*) { ++seen; });
    EXPECT_EQ(seen, 2) << dir[1];
  }
}

}  // namespace
}  // namespace blayer
