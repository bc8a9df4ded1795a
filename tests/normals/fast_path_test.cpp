// The shortcuts of the pruned enumeration (most_normal_by_pruned_enumeration, the
// previous default) against the plain candidate enumeration (most_normal_by_enumeration)
// on the fans they are meant for: convex corners and
// vertices of smoothly convex, nearly developable surfaces (wing skins), where some
// junctions are not reflex yet D* > pi/2, plus the generic random shapes, where the
// shortcut must stay out of the way.
#include <gtest/gtest.h>

#include <random>

#include "blayer/normals/most_normal.h"
#include "random_fans.h"
#include "test_fans.h"

namespace blayer {
namespace {

// A candidate within normality_tie of the optimum lies within tie / kSharpFalloff of it
// (most_normal.cpp): the two answers may differ by that much in direction, no more.
constexpr double kSameDirection = 1e-7;

bool all_junctions_reflex(const FanGeometry& g) {
  const int k = g.n_faces();
  for (int j = 0; j < k; ++j)
    if (!(dot(g.face_normals[(j + k - 1) % k], g.dirs[(j + 1) % k]) < -default_tolerances().coplanar_arc))
      return false;
  return true;
}

// Compares the two solvers on one fan; returns whether the shortcut answered.
bool expect_same(const FanGeometry& g, bool constrained, const std::string& what) {
  const MostNormalResult fast = most_normal_by_pruned_enumeration(g, default_tolerances(), constrained);
  const MostNormalResult full = most_normal_by_enumeration(g, default_tolerances(), constrained);
  EXPECT_EQ(fast.status, full.status) << what;
  EXPECT_NEAR(fast.normality, full.normality, default_tolerances().normality_tie) << what;
  if (fast.status == NormalStatus::kOk) {
    EXPECT_LE(angle_between(fast.normal, full.normal), kSameDirection) << what;
  } else {
    EXPECT_GE(fast.visibility, full.visibility - kSameDirection) << what;
  }
  return fast.n_candidates < full.n_candidates;
}

TEST(MostNormalShortcut, MatchesEnumerationOnConvexSkins) {
  std::mt19937 rng(2024);
  int shortcut_not_all_reflex = 0, n = 0;
  for (int t = 0; t < 3000; ++t) {
    const FanGeometry g = testing_fans::geometry(testing_fans::skin_fan(rng));
    if (g.any_degenerate) continue;
    ++n;
    for (bool constrained : {false, true}) {
      const bool shortcut = expect_same(g, constrained, "skin fan " + std::to_string(t));
      if (shortcut && !all_junctions_reflex(g)) ++shortcut_not_all_reflex;
    }
  }
  EXPECT_GT(n, 2500);
  // The generator must exercise the shortcut beyond convex corners.
  EXPECT_GT(shortcut_not_all_reflex, 500);
}

TEST(MostNormalShortcut, MatchesEnumerationOnPublicFans) {
  for (const testing_fans::TestFan& f : testing_fans::public_fans())
    expect_same(testing_fans::geometry(f.ring), true, f.name);
}

}  // namespace
}  // namespace blayer
