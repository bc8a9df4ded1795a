// Most-normal warm starts of the recomputed directions (step_directions.h,
// FrontWarmStarts): they carry only visibility-constrained optima from front to front,
// they give the directions of cold solves, and the march reports how often their
// certificate held. The surface is regression case 010 (an inward T-junction), whose
// junction fans are visibility-constrained.
#include <gtest/gtest.h>

#include <string>

#include "blayer/extruder/extrude_layers.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_topology.h"
#include "blayer/io/prepare_surface.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

TriSurface t_junction() {
  return load_surface(std::string(BLAYER_CASES_DIR) + "/010_t_junction_inward/surface.stl", {}).surface;
}

// The front h above the wall along the wall's directions (unit, or zero where a column
// has none).
TriSurface offset_front(const TriSurface& wall, const StepDirections& d, double h) {
  TriSurface front = wall;
  for (std::size_t v = 0; v < front.points.size(); ++v) front.points[v] += h * d.n[v];
  return front;
}

ExtrusionParams recomputed_params() {
  ExtrusionParams p = test::growth_params(3, 0.01, 1.2);
  p.column_directions = ColumnDirections::kRecomputed;
  return p;
}

TEST(FrontWarmStarts, CarryOnlyVisibilityConstrainedOptima) {
  const TriSurface wall = t_junction();
  const WallTopology topo = build_wall_topology(wall);
  FrontWarmStarts warm;
  compute_step_directions(wall, topo, topo.used, recomputed_params(), nullptr, nullptr, &warm);
  EXPECT_EQ(warm.counts.warm, 0);  // nothing to start from on the wall
  int carried = 0;
  for (int v = 0; v < topo.n_points(); ++v) {
    if (!warm.by_column[v].valid) continue;
    ++carried;
    EXPECT_EQ(surface_point_normal(wall, topo, v, NormalMethod::kMostNormal).status,
              NormalStatus::kVisibilityConstrained)
        << "point " << v;
  }
  // The case's junction fans: 58 points are constrained on this wall, some of them
  // with no reflex link vertex (their optimum is the most visible normal: nothing to
  // carry).
  EXPECT_GT(carried, 20);
}

TEST(FrontWarmStarts, GiveTheDirectionsOfColdSolvesOnTheNextFront) {
  const TriSurface wall = t_junction();
  const WallTopology topo = build_wall_topology(wall);
  const ExtrusionParams p = recomputed_params();
  FrontWarmStarts warm;
  const StepDirections on_wall = compute_step_directions(wall, topo, topo.used, p, nullptr, nullptr, &warm);
  long carried = 0;
  for (const MostNormalWarmStart& w : warm.by_column) carried += w.valid;
  const TriSurface front = offset_front(wall, on_wall, 0.01);
  const StepDirections cold = compute_step_directions(front, topo, topo.used, p);
  const StepDirections hot = compute_step_directions(front, topo, topo.used, p, nullptr, nullptr, &warm);
  EXPECT_EQ(warm.counts.warm, carried);
  EXPECT_GT(warm.counts.hits, 0);
  EXPECT_LE(warm.counts.hits, warm.counts.warm);
  for (int v = 0; v < topo.n_points(); ++v) {
    EXPECT_EQ(hot.ok[v], cold.ok[v]) << "point " << v;
    EXPECT_LE(angle_between(hot.n[v], cold.n[v]), 1e-12) << "point " << v;
  }
}

TEST(FrontWarmStarts, RecomputedMarchReportsItsHitRateAndKeptReportsNone) {
  const TriSurface wall = t_junction();
  const ExtrusionResult recomputed = extrude_layers(wall, recomputed_params());
  EXPECT_GT(recomputed.report.n_warm_starts, 0);
  EXPECT_GT(recomputed.report.n_warm_hits, 0);
  EXPECT_LE(recomputed.report.n_warm_hits, recomputed.report.n_warm_starts);
  ExtrusionParams kept = recomputed_params();
  kept.column_directions = ColumnDirections::kKept;
  const ExtrusionResult straight = extrude_layers(wall, kept);
  EXPECT_EQ(straight.report.n_warm_starts, 0);
}

}  // namespace
}  // namespace blayer
