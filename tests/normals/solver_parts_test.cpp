// The parts of the default most-normal solver on their own (white-box, normals/src):
// the candidate pool evaluates D and the fluid side as the references do,
// the subdivision over the whole sphere finds the enumeration's optimum on fans of every
// size (also where it sets invisible cells aside and where cell centres raise its
// floor), the link-vertex lens holds every sampled direction of its superlevel set, the
// lower envelope of V along a plateau circle peaks as high as all pairwise crossings do,
// the constraint pass's great-circle screen keeps every circle through a leaf, and the
// first direction at V_min on the way from n_MV is where a sampled arc first falls
// below it, its D never above the constrained optimum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "agreement_test_support.h"
#include "blayer/normals/most_normal.h"
#include "blayer/normals/most_visible.h"
#include "cad_fans.h"
#include "candidate_families.h"
#include "candidate_pool.h"
#include "fan_sites.h"
#include "link_vertex_lens.h"
#include "most_normal_enumeration.h"
#include "oracle.h"
#include "random_fans.h"
#include "site_subdivision.h"
#include "test_fans.h"
#include "visibility_boundary.h"

namespace blayer {
namespace {

using testing_fans::Shape;

// visit(geometry, label) for every non-degenerate fan of `per_shape` draws of each
// random shape, all from one stream.
template <class Visit>
void for_each_random_fan(std::mt19937& rng, int per_shape, Visit&& visit) {
  for (Shape shape : {Shape::kConvex, Shape::kConcave, Shape::kSaddle, Shape::kSliver, Shape::kWild})
    for (int t = 0; t < per_shape; ++t) {
      const FanGeometry g = testing_fans::geometry(testing_fans::random_fan(rng, shape));
      if (!g.any_degenerate) visit(g, std::string(testing_fans::shape_name(shape)) + " " + std::to_string(t));
    }
}

// The whole-sphere subdivision alone, as the default solver runs it on large fans: the
// figures of its pool and its statistics. False where it does not run (no visible
// direction, or no reflex vertex: MN = MV).
struct SubdivisionOutcome {
  double best_constrained, floor;
  bool limited;
  detail::SubdivisionStats stats;
};
bool run_subdivision(const FanGeometry& g, bool constrained, SubdivisionOutcome* out) {
  const MostVisibleResult mv = most_visible_normal(g.face_normals);
  if (!mv.feasible) return false;
  detail::CandidatePool pool(g, default_tolerances(), constrained, 0.5 * mv.visibility);
  detail::FanSites sites;
  detail::build_fan_sites(g, default_tolerances(), &sites);
  if (sites.points.empty()) return false;
  pool.consider(mv.normal);
  detail::SiteSubdivision subdivision(sites, &pool);
  subdivision.unconstrained_candidates();
  subdivision.remaining_passes();
  *out = {pool.best_constrained(), pool.floor(), pool.limited(), subdivision.stats()};
  return true;
}

// The whole-sphere subdivision alone (the default solver sends small fans to the
// screened enumeration instead) reaches the enumeration's optimum D.
TEST(SiteSubdivision, ReachesTheEnumerationOptimumOnAnyFan) {
  std::mt19937 rng(99);
  int n = 0;
  for_each_random_fan(rng, 150, [&](const FanGeometry& g, const std::string& label) {
    for (bool constrained : {true, false}) {
      SubdivisionOutcome run;
      if (!run_subdivision(g, constrained, &run)) continue;
      const MostNormalResult oracle = most_normal_by_enumeration(g, default_tolerances(), constrained);
      ++n;
      EXPECT_NEAR(run.best_constrained, oracle.normality, 1e-12) << label << (constrained ? " constrained" : " free");
      EXPECT_GE(run.stats.cells, 6);  // every cube face visited
    }
  });
  EXPECT_GT(n, 900);
}

// Cells invisible below V_min all over are set aside and taken up only while no direction
// beats the constrained optimum by more than the tie. The status and the constrained
// optimum must still be the enumeration's, whether a candidate settled the status with
// set-aside cells left unrefined, the set-aside cells showed the limit, or all of them
// were refined without one.
TEST(SiteSubdivision, SetAsideInvisibleCellsLeaveTheEnumerationStatus) {
  std::mt19937 rng(2718);
  int settled_early = 0, settled_by_set_aside = 0, exhausted = 0;
  testing_fans::for_each_cad_fan(rng, {12, 16, 20, 24}, 8, [&](const FanGeometry& g, const std::string& label) {
    SubdivisionOutcome run;
    if (!run_subdivision(g, true, &run)) return;
    const MostNormalResult oracle = most_normal_by_enumeration(g, default_tolerances(), true);
    // The enumeration's tie-break may pick a maximiser up to the tie below the best D.
    EXPECT_NEAR(run.best_constrained, oracle.normality, default_tolerances().normality_tie) << label;
    EXPECT_EQ(run.limited, oracle.status == NormalStatus::kVisibilityConstrained) << label;
    if (run.limited && run.stats.set_aside > run.stats.set_aside_refined) ++settled_early;
    if (run.limited && run.stats.set_aside_refined > 0) ++settled_by_set_aside;
    if (!run.limited && run.stats.set_aside_refined > 0) ++exhausted;
  });
  EXPECT_GT(settled_early, 10);
  EXPECT_GT(settled_by_set_aside, 0);
  EXPECT_GT(exhausted, 10);
}

// The constrained subdivision on the CAD-like fans of the given valences (per_shape of
// each shape and offset); where counter (a SubdivisionStats field) shows that a shortcut
// fired (probes that raised the floor, closed cells), the run must still reach the
// enumeration's optimum and status, and the default solver its tie-broken direction: a
// floor above every candidate would mean the candidates missed the optimum. Returns how
// many fans the shortcut fired on.
int check_fans_where_counted(unsigned seed, std::initializer_list<int> valences, int per_shape,
                             int detail::SubdivisionStats::*counter) {
  std::mt19937 rng(seed);
  int fired = 0;
  testing_fans::for_each_cad_fan(rng, valences, per_shape, [&](const FanGeometry& g, const std::string& label) {
    SubdivisionOutcome run;
    if (!run_subdivision(g, true, &run) || run.stats.*counter == 0) return;
    ++fired;
    EXPECT_GE(run.best_constrained, run.floor - default_tolerances().normality_tie) << label;
    const MostNormalResult oracle = most_normal_by_enumeration(g, default_tolerances(), true);
    EXPECT_NEAR(run.best_constrained, oracle.normality, default_tolerances().normality_tie) << label;
    EXPECT_EQ(run.limited, oracle.status == NormalStatus::kVisibilityConstrained) << label;
    EXPECT_TRUE(testing_fans::same_optimum(g, true, most_normal_normal(g), oracle)) << label;
  });
  return fired;
}

// Where the constraint binds, feasible cell centres far above the threshold raise the
// pool's floor during the refinement. The floor is an exact D, so the constrained
// optimum, the status and the tie-broken direction stay the enumeration's.
TEST(SiteSubdivision, CentresProbedAsFloorsLeaveTheEnumerationOptimum) {
  // Probes fire on a few per cent of the CAD-like fans of valence 24 and up.
  EXPECT_GT(check_fans_where_counted(4141, {24, 30}, 30, &detail::SubdivisionStats::floors_raised), 5);
}

// The probes fire also before any direction beats the constrained optimum, in cells that
// reach below V_min: a constrained optimum there may lie on a constraint circle, whose
// candidates come only after the refinement, while the leaves' candidates near the
// constraint are infeasible. The floors leave the optimum, the status and the
// tie-broken direction the enumeration's.
TEST(SiteSubdivision, CentresNearTheConstraintProbedAsFloorsLeaveTheEnumerationOptimum) {
  // They fire on about one CAD-like fan in a hundred of valence 24 to 40.
  EXPECT_GT(check_fans_where_counted(5150, {24, 30, 40}, 60, &detail::SubdivisionStats::floors_raised_unlimited), 5);
}

// A small cell whose site subsets were all enumerated, but for a few it enumerates
// itself, is closed instead of refined (on nearly flat fans, along their ridges of
// near-ties). Every maximiser in it is a candidate of one of those subsets, so the
// optimum, the status and the tie-broken direction stay the enumeration's.
TEST(SiteSubdivision, ClosedCellsLeaveTheEnumerationOptimum) {
  EXPECT_GT(check_fans_where_counted(6262, {30, 40}, 20, &detail::SubdivisionStats::closed), 50);
}

// A child cell whose parent's nearest arc is nearer than the threshold allows is dropped
// on that arc's distance alone, before the distances to all the kept arcs are taken. D
// is at most the distance to any arc, so the optimum, the status and the tie-broken
// direction stay the enumeration's.
TEST(SiteSubdivision, CellsDroppedByTheirParentsNearestArcLeaveTheEnumerationOptimum) {
  // It fires on most of the CAD-like fans of valence 20 and 30 (93 of these 120).
  EXPECT_GT(check_fans_where_counted(7373, {20, 30}, 5, &detail::SubdivisionStats::dropped_by_hint), 40);
}

// The pool's exact D at a direction agrees with the reference distance to the link, and
// its fluid side with the crossing-parity reference, on random directions and on the
// directions where two features nearly tie: the bisectors of link-vertex pairs and of
// arc pairs, exactly and moved off by 1e-13. evaluate() compares only the arcs whose
// rounded cosine is near the largest; a wrong cut would return a farther arc's distance.
TEST(CandidatePool, EvaluateGivesTheNearestFeatureAlsoWhereFeaturesNearlyTie) {
  std::mt19937 rng(31);
  std::normal_distribution<double> nd;
  int n = 0, fluid_checked = 0;
  for_each_random_fan(rng, 40, [&](const FanGeometry& g, const std::string& label) {
    const oracle::Link link = oracle::make_link(g.dirs);
    detail::CandidatePool pool(g, default_tolerances(), false, 0.0);
    const int k = g.n_faces();
    std::vector<Vec3> directions;
    for (int t = 0; t < 20; ++t) directions.push_back(normalized(Vec3{nd(rng), nd(rng), nd(rng)}));
    for (int a = 0; a < k; ++a)
      for (int b = a + 1; b < k; ++b) {
        directions.push_back(normalized(g.dirs[a] + g.dirs[b]));
        directions.push_back(normalized(g.face_normals[a] + g.face_normals[b]));
      }
    const std::size_t n_exact = directions.size();
    for (std::size_t i = 20; i < n_exact; ++i)
      directions.push_back(normalized(directions[i] + 1e-13 * Vec3{nd(rng), nd(rng), nd(rng)}));
    for (const Vec3& x : directions) {
      if (!(norm2(x) > 0.5)) continue;
      double d = 0.0;
      bool fluid = false;
      ASSERT_TRUE(pool.evaluate(x, -std::numeric_limits<double>::infinity(), &d, &fluid)) << label;
      ASSERT_NEAR(d, oracle::normality(link, x), 1e-12) << label;
      ++n;
      // The side is compared where it is clear-cut: D well above zero, so x is off the link.
      const int reference = oracle::fluid(link, x);
      if (d > 1e-6 && reference >= 0) {
        EXPECT_EQ(fluid, reference == 1) << label;
        ++fluid_checked;
      }
    }
  });
  EXPECT_GT(n, 10000);
  EXPECT_GT(fluid_checked, n / 2);
}

// Every sampled direction with g(n) = min_j angle(n, u_j) >= thr lies within the lens
// radius of the cap antipode, for thresholds just above 90 degrees up to the bound.
TEST(LinkVertexLens, HoldsEverySampledDirectionOfItsRegion) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (int t = 0; t < 300; ++t) {
    const FanGeometry g = testing_fans::geometry(t % 2 ? testing_fans::skin_fan(rng)
                                                       : testing_fans::random_fan(rng, Shape::kConvex));
    const Tolerances cap_tol = detail::lens_cap_tolerances(default_tolerances());
    MostVisibleResult cap;
    if (wolfe_min_norm_point(g.dirs.data(), g.n_faces(), cap_tol, &cap) != WolfeOutcome::kCertified) continue;
    const Vec3 centre = -cap.normal;
    const double target = M_PI - std::acos(std::min(1.0, cap.visibility));
    if (target < 0.5 * M_PI + 1e-6) continue;
    const double thr = 0.5 * M_PI + (target - 0.5 * M_PI) * (0.5 + 0.5 * u(rng));
    const double radius = detail::link_vertex_lens_radius(g.dirs, centre, thr, 0.5);
    if (radius < 0.0) continue;
    ++checked;
    // Sample a cap of twice the radius (and at least 0.05 rad) around the centre.
    Vec3 e1, e2;
    detail::orthonormal_complement(centre, &e1, &e2);
    const double reach = std::max(2.0 * radius, 0.05);
    for (int s = 0; s < 4000; ++s) {
      const double r = reach * std::sqrt(u(rng)), a = 2.0 * M_PI * u(rng);
      const Vec3 n = normalized(std::cos(r) * centre + std::sin(r) * (std::cos(a) * e1 + std::sin(a) * e2));
      double gmin = M_PI;
      for (const Vec3& w : g.dirs) gmin = std::min(gmin, angle_between(n, w));
      if (gmin >= thr) {
        ASSERT_LE(angle_between(n, centre), radius) << "fan " << t;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

// The radius bounds the region only around a point of it: a centre outside, as a cap
// antipode computed inaccurately for a nearly flat link can be, gets no radius, also
// where the circles around it miss the region.
TEST(LinkVertexLens, RefusesACentreOutsideItsRegion) {
  std::mt19937 rng(17);
  int refused = 0;
  for (int t = 0; t < 100; ++t) {
    const FanGeometry g = testing_fans::geometry(testing_fans::skin_fan(rng));
    const Tolerances cap_tol = detail::lens_cap_tolerances(default_tolerances());
    MostVisibleResult cap;
    if (wolfe_min_norm_point(g.dirs.data(), g.n_faces(), cap_tol, &cap) != WolfeOutcome::kCertified) continue;
    const double target = M_PI - std::acos(std::min(1.0, cap.visibility));
    if (target < 0.5 * M_PI + 1e-6) continue;
    const double thr = 0.5 * M_PI + 0.5 * (target - 0.5 * M_PI);
    // Beyond the region: 1.5 times the bound's excess from the antipode, towards a vertex.
    Vec3 e1, e2;
    detail::orthonormal_complement(-cap.normal, &e1, &e2);
    const Vec3 away = normalized(-cap.normal + 0.3 * (std::cos(t) * e1 + std::sin(t) * e2));
    double g_away = M_PI;
    for (const Vec3& w : g.dirs) g_away = std::min(g_away, angle_between(away, w));
    if (g_away >= thr) continue;
    ++refused;
    EXPECT_LT(detail::link_vertex_lens_radius(g.dirs, away, thr, 0.5), 0.0) << "fan " << t;
  }
  EXPECT_GT(refused, 30);
}

// The first direction on the way from n_MV where V falls to V_min, against the arc
// sampled at 5,001 points: V is V_min there, no sample before it is below V_min, and
// it comes no later than the first sample that is. Towards random directions from the
// CAD-like fans' n_MV (V_min = V*/2, as the solver's constraint).
TEST(VisibilityBoundary, FirstDirectionIsWhereTheSampledArcFirstFallsBelowTheLimit) {
  std::mt19937 rng(4040);
  std::normal_distribution<double> gauss;
  int crossed = 0, stayed_above = 0;
  testing_fans::for_each_cad_fan(rng, {12, 24}, 4, [&](const FanGeometry& g, const std::string& label) {
    const MostVisibleResult mv = most_visible_normal(g.face_normals);
    if (!mv.feasible) return;
    const double v_min = 0.5 * mv.visibility;
    for (int t = 0; t < 4; ++t) {
      const Vec3 to = normalized(Vec3{gauss(rng), gauss(rng), gauss(rng)});
      const double end = angle_between(mv.normal, to);
      const Vec3 b = normalized(to - dot(to, mv.normal) * mv.normal);
      constexpr int kSamples = 5000;
      double first_below = -1.0, step = end / kSamples;
      for (int i = 0; i <= kSamples && first_below < 0.0; ++i)
        if (fan_visibility(g, std::cos(i * step) * mv.normal + std::sin(i * step) * b) < v_min) first_below = i * step;
      Vec3 n;
      const bool found =
          detail::first_direction_at_visibility(g.face_normals.data(), g.n_faces(), mv.normal, to, v_min, &n);
      if (first_below < 0.0) {
        // V may dip below V_min only between two samples; then the answer lies there.
        ++stayed_above;
        if (found) {
          EXPECT_NEAR(fan_visibility(g, n), v_min, 1e-12) << label;
        }
        continue;
      }
      ++crossed;
      ASSERT_TRUE(found) << label;
      const double at = angle_between(mv.normal, n);
      EXPECT_NEAR(norm(n), 1.0, 1e-14) << label;
      EXPECT_NEAR(dot(n, cross(mv.normal, b)), 0.0, 1e-14) << label << ": off the arc";
      EXPECT_NEAR(fan_visibility(g, n), v_min, 1e-12) << label;
      EXPECT_LE(at, first_below + 1e-12) << label;
      for (int i = 0; i * step < at - 1e-9; ++i)
        ASSERT_GE(fan_visibility(g, std::cos(i * step) * mv.normal + std::sin(i * step) * b), v_min - 1e-12)
            << label << ": sample " << i << " below the limit before the answer";
    }
  });
  EXPECT_GT(crossed, 200);
  EXPECT_GT(stayed_above, 20);
}

// Where the cap antipode is fluid but fails the constraint, the solver's floor is D at
// the first direction where the way from n_MV towards the antipode meets V = V_min. A
// floor above the constrained optimum would make the solver settle on it, so it must
// stay below the enumeration's D*; on the rims, where the constraint binds, it comes
// within 0.01 rad of it. The default solver keeps the enumeration's optimum.
TEST(VisibilityBoundary, FloorOnTheConstraintStaysBelowTheConstrainedOptimum) {
  std::mt19937 rng(5151);
  int floors = 0, close_on_rims = 0;
  testing_fans::for_each_cad_fan(rng, {12, 16, 20, 24}, 4, [&](const FanGeometry& g, const std::string& label) {
    const MostVisibleResult mv = most_visible_normal(g.face_normals);
    const Tolerances cap_tol = detail::lens_cap_tolerances(default_tolerances());
    MostVisibleResult cap;
    if (!mv.feasible || wolfe_min_norm_point(g.dirs.data(), g.n_faces(), cap_tol, &cap) != WolfeOutcome::kCertified)
      return;
    const double v_min = 0.5 * mv.visibility;
    const oracle::Link link = oracle::make_link(g.dirs);
    if (oracle::fluid(link, -cap.normal) != 1 || fan_visibility(g, -cap.normal) >= v_min) return;
    Vec3 n;
    if (!detail::first_direction_at_visibility(g.face_normals.data(), g.n_faces(), mv.normal, -cap.normal, v_min, &n))
      return;
    if (oracle::fluid(link, n) != 1) return;
    ++floors;
    const MostNormalResult optimum = most_normal_by_enumeration(g, default_tolerances(), true);
    const double floor = oracle::normality(link, n);
    EXPECT_LE(floor, optimum.normality + default_tolerances().normality_tie) << label;
    if (label.rfind("rim", 0) == 0 && optimum.status == NormalStatus::kVisibilityConstrained &&
        floor > optimum.normality - 0.01)
      ++close_on_rims;
    EXPECT_TRUE(testing_fans::same_optimum(g, true, most_normal_normal(g), optimum)) << label;
  });
  EXPECT_GT(floors, 40);
  EXPECT_GT(close_on_rims, 40);
}

// The envelope sweep emits a point of largest V inside the window, as high as the best
// of all single peaks and pairwise crossings there.
// The bisector peak of two unit sites a, b (a + b in exact arithmetic): for nearly
// opposite sites it stays on the bisector {n.a = n.b} to rounding, where the plain sum
// strays by ~1e-16 / |a + b|; for nearly equal sites it is the sum's direction, where a
// projection on the ill-conditioned plane {x.(a - b) = 0} would stray as much.
TEST(CandidateFamilies, BisectorPeakStaysOnTheBisectorOfNearlyOppositeOrEqualSites) {
  std::mt19937 rng(11);
  std::normal_distribution<double> nd;
  for (int t = 0; t < 200; ++t) {
    const Vec3 a = normalized(Vec3{nd(rng), nd(rng), nd(rng)});
    const Vec3 tilt = normalized(Vec3{nd(rng), nd(rng), nd(rng)});
    const double eps = std::pow(10.0, -6.0 - 3.0 * (t % 4));  // 1e-6 to 1e-15
    const Vec3 opposite = normalized(-a + eps * tilt), near = normalized(a + eps * tilt);
    const Vec3 n = normalized(detail::bisector_peak(a, opposite));
    ASSERT_GT(norm(n), 0.5) << t;
    EXPECT_LE(std::fabs(dot(n, a) - dot(n, opposite)), 1e-15) << "opposite, eps " << eps;
    const Vec3 m = normalized(detail::bisector_peak(a, near));
    EXPECT_LE(angle_between(m, normalized(a + near)), 1e-15) << "near, eps " << eps;
  }
}

TEST(PlateauEnvelope, PeaksAsHighAsAllPairwiseCrossings) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> nd;
  int n = 0;
  for (int t = 0; t < 400; ++t) {
    const FanGeometry g = testing_fans::geometry(testing_fans::random_fan(rng, t % 2 ? Shape::kSaddle : Shape::kWild));
    const detail::PlateauCircle circle{normalized(Vec3{nd(rng), nd(rng), nd(rng)}), 2.0 * u(rng) - 1.0};
    const Vec3 centre = normalized(Vec3{nd(rng), nd(rng), nd(rng)});
    const double cos_radius = std::cos(0.1 + 2.0 * u(rng));
    std::vector<int> faces(g.n_faces());
    std::iota(faces.begin(), faces.end(), 0);
    std::vector<double> ca, cb, cc;
    double best_all = -2.0, best_envelope = -2.0;
    auto in_window = [&](const Vec3& x) { return dot(normalized(x), centre) >= cos_radius - 1e-12; };
    detail::plateau_peaks(g, circle, faces.data(), g.n_faces(), &ca, &cb, &cc, [&](const Vec3& x) {
      if (in_window(x)) best_all = std::max(best_all, fan_visibility(g, normalized(x)));
    });
    detail::plateau_envelope_peaks(g, circle, faces.data(), g.n_faces(), centre, cos_radius, &ca, &cb, &cc,
                                   [&](const Vec3& x) {
                                     if (in_window(x)) best_envelope = std::max(best_envelope, fan_visibility(g, normalized(x)));
                                   });
    if (best_all < -1.5) continue;
    ++n;
    EXPECT_GE(best_envelope, best_all - 1e-12) << "circle " << t;
  }
  EXPECT_GT(n, 100);
}

// Faces of one plane form a run with the first face of the run (CAD fans drawn exactly:
// a fan-triangulated face is one run; the sliver's skin is curved), and a run breaks only
// where the next normal leaves the first one's tolerance (offset fans: every face its
// own).
TEST(SamePlaneRuns, GroupConsecutiveFacesWithinTheToleranceOfTheirRunsFirstFace) {
  std::mt19937 rng(77);
  int exact_fans = 0, offset_fans = 0;
  for (double offset : {0.0, 1e-5})
    for (testing_fans::CadShape shape : {testing_fans::CadShape::kRidge, testing_fans::CadShape::kCorner,
                                         testing_fans::CadShape::kRim, testing_fans::CadShape::kSliver})
      for (int t = 0; t < 12; ++t) {
        const FanGeometry g = testing_fans::geometry(testing_fans::cad_like_fan(rng, shape, 24, offset));
        if (g.any_degenerate) continue;
        std::vector<int> first;
        detail::same_plane_runs(g, &first);
        ASSERT_EQ(static_cast<int>(first.size()), g.n_faces());
        int runs = 0;
        for (int j = 0; j < g.n_faces(); ++j) {
          ASSERT_LE(first[j], j);
          EXPECT_LE(norm(g.face_normals[j] - g.face_normals[first[j]]), detail::kSamePlaneNormal) << j;
          if (first[j] != j) {
            EXPECT_EQ(first[j], first[j - 1]) << j;
            continue;
          }
          ++runs;
          if (j > 0) {
            EXPECT_GT(norm(g.face_normals[j] - g.face_normals[first[j - 1]]), detail::kSamePlaneNormal) << j;
          }
        }
        if (offset == 0.0 && shape != testing_fans::CadShape::kSliver) {
          ++exact_fans;
          // The fan-triangulated face (k - 3 or more faces of the 24) is one run.
          EXPECT_LE(runs, 8) << testing_fans::cad_shape_name(shape) << " " << t;
        } else if (offset > 0.0) {
          ++offset_fans;
          EXPECT_EQ(runs, g.n_faces()) << testing_fans::cad_shape_name(shape) << " " << t;
        }
      }
  EXPECT_GT(exact_fans, 30);
  EXPECT_GT(offset_fans, 40);
}

TEST(DropRepeatedPlanes, KeepsTheFirstListedFaceOfEachRunInTheListsOrder) {
  const std::vector<int> first = {0, 0, 0, 3, 3, 5};
  std::vector<int> faces = {4, 1, 2, 3, 5, 0};
  detail::drop_repeated_planes(first, &faces);
  EXPECT_EQ(faces, (std::vector<int>{4, 1, 5}));
  std::vector<int> one_each = {2, 3, 5};
  detail::drop_repeated_planes(first, &one_each);
  EXPECT_EQ(one_each, (std::vector<int>{2, 3, 5}));
}

// The pair bound of the subdivision holds on every sampled direction of the cap, rim
// included, for random and for nearly antipodal pairs of link directions.
TEST(SiteSubdivision, PairBoundHoldsOnEverySampledDirectionOfTheCap) {
  std::mt19937 rng(31);
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto random_unit = [&]() { return normalized(Vec3{nd(rng), nd(rng), nd(rng)}); };
  int bounded = 0;
  for (int t = 0; t < 4000; ++t) {
    const Vec3 c = random_unit(), a = random_unit();
    const Vec3 b = t % 2 == 0 ? random_unit() : normalized(-a + 1e-3 * u01(rng) * random_unit());
    const double rho = t % 4 < 2 ? 0.5 * u01(rng) : 1e-3 * u01(rng);
    const double bound = detail::pair_cap_cosine(c, std::cos(rho), std::sin(rho), a, b);
    if (bound == -2.0) continue;
    ++bounded;
    Vec3 e1, e2;
    detail::orthonormal_complement(c, &e1, &e2);
    for (int s = 0; s < 64; ++s) {
      // Points of the cap, its rim included.
      const double r = s < 32 ? rho : rho * std::sqrt(u01(rng)), phi = 2.0 * M_PI * u01(rng);
      const Vec3 n = std::cos(r) * c + std::sin(r) * (std::cos(phi) * e1 + std::sin(phi) * e2);
      ASSERT_GE(std::max(dot(n, a), dot(n, b)), bound - 1e-15) << "pair " << t << " sample " << s;
    }
  }
  EXPECT_GT(bounded, 1500);
}

// The pair bound's screen says "below the level" only where pair_cap_cosine is at most
// the level, and says it wherever the bound lies clearly below (its squares then differ
// by far more than its allowance), with levels at and around the bound itself.
TEST(SiteSubdivision, PairBoundScreenRejectsOnlyPairsWhoseBoundIsBelowTheLevel) {
  std::mt19937 rng(37);
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto random_unit = [&]() { return normalized(Vec3{nd(rng), nd(rng), nd(rng)}); };
  const double offsets[] = {0.0, 1e-15, -1e-15, 1e-13, -1e-13, 1e-9, -1e-9, 1e-3, -1e-3, 0.3, -0.3};
  int rejected = 0, clear = 0;
  for (int t = 0; t < 4000; ++t) {
    const Vec3 c = random_unit(), a = random_unit();
    const Vec3 b = t % 2 == 0 ? random_unit() : normalized(-a + 1e-3 * u01(rng) * random_unit());
    const double rho = t % 4 < 2 ? 0.5 * u01(rng) : 1e-3 * u01(rng);
    const double cr = std::cos(rho), sr = std::sin(rho);
    const double bound = detail::pair_cap_cosine(c, cr, sr, a, b);
    const double x = 0.5 * (dot(c, a) + dot(c, b));
    for (double offset : offsets) {
      const double level = bound + offset;
      const bool below = detail::pair_cap_certainly_below(x, cr, sr, a, b, level);
      if (below) {
        ++rejected;
        ASSERT_LE(bound, level) << "pair " << t << " offset " << offset;
      }
      // Clearly below: the bound beats the level by 1e-6 with l = x cos(rho) - level
      // above 1e-4, so that s^2 - l^2 exceeds the allowance a hundred times.
      if (bound != -2.0 && level - bound > 1e-6 && x * cr - level > 1e-4) {
        ++clear;
        EXPECT_TRUE(below) << "pair " << t << " offset " << offset;
      }
    }
  }
  EXPECT_GT(rejected, 2000);
  EXPECT_GT(clear, 500);
}

// The subdivision counts a link vertex w as a site of a cell only where the cell meets
// its wedge {n.arc_end_lune(in) <= 0, n.arc_start_lune(out) <= 0}: outside it, one of
// w's two arcs has a point nearer than w, so w generates no candidate there. Checked
// with the reference arc distance on random and CAD-like fans (the latter's nearly flat
// junctions have wedges a fraction of a degree wide), at random directions and at
// directions near w. Inside the wedge, near w, w is its arcs' nearest point (a tie):
// there it can generate, and a lune of the wrong sign would put such directions
// outside.
TEST(SiteSubdivision, LinkVertexIsTheNearestPointOfItsArcsOnlyInItsWedge) {
  std::mt19937 rng(53);
  std::normal_distribution<double> nd;
  auto random_unit = [&]() { return normalized(Vec3{nd(rng), nd(rng), nd(rng)}); };
  int outside = 0, inside_tied = 0;
  auto check = [&](const FanGeometry& g, const std::string& label) {
    const oracle::Link link = oracle::make_link(g.dirs);
    const int k = g.n_faces();
    for (int j = 0; j < k; ++j) {
      const int in = (j + k - 1) % k;
      const Vec3& w = g.dirs[j];
      const Vec3 a = detail::arc_end_lune(g, in), b = detail::arc_start_lune(g, j);
      for (int s = 0; s < 60; ++s) {
        const Vec3 n = s < 20 ? random_unit() : normalized(w + std::pow(10.0, -3.0 * (s % 4)) * random_unit());
        const double to_w = std::atan2(norm(cross(n, w)), dot(n, w));
        const double to_arcs = std::min(oracle::arc_distance(link, in, n), oracle::arc_distance(link, j, n));
        if (dot(n, a) > 1e-4 || dot(n, b) > 1e-4) {
          ++outside;
          ASSERT_GT(to_w, to_arcs) << label << " vertex " << j << " sample " << s;
        } else if (dot(n, a) < -1e-4 && dot(n, b) < -1e-4 && std::fabs(to_w - to_arcs) <= 1e-12) {
          ++inside_tied;
        }
      }
    }
  };
  for_each_random_fan(rng, 40, check);
  testing_fans::for_each_cad_fan(rng, {12, 40}, 2, [&](const FanGeometry& g, const std::string& label) {
    check(g, label);
  });
  EXPECT_GT(outside, 50000);
  EXPECT_GT(inside_tied, 5000);
}

// Random unit vectors and leaves for the constraint pass's screens: a leaf's centre, its
// radius (1e-9 to 1.6, where the cosine margin dominates at the small end), the cosine
// offer() admits, as SiteSubdivision::record_leaf sets it, and that cosine's angle.
class RandomLeaves {
 public:
  explicit RandomLeaves(unsigned seed) : rng_(seed) {}
  Vec3 unit() { return normalized(Vec3{nd_(rng_), nd_(rng_), nd_(rng_)}); }
  double uniform() { return u01_(rng_); }
  struct Leaf {
    Vec3 c;
    double rho, cos_cap, admitted;
  };
  Leaf leaf() {
    Leaf l;
    l.c = unit();
    l.rho = std::pow(10.0, -9.0 + 9.2 * uniform());
    l.cos_cap = std::cos(l.rho + 1e-12) - 1e-15;
    l.admitted = std::acos(std::min(1.0, l.cos_cap));
    return l;
  }

 private:
  std::mt19937 rng_;
  std::normal_distribution<double> nd_;
  std::uniform_real_distribution<double> u01_{0.0, 1.0};
};

// The constraint pass builds the points of a great circle {n.h = 0} in a leaf only when
// great_circle_meets_cap says the circle can hold a direction the leaf admits
// (n.c >= cos_cap). For random leaves, of radii down to 1e-9 where the cosine margin
// dominates, every great circle that holds an admitted direction (its point nearest c,
// and points computed as the candidates are, by plane_plane_sphere) is kept; circles
// well outside are dropped.
TEST(SiteSubdivision, GreatCircleScreenKeepsEveryCircleThroughTheLeaf) {
  RandomLeaves random(41);
  int held = 0, dropped = 0;
  for (int t = 0; t < 20000; ++t) {
    const auto [c, rho, cos_cap, admitted] = random.leaf();
    // A circle whose nearest point to c is at a chosen angle, around the cap's edge.
    const double gap = admitted * (0.5 + random.uniform()) + (t % 3 == 0 ? 1e-8 * random.uniform() : 0.0);
    const Vec3 t1 = normalized(cross(c, random.unit()));
    const Vec3 nearest = std::cos(gap) * c + std::sin(gap) * t1;
    const Vec3 h = (0.01 + random.uniform()) * normalized(cross(nearest, cross(c, t1)));
    // The points a candidate formula would give on it: through a random circle n.f = v.
    std::vector<Vec3> points = {nearest};
    const Vec3 f = random.unit();
    detail::plane_plane_sphere(h, 0.0, f, dot(f, nearest), [&](const Vec3& n) { points.push_back(n); });
    bool admits = false;
    for (const Vec3& n : points) admits |= dot(n, c) >= cos_cap * norm(n);
    const bool kept = detail::great_circle_meets_cap(c, cos_cap, h);
    if (admits) {
      ++held;
      EXPECT_TRUE(kept) << "leaf " << t << " radius " << rho;
    }
    if (!kept) ++dropped;
  }
  EXPECT_GT(held, 5000);
  EXPECT_GT(dropped, 5000);
}

// The constraint pass solves a point-arc cone's quartic on a constraint circle in a leaf
// only when the window of that circle in the leaf (circle_window_in_cap) where another
// face stays feasible (circle_window_feasible) can hold a root
// (cone_terms_reach_window). For random leaves of radii down to 1e-9, constraint circles
// through or near them, a second face whose circle passes near them, and cones through a
// point near them (or random), every point circle_cone builds on the whole circle that
// the leaf admits and the second face leaves feasible (as CandidatePool::consider tests)
// is built, bit for bit, within the window too; and many quartics are skipped.
TEST(SiteSubdivision, ConeWindowKeepsEveryConePointTheLeafAdmits) {
  RandomLeaves random(43);
  int admitted_points = 0, skipped = 0;
  for (int t = 0; t < 20000; ++t) {
    const auto [c, rho, cos_cap, admitted] = random.leaf();
    // A point around the cap's edge, on the constraint circle {n.f = c0}.
    const Vec3 p = normalized(std::cos(admitted * 1.5 * random.uniform()) * c +
                              std::sin(admitted * 1.5 * random.uniform()) * normalized(cross(c, random.unit())));
    const Vec3 f = random.unit();
    const double c0 = dot(f, p);
    // The second face: its circle {n.f2 = c0} passes within about the leaf's radius of p.
    const double v2 = std::clamp(c0 + admitted * (2.0 * random.uniform() - 1.0), -1.0, 1.0);
    const Vec3 f2 = normalized(v2 * p + std::sqrt(1.0 - v2 * v2) * normalized(cross(p, random.unit())));
    // A cone through p (w, g with (p.w)^2 + (p.g)^2 = 1), or a random one.
    const Vec3 w = random.unit();
    Vec3 g = random.unit();
    if (t % 4 != 0) {
      const double cos_a = std::sqrt(std::max(0.0, 1.0 - dot(p, w) * dot(p, w)));
      const Vec3 q = normalized(cross(p, random.unit()));
      g = normalized(cos_a * p + std::sqrt(std::max(0.0, 1.0 - cos_a * cos_a)) * q);
    }
    std::vector<Vec3> whole, windowed;
    detail::circle_cone(f, c0, w, g, [&](const Vec3& n) { whole.push_back(n); });
    const detail::CircleWindow window = detail::intersect_windows(
        detail::circle_window_in_cap(c, cos_cap, f, c0), detail::circle_window_feasible(f2, c0, f, c0));
    detail::circle_cone(f, c0, w, g, [&](const Vec3& n) { windowed.push_back(n); }, window);
    if (windowed.size() < whole.size()) ++skipped;
    for (const Vec3& n : whole) {
      if (!(dot(n, c) >= cos_cap * norm(n))) continue;
      if (!(dot(n / norm(n), f2) >= c0 - detail::kConstraintSlack)) continue;
      ++admitted_points;
      bool built = false;
      for (const Vec3& m : windowed) built |= m == n;
      EXPECT_TRUE(built) << "leaf " << t << " radius " << rho;
    }
  }
  EXPECT_GT(admitted_points, 5000);
  EXPECT_GT(skipped, 5000);
}

// intersect_windows keeps every angle that lies in both windows (a sampled brute force,
// across the wrap at pi), and its window is no wider than the first one.
TEST(SiteSubdivision, IntersectedWindowsHoldEveryCommonAngle) {
  std::mt19937 rng(47);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto random_window = [&]() {
    const double kind = u01(rng);
    if (kind < 0.05) return detail::CircleWindow{};             // whole
    if (kind < 0.1) return detail::CircleWindow{0.0, -1.0};     // empty
    return detail::CircleWindow{2.0 * M_PI * (u01(rng) - 0.5) * 1.2, M_PI * u01(rng) * u01(rng)};
  };
  auto holds = [](const detail::CircleWindow& w, double t) {
    return w.whole() || (w.half_width >= 0.0 && std::fabs(std::remainder(t - w.centre, 2.0 * M_PI)) <= w.half_width);
  };
  int common = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const detail::CircleWindow a = random_window(), b = random_window();
    const detail::CircleWindow both = detail::intersect_windows(a, b);
    if (!a.whole()) {
      EXPECT_LE(both.half_width, a.half_width + 1e-15) << trial;
    }
    for (int k = 0; k < 720; ++k) {
      const double t = -M_PI + 2.0 * M_PI * (k + 0.5) / 720.0;
      if (!(holds(a, t) && holds(b, t))) continue;
      ++common;
      // 1e-12 of slack for the rounding of the centre's shift.
      const bool kept = holds(both, t) || holds(both, t + 1e-12) || holds(both, t - 1e-12);
      EXPECT_TRUE(kept) << "trial " << trial << " angle " << t;
    }
  }
  EXPECT_GT(common, 100000);
}

// pair_sum_below_on_cap proves that no direction of a cap keeps two faces at V_min (as
// SiteSubdivision::pair_infeasible uses it). For random caps of radii 1e-9 to 1.6 across
// the constraint of one face, paired with a nearly opposite face (or a random one), every
// proof is checked against directions sampled inside the cap and on its rim: none may
// keep both faces at V_min - slack or above. Nearly opposite pairs give many proofs, and
// many caps are refused.
TEST(SiteSubdivision, PairOfFacesProvesACapInfeasibleOnlyWhereNoDirectionIsFeasible) {
  RandomLeaves random(53);
  int proofs = 0, refused = 0;
  for (int t = 0; t < 20000; ++t) {
    const double rho = random.leaf().rho;
    const double v_min = std::pow(10.0, -5.0 + 4.0 * random.uniform());
    const double level = 2.0 * (v_min - detail::kConstraintSlack);
    const Vec3 f_a = random.unit();
    // A centre whose visibility of f_a is within two radii of V_min.
    const double v_c = std::clamp(v_min + 2.0 * rho * (2.0 * random.uniform() - 1.0), -1.0, 1.0);
    const Vec3 c = normalized(v_c * f_a + std::sqrt(1.0 - v_c * v_c) * normalized(cross(f_a, random.unit())));
    const double tilt = std::pow(10.0, -6.0 + 5.0 * random.uniform());
    const Vec3 f_b = t % 4 == 0 ? random.unit() : normalized(-1.0 * f_a + tilt * random.unit());
    if (!detail::pair_sum_below_on_cap(c, rho, f_a, f_b, level)) {
      ++refused;
      continue;
    }
    ++proofs;
    Vec3 e1, e2;
    detail::orthonormal_complement(c, &e1, &e2);
    for (int k = 0; k < 64; ++k) {
      const double angle = (k % 4 == 0 ? 1.0 : std::sqrt(random.uniform())) * rho;
      const double phi = 2.0 * M_PI * random.uniform();
      const Vec3 n = std::cos(angle) * c + std::sin(angle) * (std::cos(phi) * e1 + std::sin(phi) * e2);
      const bool both = dot(n, f_a) >= v_min - detail::kConstraintSlack && dot(n, f_b) >= v_min - detail::kConstraintSlack;
      EXPECT_FALSE(both) << "cap " << t << " radius " << rho << " sample " << k;
    }
  }
  EXPECT_GT(proofs, 2000);
  EXPECT_GT(refused, 2000);
}

// The generator screen keeps an arc only on its fluid side: a direction at its pole
// passes, its antipode does not, nor a pair of arcs whose poles are antipodal.
TEST(ArcReachScreen, KeepsArcGeneratorsOnTheirFluidSideOnly) {
  FanGeometry g;
  for (const testing_fans::TestFan& f : testing_fans::public_fans())
    if (std::string(f.name) == "T8") g = testing_fans::geometry(f.ring);  // monkey saddle
  ASSERT_EQ(g.n_faces(), 6);
  detail::CandidatePool pool(g, default_tolerances(), true, 0.1);
  pool.raise_floor({0.0, 0.0, 1.0}, 1.0);
  const detail::ArcReachScreen screen(pool);
  const Vec3 f = g.face_normals[0];
  EXPECT_TRUE(screen.arc_ok(f, f));
  EXPECT_FALSE(screen.arc_ok(-f, f));
  EXPECT_FALSE(screen.arc_pair(f, f));
  EXPECT_TRUE(screen.arc_pair(f, -f));
}

// The premise of that screen, on the enumeration's own maximisers: every arc that
// generates one (foot inside, at the optimum's distance) has it on the side of its
// normal, at x.g = sin D.
TEST(ArcReachScreen, EveryArcGeneratorOfAMaximiserHasItOnItsNormalSide) {
  std::mt19937 rng(515);
  int generators = 0;
  for_each_random_fan(rng, 60, [&](const FanGeometry& g, const std::string& label) {
    for (bool constrained : {true, false})
      for (const detail::Maximizer& m : detail::most_normal_maximizers(g, default_tolerances(), constrained, false))
        for (int i = 0; i < g.n_faces(); ++i) {
          const Vec3& f = g.face_normals[i];
          const Vec3 foot = m.n - dot(m.n, f) * f;
          const bool inside = dot(cross(g.arc_start(i), foot), f) > 0.0 && dot(cross(foot, g.arc_end(i)), f) > 0.0;
          if (!inside || std::fabs(std::asin(std::min(1.0, std::fabs(dot(m.n, f)))) - m.d) > 1e-9) continue;
          ++generators;
          EXPECT_NEAR(dot(m.n, f), std::sin(m.d), 1e-9) << label << " arc " << i;
        }
  });
  EXPECT_GT(generators, 300);
}

}  // namespace
}  // namespace blayer
