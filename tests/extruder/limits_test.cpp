// The limit rules of extrude_layers.h on a block with a slot one cell wide: the first
// height is kept, a limit compresses the upper layers (N layers, no ratio above the
// law's, none below 1) and ends a column only when even uniform layers do not fit.
#include <gtest/gtest.h>

#include <cmath>

#include "blayer/extruder/extrude_layers.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

constexpr double kCell = 0.25;  // slot width: the gap between its two walls
// Heights follow from a step formula exact up to rounding (a few ulps of 1e-1).
constexpr double kHeightTol = 1e-12;

// A block 9 x 6 x 6 cells with a slot one cell wide and five deep (x in [1, 1.25], z in
// [0.25, 1.5]): columns in the middle of the slot wall are three rings from its floor,
// its mouth and the block's faces.
TriSurface slotted_block() {
  return test::voxel_surface({9, 6, 6}, [](int i, int, int k) { return !(i == 4 && k >= 1); }, kCell);
}


// Points of every column, wall point first (layer by layer, columns in index order:
// the order in which the extruder appends them).
std::vector<std::vector<Vec3>> column_points(const TriSurface& wall, const ExtrusionResult& r) {
  const int nv = static_cast<int>(wall.points.size());
  std::vector<std::vector<Vec3>> c(nv);
  for (int v = 0; v < nv; ++v) c[v].push_back(wall.points[v]);
  std::size_t next = wall.points.size();
  for (int k = 0; next < r.mesh.points.size(); ++k)
    for (int v = 0; v < nv; ++v)
      if (r.column_layers[v] > k) c[v].push_back(r.mesh.points[next++]);
  return c;
}

// Wall points in the middle of the slot's left wall (x = 4 cells): each column there
// faces the right wall one cell away.
std::vector<int> mid_slot_columns(const TriSurface& wall) {
  std::vector<int> ids;
  for (int v = 0; v < static_cast<int>(wall.points.size()); ++v) {
    const Vec3& w = wall.points[v];
    if (w[0] == 4 * kCell && w[2] == 3 * kCell && w[1] == 3 * kCell) ids.push_back(v);
  }
  return ids;
}

// Layer heights of a column on the slot's left wall: the x steps (the wall is x = const
// and the columns there go straight in +x).
std::vector<double> x_heights(const std::vector<Vec3>& column) {
  std::vector<double> h;
  for (std::size_t i = 1; i < column.size(); ++i) h.push_back(column[i][0] - column[i - 1][0]);
  return h;
}

TEST(LayerLimits, WallGapCompressesTheUpperLayersAndKeepsTheFirstHeight) {
  const TriSurface wall = slotted_block();
  const ExtrusionParams p = test::growth_params(5, 0.02, 1.3);  // T = 0.181 > 0.45 x 0.25; 5 x h1 = 0.1 fits
  const ExtrusionResult r = extrude_layers(wall, p);
  const auto columns = column_points(wall, r);
  const std::vector<int> mid = mid_slot_columns(wall);
  ASSERT_FALSE(mid.empty());
  for (int v : mid) {
    ASSERT_EQ(r.column_layers[v], 5) << "compression keeps N layers; stopped: " << stop_reason_name(r.stop_reason[v]);
    const std::vector<double> h = x_heights(columns[v]);
    EXPECT_NEAR(h[0], 0.02, kHeightTol) << "first height";
    double total = 0.0;
    for (std::size_t k = 0; k < h.size(); ++k) {
      total += h[k];
      if (k > 0) {
        EXPECT_LE(h[k] / h[k - 1], 1.3 + 1e-12) << "no ratio above the law's";
        EXPECT_GE(h[k] / h[k - 1], 1.0 - 1e-12) << "no layer below the one under it";
      }
    }
    EXPECT_LE(total, p.proximity_safety * kCell + kHeightTol);
    EXPECT_LT(h.back() / h[h.size() - 2], 1.3 - 1e-3) << "the ratio is really compressed";
  }
  EXPECT_GT(r.report.limited_columns[static_cast<int>(StopReason::kWallGap)], 0);
  EXPECT_FALSE(r.report.complete());
  EXPECT_NE(thickness_warning(r.report).find("wall_gap"), std::string::npos);
  EXPECT_EQ(extrusion_report_to_json(r.report)["verdict"]["outcome"], "limited");
}

