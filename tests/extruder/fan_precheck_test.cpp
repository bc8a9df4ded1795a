// The straight-layer precheck of fan points (extruder/src/fan_precheck.h) reuses the
// previous round's passes only where every column runs through the same points: its
// failing set is always the one a fresh precheck finds.
#include "fan_precheck.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "blayer/core/vertex_fans.h"
#include "blayer/extruder/column_plan.h"
#include "blayer/extruder/fan_layout.h"
#include "blayer/extruder/wall_planes.h"
#include "blayer/extruder/wall_topology.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

struct BoxWithFans {
  TriSurface box;
  ColumnLayout layout = build_column_layout(box, build_vertex_fans(box), FanParams{60.0, 30.0},
                                            NormalMethod::kMostNormal, std::vector<char>(box.points.size(), 0));
  WallTopology topo = build_column_topology(layout);
  WallPlanes planes{box, layout, topo};
  ExtrusionParams params;
  ColumnPlan plan = plan_with_first_height(0.05);

  explicit BoxWithFans(int subdivisions = 3) : box(test_surfaces::box({0, 0, 0}, {1, 1, 1}, subdivisions)) {}

  // Four layers growing by 1.5 from h1 on every column.
  ColumnPlan plan_with_first_height(double h1) const {
    GrowthLaw law;
    law.layers = 4;
    law.first_height = h1;
    law.growth_ratio = 1.5;
    return plan_columns(resolve_growth_law(law), std::vector<double>(layout.n_columns(), 1.0));
  }
  // Fan columns along their sector directions, the others along their face's normal.
  StepDirections directions() const {
    const int nc = layout.n_columns();
    StepDirections d;
    d.n = layout.direction;
    d.ok.assign(nc, 1);
    for (std::size_t f = 0; f < box.triangles.size(); ++f)
      for (int c : layout.front.triangles[f])
        if (!layout.in_fan[c]) d.n[c] = normalized(triangle_area_vector(box, box.triangles[f]));
    return d;
  }
  std::vector<int> fresh(const StepDirections& d) const {
    FanPrecheck p;
    return p.failing_points(box, layout, planes, d, plan, params);
  }
};

TEST(FanPrecheck, ReusedPassesGiveTheFailingSetOfAFreshCheck) {
  const BoxWithFans b;
  ASSERT_TRUE(b.layout.has_fans());
  const StepDirections straight = b.directions();
  // One column beside an edge of the top face turned into the solid: the cells on it
  // invert, and with them the fans of the edge points they touch.
  StepDirections turned = straight;
  int victim = -1;
  for (int c = 0; c < b.layout.n_columns() && victim < 0; ++c) {
    const Vec3& p = b.layout.front.points[c];
    if (!b.layout.in_fan[c] && p[2] == 1.0 && p[0] < 0.5 && p[1] < 0.5) victim = c;
  }
  ASSERT_GE(victim, 0);
  turned.n[victim] = Vec3{0.0, 0.0, -1.0};

  FanPrecheck rounds;
  const std::vector<int> first = rounds.failing_points(b.box, b.layout, b.planes, turned, b.plan, b.params);
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(first, b.fresh(turned));
  EXPECT_EQ(rounds.reused_elements(), 0u);

  const std::vector<int> second = rounds.failing_points(b.box, b.layout, b.planes, straight, b.plan, b.params);
  EXPECT_TRUE(second.empty()) << "a convex box's fans pass on straight columns";
  EXPECT_EQ(second, b.fresh(straight));
  EXPECT_GT(rounds.reused_elements(), 0u) << "the elements away from the turned column are the first round's";

  // A passing round marches next: it keeps nothing for another round.
  const std::vector<int> third = rounds.failing_points(b.box, b.layout, b.planes, turned, b.plan, b.params);
  EXPECT_EQ(rounds.reused_elements(), 0u);
  EXPECT_EQ(third, b.fresh(turned));

  // Taller layers: the same columns through other points, nothing is reused.
  BoxWithFans tall;
  tall.plan = tall.plan_with_first_height(0.2);
  const std::vector<int> fourth =
      rounds.failing_points(tall.box, tall.layout, tall.planes, turned, tall.plan, tall.params);
  EXPECT_EQ(rounds.reused_elements(), 0u);
  EXPECT_EQ(fourth, tall.fresh(turned));
}

