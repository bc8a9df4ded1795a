// The report does not depend on the order of the input: a surface read with its points
// renumbered and its triangles shuffled (each with its corners rotated) is the same
// surface, and its extrusion stops and limits the same number of columns for each
// reason. Where two limits tie (the downward height smoothing, the columns of a fan
// point stopping together), the reason follows a fixed order, not the input's.
#include <gtest/gtest.h>

#include <string>

#include "blayer/extruder/extrude_layers.h"
#include "blayer/io/prepare_surface.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

// Regression case 006 (a slot narrower than the layers, single columns as in its
// case.toml): collisions and wall gaps limit 399 of its 1,393 columns.
TEST(InputOrder, ShuffledThinSlotStopsAndLimitsTheSameColumnsPerReason) {
  const TriSurface slot = load_surface(std::string(BLAYER_CASES_DIR) + "/006_thin_slot/surface.stl", {}).surface;
  const ExtrusionParams p = test::growth_params(10, 0.004, 1.2);
  const ExtrusionReport base = extrude_layers(slot, p).report;
  ASSERT_GT(base.limited_columns[static_cast<int>(StopReason::kCollision)], 0);
  ASSERT_GT(base.limited_columns[static_cast<int>(StopReason::kWallGap)], 0);
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const ExtrusionReport r = extrude_layers(test::shuffled(slot, seed), p).report;
    EXPECT_EQ(r.stopped_columns, base.stopped_columns) << "seed " << seed;
    EXPECT_EQ(r.limited_columns, base.limited_columns) << "seed " << seed;
  }
}

// Two boxes facing each other across a gap narrower than the layers, with the default
// fans at their edges: the fan layout (sectors, sub-normals, strips, corners) is built
// from each point's triangles in the input's order, and the gap limits fan columns
// (proximity) and ends some (wall gap). A guard: this surface had no tie of reasons
// before the tie rules either.
TEST(InputOrder, ShuffledFacingBoxesGiveTheSameFansCellsAndReasons) {
  const double gap = 0.05;
  const TriSurface boxes = test_surfaces::merged(test_surfaces::box({0, 0, 0}, {1, 1, 1}, 3),
                                                 test_surfaces::box({1 + gap, 0, 0}, {2 + gap, 1, 1}, 3));
  ExtrusionParams p = test::growth_params(5, 0.01, 1.5);  // T = 0.13 > 0.45 x gap
  p.fan_angle_deg = 60.0;
  const ExtrusionResult base = extrude_layers(boxes, p);
  ASSERT_GT(base.report.fans.points, 0);
  ASSERT_GT(base.report.limited_columns[static_cast<int>(StopReason::kProximity)], 0);
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const ExtrusionResult r = extrude_layers(test::shuffled(boxes, seed), p);
    EXPECT_EQ(r.mesh.n_cells(), base.mesh.n_cells()) << "seed " << seed;
    EXPECT_EQ(r.report.fans.points, base.report.fans.points) << "seed " << seed;
    EXPECT_EQ(r.report.fans.columns, base.report.fans.columns) << "seed " << seed;
    EXPECT_EQ(r.report.fans.ridge_edges, base.report.fans.ridge_edges) << "seed " << seed;
    EXPECT_EQ(r.report.fans.corners, base.report.fans.corners) << "seed " << seed;
    EXPECT_EQ(r.report.fans.cells, base.report.fans.cells) << "seed " << seed;
    EXPECT_EQ(r.report.stopped_columns, base.report.stopped_columns) << "seed " << seed;
    EXPECT_EQ(r.report.limited_columns, base.report.limited_columns) << "seed " << seed;
  }
}

}  // namespace
}  // namespace blayer