TEST(LayerLimits, ColumnsEndOnlyWhenEvenUniformLayersDoNotFit) {
  const TriSurface wall = slotted_block();
  // 5 x h1 = 0.15 > 0.1125: three layers of h1 fit (0.09), a fourth does not.
  const ExtrusionResult r = extrude_layers(wall, test::growth_params(5, 0.03, 1.2));
  const auto columns = column_points(wall, r);
  for (int v : mid_slot_columns(wall)) {
    ASSERT_EQ(r.column_layers[v], 3) << stop_reason_name(r.stop_reason[v]) << " at y " << wall.points[v][1];
    for (double h : x_heights(columns[v])) EXPECT_NEAR(h, 0.03, kHeightTol);
    EXPECT_EQ(r.stop_reason[v], StopReason::kWallGap);
  }
}

TEST(LayerLimits, TerminateKeepsTheLawsHeightsAndEndsAtTheLimit) {
  const TriSurface wall = slotted_block();
  ExtrusionParams p = test::growth_params(5, 0.02, 1.3);
  p.limit_policy = LimitPolicy::kTerminate;
  const ExtrusionResult r = extrude_layers(wall, p);
  const auto columns = column_points(wall, r);
  // Cumulative law heights 0.02, 0.046, 0.0798, 0.12374: three fit into 0.1125.
  for (int v : mid_slot_columns(wall)) {
    ASSERT_EQ(r.column_layers[v], 3) << stop_reason_name(r.stop_reason[v]) << " at y " << wall.points[v][1];
    const std::vector<double> h = x_heights(columns[v]);
    EXPECT_NEAR(h[0], 0.02, kHeightTol);
    EXPECT_NEAR(h[1], 0.026, kHeightTol);
    EXPECT_NEAR(h[2], 0.0338, kHeightTol);
  }
}

TEST(LayerLimits, AGapBelowTheFirstHeightOverTheSafetyGrowsNoLayer) {
  const TriSurface wall = slotted_block();
  const ExtrusionResult r = extrude_layers(wall, test::growth_params(3, 0.12, 1.2));  // 0.12 > 0.1125
  for (int v : mid_slot_columns(wall)) {
    EXPECT_EQ(r.column_layers[v], 0);
    EXPECT_EQ(r.stop_reason[v], StopReason::kWallGap);
  }
  // Outside the slot the first layer is grown at its height.
  EXPECT_NEAR(r.report.first_height.max, 0.12, kHeightTol);
}

TEST(LayerLimits, FreeColumnsKeepTheLawExactly) {
  const TriSurface wall = test::voxel_surface({2, 2, 2}, [](int, int, int) { return true; }, kCell);
  const ExtrusionResult r = extrude_layers(wall, test::growth_params(4, 0.01, 1.25));
  const auto columns = column_points(wall, r);
  EXPECT_TRUE(r.report.complete());
  EXPECT_TRUE(thickness_warning(r.report).empty());
  // A face-centre point of the x = 0.5 face grows straight in +x by the law.
  for (int v = 0; v < static_cast<int>(wall.points.size()); ++v) {
    const Vec3& w = wall.points[v];
    if (!(w[0] == 2 * kCell && w[1] == kCell && w[2] == kCell)) continue;
    const std::vector<double> h = x_heights(columns[v]);
    ASSERT_EQ(h.size(), 4u);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(h[k], 0.01 * std::pow(1.25, k), kHeightTol) << k;
  }
}

TEST(LayerLimits, AspectRatioLayerEndStopsTallLayers) {
  const TriSurface wall = test::voxel_surface({2, 2, 2}, [](int, int, int) { return true; }, kCell);
  ExtrusionParams p = test::growth_params(6, 0.02, 1.5);  // heights 0.02 0.03 0.045 0.0675 ...
  // Mean wall edge at a face centre: 4 x 0.25 and 2 x 0.25 sqrt 2 -> 0.285; x 0.2 = 0.057.
  p.max_layer_aspect = 0.2;
  const ExtrusionResult r = extrude_layers(wall, p);
  for (int v = 0; v < static_cast<int>(wall.points.size()); ++v) {
    const Vec3& w = wall.points[v];
    if (!(w[0] == 2 * kCell && w[1] == kCell && w[2] == kCell)) continue;
    EXPECT_EQ(r.column_layers[v], 3);
    EXPECT_EQ(r.stop_reason[v], StopReason::kAspectRatio);
  }
  EXPECT_GT(r.report.stopped_columns[static_cast<int>(StopReason::kAspectRatio)], 0);
}

}  // namespace
}  // namespace blayer