TEST(FanPrecheck, LastRoundFindsAFailureWhereAFullCheckDoesAndKeepsNothing) {
  const BoxWithFans b;
  const StepDirections straight = b.directions();
  StepDirections turned = straight;
  // Every column of the top face turned into the solid: all its fans fail in layer 0.
  for (int c = 0; c < b.layout.n_columns(); ++c)
    if (b.layout.front.points[c][2] == 1.0) turned.n[c] = Vec3{0.0, 0.0, -1.0};
  const std::vector<int> full = b.fresh(turned);
  ASSERT_FALSE(full.empty());

  FanPrecheck rounds;
  const std::vector<int> last = rounds.failing_points(b.box, b.layout, b.planes, turned, b.plan, b.params, true);
  ASSERT_FALSE(last.empty());
  for (int w : last) EXPECT_TRUE(std::binary_search(full.begin(), full.end(), w)) << "point " << w;
  // The failing last round kept no records: the next round reuses nothing (after a
  // failing round that is not the last, it reuses the elements away from the top face).
  EXPECT_TRUE(rounds.failing_points(b.box, b.layout, b.planes, straight, b.plan, b.params).empty());
  EXPECT_EQ(rounds.reused_elements(), 0u);
  FanPrecheck not_last;
  not_last.failing_points(b.box, b.layout, b.planes, turned, b.plan, b.params);
  not_last.failing_points(b.box, b.layout, b.planes, straight, b.plan, b.params);
  EXPECT_GT(not_last.reused_elements(), 0u);

  EXPECT_TRUE(rounds.failing_points(b.box, b.layout, b.planes, straight, b.plan, b.params, true).empty());
}

// On a finer box the columns in the middle of a face belong to no fan element: the
// precheck does not follow them, and turning one changes no verdict, while a column
// beside an edge still fails its fans as a fresh check finds.
TEST(FanPrecheck, ColumnsOfNoFanElementChangeNoVerdict) {
  const BoxWithFans b(8);
  const StepDirections straight = b.directions();
  auto top_column_near = [&](double x, double y) {
    int best = -1;
    for (int c = 0; c < b.layout.n_columns(); ++c) {
      const Vec3& p = b.layout.front.points[c];
      if (b.layout.in_fan[c] || p[2] != 1.0) continue;
      if (best < 0 || std::hypot(p[0] - x, p[1] - y) < std::hypot(b.layout.front.points[best][0] - x,
                                                                  b.layout.front.points[best][1] - y))
        best = c;
    }
    return best;
  };
  const int centre = top_column_near(0.5, 0.5), beside_edge = top_column_near(0.1, 0.3);
  ASSERT_GE(centre, 0);
  for (std::size_t f = 0; f < b.box.triangles.size(); ++f) {
    const Triangle& t = b.layout.front.triangles[f];
    if (std::find(t.begin(), t.end(), centre) == t.end()) continue;
    for (int c : t) ASSERT_FALSE(b.layout.in_fan[c]) << "the centre column lies in a fan element";
  }
  StepDirections turned_centre = straight, turned_edge = straight;
  turned_centre.n[centre] = Vec3{0.0, 0.0, -1.0};
  turned_edge.n[beside_edge] = Vec3{0.0, 0.0, -1.0};
  ASSERT_FALSE(b.fresh(turned_edge).empty());

  FanPrecheck rounds;
  EXPECT_EQ(rounds.failing_points(b.box, b.layout, b.planes, turned_edge, b.plan, b.params), b.fresh(turned_edge));
  const std::vector<int> second =
      rounds.failing_points(b.box, b.layout, b.planes, turned_centre, b.plan, b.params);
  EXPECT_TRUE(second.empty());
  EXPECT_EQ(second, b.fresh(straight));
  EXPECT_GT(rounds.reused_elements(), 0u);
}

}  // namespace
}  // namespace blayer
