// The report does not depend on the order of the input: a surface read with its points
// renumbered and its triangles shuffled (each with its corners rotated) is the same
// surface, and its extrusion stops and limits the same number of columns for each
// reason. Where two limits tie (the downward height smoothing, the columns of a fan
// point stopping together), the reason follows a fixed order, not the input's.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <string>

#include "blayer/extruder/extrude_layers.h"
#include "blayer/io/prepare_surface.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

TriSurface shuffled(const TriSurface& s, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<int> to(s.points.size());
  std::iota(to.begin(), to.end(), 0);
  std::shuffle(to.begin(), to.end(), rng);
  TriSurface out;
  out.points.resize(s.points.size());
  for (std::size_t v = 0; v < s.points.size(); ++v) out.points[to[v]] = s.points[v];
  for (const Triangle& t : s.triangles) {
    const int r = static_cast<int>(rng() % 3);
    out.triangles.push_back({to[t[r]], to[t[(r + 1) % 3]], to[t[(r + 2) % 3]]});
  }
  std::shuffle(out.triangles.begin(), out.triangles.end(), rng);
  return out;
}

// Regression case 006 (a slot narrower than the layers, single columns as in its
// case.toml): collisions and wall gaps limit a third of its columns.
TEST(InputOrder, ShuffledThinSlotStopsAndLimitsTheSameColumnsPerReason) {
  const TriSurface slot = load_surface(std::string(BLAYER_CASES_DIR) + "/006_thin_slot/surface.stl", {}).surface;
  const ExtrusionParams p = test::growth_params(10, 0.004, 1.2);
  const ExtrusionReport base = extrude_layers(slot, p).report;
  ASSERT_GT(base.limited_columns[static_cast<int>(StopReason::kCollision)], 0);
  ASSERT_GT(base.limited_columns[static_cast<int>(StopReason::kWallGap)], 0);
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const ExtrusionReport r = extrude_layers(shuffled(slot, seed), p).report;
    EXPECT_EQ(r.stopped_columns, base.stopped_columns) << "seed " << seed;
    EXPECT_EQ(r.limited_columns, base.limited_columns) << "seed " << seed;
  }
}

}  // namespace
}  // namespace blayer
