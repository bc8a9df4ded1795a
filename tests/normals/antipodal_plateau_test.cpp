// The plateau of an antipodal pair of link vertices (normals/src/antipodal_plateau.h):
// the straight ridges of docs/normals.md against their analytic plateaus and
// tie-breaks, the fans it must leave to the other passes, and the CAD-like sliver fans
// exactly as drawn (whose spanwise neighbours line up) against the enumeration, with
// and without the visibility constraint.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "agreement_test_support.h"
#include "antipodal_plateau.h"
#include "blayer/normals/most_normal.h"
#include "blayer/normals/most_visible.h"
#include "cad_fans.h"
#include "candidate_pool.h"
#include "test_fans.h"

namespace blayer {
namespace {

using testing_fans::deg;

// Direction at angle psi (degrees) in the plane y = 0, from +x towards +z.
Vec3 in_xz(double psi) { return {std::cos(deg(psi)), 0.0, std::sin(deg(psi))}; }

bool holds_direction(const std::vector<detail::Maximizer>& maxima, const Vec3& n) {
  for (const detail::Maximizer& m : maxima)
    if (angle_between(m.n, n) <= 1e-12) return true;
  return false;
}

// docs/normals.md, section 6: the plateau (psi from +x towards +z in y = 0, D = 90
// degrees) of each straight ridge and the tie-broken normal, the largest V on it.
TEST(AntipodalPlateau, StraightRidgesGiveTheirAnalyticPlateausAndTieBreaks) {
  struct Ridge {
    int fan;
    double psi_from, psi_to;
    Vec3 normal;
    double v;
  };
  const std::vector<Ridge> ridges = {{3, 0.0, 90.0, in_xz(45.0), std::sqrt(0.5)},
                                     {4, -75.0, 75.0, in_xz(0.0), std::sin(deg(15.0))},
                                     {6, -85.0, 85.0, in_xz(0.0), std::sin(deg(5.0))}};
  const auto fans = testing_fans::public_fans();
  for (const Ridge& ridge : ridges) {
    const FanGeometry g = testing_fans::geometry(fans[ridge.fan].ring);
    const char* name = fans[ridge.fan].name;
    // Unconstrained, so that the plateau's ends, where V is lowest, are maximisers too.
    detail::CandidatePool pool(g, default_tolerances(), false, 0.0);
    ASSERT_TRUE(detail::antipodal_plateau_settles(&pool)) << name;
    EXPECT_TRUE(holds_direction(pool.maximizers(), in_xz(ridge.psi_from))) << name;
    EXPECT_TRUE(holds_direction(pool.maximizers(), in_xz(ridge.psi_to))) << name;
    for (const detail::Maximizer& m : pool.maximizers()) {
      EXPECT_LE(std::fabs(m.n[1]), 1e-12) << name << ": off the plateau circle";
      EXPECT_NEAR(m.d, 0.5 * M_PI, 1e-12) << name;
    }
    const MostNormalResult r = pool.pick(pool.unconstrained_maxima_distinct());
    EXPECT_EQ(r.status, NormalStatus::kNonUnique) << name;
    EXPECT_LE(angle_between(r.normal, ridge.normal), 1e-12) << name;
    EXPECT_NEAR(r.visibility, ridge.v, 1e-12) << name;
  }
}

// T1, a flat fan, holds an antipodal pair (azimuths 50 and 230 degrees) whose other link
// vertices all project onto one line of the plateau circle's plane: the two single
// directions +z and -z, of which +z is fluid and unique.
TEST(AntipodalPlateau, FlatFanSettlesOnItsSingleFluidDirection) {
  const FanGeometry g = testing_fans::geometry(testing_fans::public_fans()[0].ring);
  detail::CandidatePool pool(g, default_tolerances(), true, 0.5);
  ASSERT_TRUE(detail::antipodal_plateau_settles(&pool));
  const MostNormalResult r = pool.pick(pool.unconstrained_maxima_distinct());
  EXPECT_EQ(r.status, NormalStatus::kOk);
  EXPECT_LE(angle_between(r.normal, Vec3{0.0, 0.0, 1.0}), 1e-12);
  EXPECT_NEAR(r.normality, 0.5 * M_PI, 1e-12);
}

// Fans without an antipodal pair of link vertices (checked here pair by pair) get no
// candidate from it.
TEST(AntipodalPlateau, OffersNothingWithoutAnAntipodalPair) {
  const auto fans = testing_fans::public_fans();
  for (int i : {1, 2, 8, 10}) {
    const FanGeometry g = testing_fans::geometry(fans[i].ring);
    for (std::size_t a = 0; a < g.dirs.size(); ++a)
      for (std::size_t b = a + 1; b < g.dirs.size(); ++b) ASSERT_GT(norm(g.dirs[a] + g.dirs[b]), 1e-3) << fans[i].name;
    detail::CandidatePool pool(g, default_tolerances(), true, 0.0);
    EXPECT_FALSE(detail::antipodal_plateau_settles(&pool)) << fans[i].name;
    EXPECT_EQ(pool.n_candidates(), 0) << fans[i].name;
  }
}

// T6 (a concave ridge), T8 (a monkey saddle) and T10 (a cube on a floor) hold antipodal
// link vertices, but their optimum is 45, 63.4 and 45 degrees: nothing reaches the
// pair's bound of 90, and the other passes go on.
TEST(AntipodalPlateau, DoesNotSettleBelowTheBound) {
  const auto fans = testing_fans::public_fans();
  for (int i : {5, 7, 9}) {
    const FanGeometry g = testing_fans::geometry(fans[i].ring);
    detail::CandidatePool pool(g, default_tolerances(), true, 0.0);
    EXPECT_FALSE(detail::antipodal_plateau_settles(&pool)) << fans[i].name;
    EXPECT_LT(pool.best_unconstrained(), 0.5 * M_PI - 0.1) << fans[i].name;
  }
}

// CAD-like sliver fans exactly as drawn: the spanwise neighbours at x = 0 on both sides
// are antipodal, D = 90 degrees along a plateau that the default solver now takes
// directly (no subdivision cell), and the answers agree with the enumeration's.
TEST(AntipodalPlateau, SliverFansAsDrawnMatchTheEnumeration) {
  std::mt19937 rng(2024u);
  int n = 0;
  for (int k : {12, 16, 20})
    for (int t = 0; t < 4; ++t) {
      const FanGeometry g =
          testing_fans::geometry(testing_fans::cad_like_fan(rng, testing_fans::CadShape::kSliver, k, 0.0));
      if (g.any_degenerate) continue;
      ++n;
      for (bool constrained : {true, false}) {
        const MostNormalResult a = most_normal_normal(g, default_tolerances(), constrained);
        const MostNormalResult b = most_normal_by_enumeration(g, default_tolerances(), constrained);
        const std::string what = "valence " + std::to_string(k) + " draw " + std::to_string(t);
        EXPECT_EQ(a.n_cells, 0) << what;
        EXPECT_EQ(a.status, NormalStatus::kNonUnique) << what;
        EXPECT_TRUE(testing_fans::same_optimum(g, constrained, a, b)) << what;
      }
    }
  EXPECT_GE(n, 10);
}

// Where the plateau fails the visibility constraint (nearly invisible sliver fans of
// valence 28), it settles the unconstrained optimum only: the constrained one is then
// sought without the cells that fail the constraint all over, and still agrees with
// the enumeration's.
TEST(AntipodalPlateau, InvisiblePlateauLeavesTheConstrainedOptimumToTheSubdivision) {
  std::mt19937 rng(2024u);
  int n = 0;
  for (int t = 0; t < 60 && n < 3; ++t) {
    const FanGeometry g =
        testing_fans::geometry(testing_fans::cad_like_fan(rng, testing_fans::CadShape::kSliver, 28, 0.0));
    if (g.any_degenerate) continue;
    const MostNormalResult a = most_normal_normal(g);
    if (a.status != NormalStatus::kVisibilityConstrained) continue;
    const MostVisibleResult mv = most_visible_normal(g.face_normals);
    detail::CandidatePool pool(g, default_tolerances(), true, 0.5 * mv.visibility);
    EXPECT_FALSE(detail::antipodal_plateau_settles(&pool)) << "draw " << t;
    if (pool.best_unconstrained() < 0.5 * M_PI - 1e-9) continue;  // no plateau at 90 degrees
    ++n;
    const MostNormalResult b = most_normal_by_enumeration(g);
    EXPECT_TRUE(testing_fans::same_optimum(g, true, a, b)) << "draw " << t;
  }
  EXPECT_EQ(n, 3);
}

}  // namespace
}  // namespace blayer
