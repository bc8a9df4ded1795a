// The default most-normal solver (the link-vertex lens, the screened enumeration of small
// fans, the subdivision of large ones; most_normal.h) against the unpruned enumeration
// (most_normal_by_enumeration) on the public fans, thousands of random fans of every
// shape, near-flat wing skins, convex skins and CAD-like fans with and without offsets,
// with and without the visibility constraint (agreement rule: agreement.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "agreement_test_support.h"
#include "blayer/normals/most_normal.h"
#include "cad_fans.h"
#include "random_fans.h"
#include "test_fans.h"

namespace blayer {
namespace {

using testing_fans::Shape;

// Which passes answered, from the diagnostics: the subdivision visits cells; without
// cells the screened enumeration (or MN = MV) did.
struct Paths {
  int subdivided = 0;
  int enumerated = 0;
};

void expect_same(const FanGeometry& g, const std::string& what, Paths* paths = nullptr) {
  for (bool constrained : {true, false}) {
    const MostNormalResult a = most_normal_normal(g, default_tolerances(), constrained);
    const MostNormalResult b = most_normal_by_enumeration(g, default_tolerances(), constrained);
    EXPECT_TRUE(testing_fans::same_optimum(g, constrained, a, b)) << what << (constrained ? " constrained" : " free");
    if (paths && constrained) (a.n_cells > 0 ? paths->subdivided : paths->enumerated) += 1;
  }
}

TEST(DefaultMostNormal, MatchesEnumerationOnPublicFans) {
  for (const testing_fans::TestFan& f : testing_fans::public_fans()) expect_same(testing_fans::geometry(f.ring), f.name);
}

TEST(DefaultMostNormal, MatchesEnumerationOnRandomShapes) {
  for (Shape shape : {Shape::kConvex, Shape::kConcave, Shape::kSaddle, Shape::kSliver, Shape::kWild}) {
    std::mt19937 rng(5150u + static_cast<unsigned>(shape));
    int n = 0;
    for (int t = 0; t < 400; ++t) {
      const FanGeometry g = testing_fans::geometry(testing_fans::random_fan(rng, shape));
      if (g.any_degenerate) continue;
      ++n;
      expect_same(g, std::string(testing_fans::shape_name(shape)) + " fan " + std::to_string(t));
    }
    EXPECT_GT(n, 350) << testing_fans::shape_name(shape);
  }
}

TEST(DefaultMostNormal, MatchesEnumerationOnNearFlatAndConvexSkins) {
  std::mt19937 rng(8086);
  int n = 0;
  for (int t = 0; t < 3000; ++t) {
    const FanGeometry flat = testing_fans::geometry(testing_fans::near_flat_fan(rng));
    if (!flat.any_degenerate) expect_same(flat, "near-flat fan " + std::to_string(t));
    const FanGeometry skin = testing_fans::geometry(testing_fans::skin_fan(rng));
    if (!skin.any_degenerate) expect_same(skin, "skin fan " + std::to_string(t));
    n += (flat.any_degenerate ? 0 : 1) + (skin.any_degenerate ? 0 : 1);
  }
  EXPECT_GT(n, 5000);
}

// CAD-like fans of valence 12-24 (the enumeration is O(k^3): larger ones are compared in
// bench/normals/most_normal_agreement --cad): exact planes (merged arcs, plateaus) and
// offsets of 1e-5 and 1e-3 of the edge length.
TEST(DefaultMostNormal, MatchesEnumerationOnCadLikeFans) {
  std::mt19937 rng(1969);
  Paths paths;
  int n = 0;
  testing_fans::for_each_cad_fan(rng, {12, 16, 20, 24}, 6, [&](const FanGeometry& g, const std::string& label) {
    ++n;
    expect_same(g, label, &paths);
  });
  EXPECT_GT(n, 250);
  // Both passes of the default solver must have been exercised.
  EXPECT_GT(paths.subdivided, 50);
  EXPECT_GT(paths.enumerated, 20);
}

// The agreement rule may excuse a status difference only by maximisers that are not
// genuine; the check must accept every unique optimum of the enumeration...
TEST(AgreementRule, EveryUniqueEnumeratedOptimumIsGenuine) {
  std::mt19937 rng(31337);
  int n = 0;
  for (Shape shape : {Shape::kConvex, Shape::kConcave, Shape::kSaddle, Shape::kWild})
    for (int t = 0; t < 100; ++t) {
      const FanGeometry g = testing_fans::geometry(testing_fans::random_fan(rng, shape));
      if (g.any_degenerate) continue;
      const MostNormalResult r = most_normal_by_enumeration(g, default_tolerances(), false);
      if (r.status != NormalStatus::kOk) continue;
      ++n;
      EXPECT_TRUE(testing_fans::genuine_maximizer(g, r.normal)) << testing_fans::shape_name(shape) << " " << t;
    }
  EXPECT_GT(n, 300);
}

// ...and reject a point that is not a maximiser: beside T4's plateau (D = 90 deg on the
// circle y = 0 between the face normals), 1e-3 rad off it, while accepting the plateau.
TEST(AgreementRule, PointBesideAPlateauIsNotGenuine) {
  const auto fans = testing_fans::public_fans();
  const FanGeometry t4 = testing_fans::geometry(fans[3].ring);
  const Vec3 off_plateau = normalized(Vec3{std::cos(0.3), 1e-3, std::sin(0.3)});
  EXPECT_FALSE(testing_fans::genuine_maximizer(t4, off_plateau));
  EXPECT_TRUE(testing_fans::genuine_maximizer(t4, normalized(Vec3{std::cos(0.3), 0.0, std::sin(0.3)})));
}

// ...and a pair candidate placed beside a three-site vertex: vertex 11602 of the 717
// wing's first simulated offset front (bench/normals/front_march.h), valence 6, D just
// above 90 degrees. At the enumeration's answer two point sites tie exactly and the
// nearest lies 1.5e-9 below them, so walking along the bisector of the nearest two
// gains nothing; yet D rises by 9.8e-10 towards the vertex where all three tie, 2.4e-7
// away, which the default solver returns. The enumeration's point won its tie-break by
// a V higher by 1.2e-7 and was counted as a missed maximiser.
TEST(AgreementRule, PairCandidateBesideAThreeSiteVertexIsNotGenuine) {
  const Vec3 p{6.1694961327270592, -0.0092774926902843783, 4.0828275839431667};
  const std::vector<Vec3> ring{{6.1731955699102956, -0.0059778259597887302, 4.0821145558619127},
                               {6.3026998124340166, -0.0089740049717075988, 4.5462590732734967},
                               {6.2997733344287612, -0.0098557501767220657, 4.5465742245824954},
                               {6.1673207499209965, -0.0098543173757228326, 4.08294828693339},
                               {6.0397286311250094, -0.0092653199812735357, 3.6285490124542483},
                               {6.0439407919647472, -0.0049436952354650308, 3.6276725533543193}};
  const FanGeometry g = build_fan_geometry(p, ring, true);
  ASSERT_FALSE(g.any_degenerate);
  const Vec3 beside{0.27966479248218717, -0.9567726509844523, -0.079835444346974344};
  const Vec3 vertex{0.27966456791406874, -0.95677272193034435, -0.079835380774673045};
  // Independent of the rule: D is higher at the vertex, within the tie.
  const double tie = default_tolerances().normality_tie;
  EXPECT_GT(fan_normality(g, vertex), fan_normality(g, beside) + 5e-10);
  EXPECT_LT(fan_normality(g, vertex), fan_normality(g, beside) + tie);
  EXPECT_FALSE(testing_fans::genuine_maximizer(g, beside));
  EXPECT_TRUE(testing_fans::genuine_maximizer(g, vertex));
  for (bool constrained : {true, false}) {
    const MostNormalResult a = most_normal_normal(g, default_tolerances(), constrained);
    const MostNormalResult b = most_normal_by_enumeration(g, default_tolerances(), constrained);
    const testing_fans::Agreement verdict = testing_fans::compare_optimum(g, constrained, a, b);
    EXPECT_TRUE(verdict.ok) << verdict.why;
  }
}

// The pole of a body of revolution: every link vertex holds the cap of the link
// vertices, so every triple of them builds the optimum and the generators' candidates
// number C(k, 3) (a valence-96 pole used to take minutes). The link-vertex bound
// certifies the cap antipode instead: D* = 90 deg + atan(h) for a pole h above its rim
// (the angle from the axis to every link vertex).
// The link of the pole of a body of revolution: k points at height -h on the unit
// circle, each moved by `noise` times a normal deviate per coordinate, randomly rotated
// (the axis, its optimum without noise, in *axis).
std::vector<Vec3> pole_ring(std::mt19937& rng, int k, double h, double noise, Vec3* axis) {
  std::normal_distribution<double> nd;
  std::vector<Vec3> ring;
  for (int j = 0; j < k; ++j)
    ring.push_back(Vec3{std::cos(2.0 * M_PI * j / k), std::sin(2.0 * M_PI * j / k), -h} +
                   noise * Vec3{nd(rng), nd(rng), nd(rng)});
  Vec3 q[3];
  testing_fans::random_rotation(rng, q);
  for (Vec3& r : ring) r = testing_fans::rotate(r, q);
  *axis = testing_fans::rotate({0.0, 0.0, 1.0}, q);
  return ring;
}

// The pole's answer, constrained and free: the axis and D = 90 degrees + atan(h) within
// `tol`, straight from the link-vertex bound (no subdivision, no generator triples).
void expect_answered_by_the_bound(const FanGeometry& g, const Vec3& axis, double h, double tol,
                                  const std::string& what) {
  for (bool constrained : {true, false}) {
    const MostNormalResult r = most_normal_normal(g, default_tolerances(), constrained);
    EXPECT_EQ(r.status, NormalStatus::kOk) << what;
    EXPECT_LE(angle_between(r.normal, axis), tol) << what;
    EXPECT_NEAR(r.normality, 0.5 * M_PI + std::atan(h), tol) << what;
    EXPECT_EQ(r.n_cells, 0) << what << ": no subdivision";
    EXPECT_LE(r.n_candidates, 3) << what << ": no generator triples";
  }
}

TEST(DefaultMostNormal, PoleOfARevolvedBodyIsAnsweredByTheLinkVertexBound) {
  std::mt19937 rng(96);
  for (int k : {24, 96}) {
    const double h = 0.05;
    Vec3 axis;
    const FanGeometry g = testing_fans::geometry(pole_ring(rng, k, h, 0.0, &axis));
    const std::string what = "valence " + std::to_string(k);
    expect_answered_by_the_bound(g, axis, h, 1e-12, what);
    if (k == 24) expect_same(g, what);
  }
}

// Coordinates with noise of 1e-9 of the radius: two or three ring points hold the cap
// exactly, the others miss it by more than the support slack, yet every triple of them
// builds a candidate within the tie (a valence-96 pole took 250 ms per solve).
TEST(DefaultMostNormal, PoleWithNoisyCoordinatesIsAnsweredByItsNearlyTiedRing) {
  std::mt19937 rng(1009);
  for (int k : {24, 96})
    for (int t = 0; t < 3; ++t) {
      const double h = 0.05;
      Vec3 axis;
      const FanGeometry g = testing_fans::geometry(pole_ring(rng, k, h, 1e-9, &axis));
      const std::string what = "valence " + std::to_string(k) + " pole " + std::to_string(t);
      expect_answered_by_the_bound(g, axis, h, 1e-7, what);
      if (k == 24) expect_same(g, what);
    }
}

}  // namespace
}  // namespace blayer
