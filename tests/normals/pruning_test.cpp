// The pruned enumeration (most_normal_by_pruned_enumeration, the previous default: the
// great-circle screen of the point-point-arc and point-arc-arc families) against the
// unpruned enumeration (most_normal_by_enumeration) on nearly flat fans: wing-skin vertices where a few
// junctions are reflex and D* is close to 90 degrees, the fans the screen is for, plus
// the generic random shapes. The pruning discards only candidates the evaluation would
// reject, so the answers agree to rounding.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "blayer/normals/most_normal.h"
#include "random_fans.h"
#include "test_fans.h"

namespace blayer {
namespace {

using testing_fans::Shape;

// The bound shortcut (taken by the pruned enumeration only, where D* reaches the link-vertex
// bound, i.e. D* >= 90 degrees) answers within normality_tie and kSameDirection of the
// enumeration (fast_path_test.cpp); below 90 degrees only the pruning differs, and the
// two agree to rounding.
constexpr double kSameNormality = 1e-12;
constexpr double kSameDirection = 1e-7;

void expect_same(const FanGeometry& g, bool constrained, const std::string& what) {
  const MostNormalResult pruned = most_normal_by_pruned_enumeration(g, default_tolerances(), constrained);
  const MostNormalResult full = most_normal_by_enumeration(g, default_tolerances(), constrained);
  ASSERT_EQ(pruned.status, full.status) << what;
  const bool shortcut_reach = full.normality >= 0.5 * M_PI - default_tolerances().normality_tie;
  EXPECT_NEAR(pruned.normality, full.normality, shortcut_reach ? default_tolerances().normality_tie : kSameNormality)
      << what;
  if (pruned.status == NormalStatus::kOk) {
    EXPECT_LE(angle_between(pruned.normal, full.normal), kSameDirection) << what;
  } else {
    EXPECT_GE(pruned.visibility, full.visibility - kSameDirection) << what;
  }
}

TEST(MostNormalPruning, MatchesEnumerationOnNearFlatFans) {
  std::mt19937 rng(4711);
  int n = 0, below_right_angle = 0;
  for (int t = 0; t < 6000; ++t) {
    const FanGeometry g = testing_fans::geometry(testing_fans::near_flat_fan(rng));
    if (g.any_degenerate) continue;
    ++n;
    for (bool constrained : {false, true}) expect_same(g, constrained, "near-flat fan " + std::to_string(t));
    below_right_angle += most_normal_by_enumeration(g).normality < 0.5 * M_PI ? 1 : 0;
  }
  EXPECT_GT(n, 5000);
  // The fans the pruning is for: beyond the reach of the D* > 90 degree shortcut.
  EXPECT_GT(below_right_angle, 1000);
}

TEST(MostNormalPruning, MatchesEnumerationOnRandomShapes) {
  for (Shape shape : {Shape::kConvex, Shape::kConcave, Shape::kSaddle, Shape::kSliver, Shape::kWild}) {
    std::mt19937 rng(1234u + static_cast<unsigned>(shape));
    for (int t = 0; t < 200; ++t) {
      const FanGeometry g = testing_fans::geometry(testing_fans::random_fan(rng, shape));
      if (g.any_degenerate) continue;
      for (bool constrained : {false, true})
        expect_same(g, constrained, std::string(testing_fans::shape_name(shape)) + " fan " + std::to_string(t));
    }
  }
}

}  // namespace
}  // namespace blayer
