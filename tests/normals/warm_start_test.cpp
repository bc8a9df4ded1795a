// Warm starts of the most-normal solver across fronts (most_normal.h,
// MostNormalWarmStart): the warm answer is the cold one, the certificate holds when the
// fan has not changed its optimum's structure, stale or foreign warm starts are harmless,
// and a march over a bumpy surface keeps most certificates.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "analytic_surfaces.h"
#include "blayer/core/vertex_fans.h"
#include "blayer/normals/most_normal.h"
#include "blayer/normals/point_normals.h"
#include "cad_fans.h"
#include "random_fans.h"
#include "test_fans.h"

namespace blayer {
namespace {

using testing_fans::Shape;

// Warm and cold answers come from the same maximisers except where the two candidate sets
// differ inside the tie band (candidates built from sites that are not nearest): the same
// status and D within the tie always, the same direction or V otherwise.
void expect_same_answer(const MostNormalResult& warm, const MostNormalResult& cold, const std::string& what) {
  EXPECT_EQ(warm.status, cold.status) << what;
  EXPECT_NEAR(warm.normality, cold.normality, default_tolerances().normality_tie) << what;
  EXPECT_TRUE(angle_between(warm.normal, cold.normal) <= 1e-12 || warm.visibility >= cold.visibility - 1e-12)
      << what << ": angle " << angle_between(warm.normal, cold.normal);
}

std::vector<Vec3> moved(std::vector<Vec3> ring, std::mt19937& rng, double amount) {
  std::normal_distribution<double> nd;
  for (Vec3& r : ring) r += amount * norm(r) * normalized(Vec3{nd(rng), nd(rng), nd(rng)});
  return ring;
}

std::vector<std::vector<Vec3>> sample_rings() {
  std::vector<std::vector<Vec3>> rings;
  std::mt19937 rng(2718);
  for (Shape s : {Shape::kConvex, Shape::kSaddle, Shape::kSliver, Shape::kWild})
    for (int t = 0; t < 150; ++t) rings.push_back(testing_fans::random_fan(rng, s));
  for (int t = 0; t < 200; ++t) rings.push_back(testing_fans::near_flat_fan(rng));
  for (int t = 0; t < 40; ++t)
    rings.push_back(testing_fans::cad_like_fan(rng, testing_fans::kCadShapes[t % 4], 20 + t % 20, 1e-4));
  return rings;
}

TEST(MostNormalWarmStart, SameFanHoldsTheCertificate) {
  int warm_started = 0, hits = 0;
  for (const auto& ring : sample_rings()) {
    const FanGeometry g = testing_fans::geometry(ring);
    if (g.any_degenerate) continue;
    MostNormalWarmStart warm;
    bool hit = true;
    const MostNormalResult first = most_normal_normal(g, &warm, &hit);
    EXPECT_FALSE(hit);  // nothing to rebuild yet
    if (!warm.valid) continue;
    ++warm_started;
    const MostNormalResult again = most_normal_normal(g, &warm, &hit);
    expect_same_answer(again, first, "same fan");
    hits += hit ? 1 : 0;
  }
  EXPECT_GT(warm_started, 500);
  // The rebuilt candidate is the optimum itself, save degenerate optima with more than
  // three generators of a kind.
  EXPECT_GE(hits, warm_started * 98 / 100);
}

TEST(MostNormalWarmStart, MovedFanGetsTheColdAnswer) {
  std::mt19937 rng(161803);
  int warm_started = 0, hits = 0;
  for (const auto& ring : sample_rings()) {
    const FanGeometry g0 = testing_fans::geometry(ring);
    const FanGeometry g1 = testing_fans::geometry(moved(ring, rng, 1e-4));
    if (g0.any_degenerate || g1.any_degenerate) continue;
    MostNormalWarmStart warm;
    most_normal_normal(g0, &warm);
    warm_started += warm.valid ? 1 : 0;
    bool hit = false;
    const MostNormalResult w = most_normal_normal(g1, &warm, &hit);
    expect_same_answer(w, most_normal_normal(g1), "moved fan");
    hits += hit ? 1 : 0;
  }
  EXPECT_GT(warm_started, 500);
  EXPECT_GT(hits, warm_started / 2);
}

TEST(MostNormalWarmStart, ForeignOrStaleWarmStartIsHarmless) {
  const auto rings = sample_rings();
  MostNormalWarmStart foreign;
  for (std::size_t t = 0; t + 1 < rings.size(); ++t) {
    const FanGeometry a = testing_fans::geometry(rings[t]), b = testing_fans::geometry(rings[t + 1]);
    if (a.any_degenerate || b.any_degenerate) continue;
    MostNormalWarmStart w;
    most_normal_normal(a, &w);
    if (!w.valid) continue;
    // A warm start from another fan, and one naming vertices beyond this fan's ring.
    foreign = w;
    expect_same_answer(most_normal_normal(b, &foreign), most_normal_normal(b), "foreign fan " + std::to_string(t));
    MostNormalWarmStart stale = w;
    stale.points[0] = 1000;
    stale.n_points = std::max(stale.n_points, 1);
    expect_same_answer(most_normal_normal(a, &stale), most_normal_normal(a), "stale warm start " + std::to_string(t));
  }
}

// An icosphere with a deterministic radial bump field: convex and saddle vertices with
// reflex junctions, marched like layer fronts.
TEST(MostNormalWarmStart, FrontMarchKeepsCertificatesAndColdNormals) {
  TriSurface s = test_surfaces::icosphere(3);
  for (Vec3& p : s.points) p *= 1.0 + 0.05 * std::sin(7.0 * p[0]) * std::cos(5.0 * p[1] + 2.0 * p[2]);
  const VertexFans fans = build_vertex_fans(s);
  std::vector<MostNormalWarmStart> warm;
  double height = 2e-3;
  long warm_started = 0, hits = 0;
  for (int front = 0; front < 6; ++front) {
    WarmStartCounts counts;
    const PointNormals cold = compute_point_normals(s, fans, NormalMethod::kMostNormal);
    const PointNormals hot =
        compute_point_normals(s, fans, NormalMethod::kMostNormal, default_tolerances(), &warm, &counts);
    ASSERT_EQ(warm.size(), s.points.size());
    for (std::size_t v = 0; v < s.points.size(); ++v) {
      EXPECT_EQ(hot.status[v], cold.status[v]) << "front " << front << " vertex " << v;
      EXPECT_NEAR(hot.normality[v], cold.normality[v], default_tolerances().normality_tie);
    }
    if (front == 0) {
      EXPECT_EQ(counts.warm, 0);
    } else {
      warm_started += counts.warm;
      hits += counts.hits;
    }
    for (std::size_t v = 0; v < s.points.size(); ++v) s.points[v] += height * cold.normal[v];
    height *= 1.2;
  }
  EXPECT_GT(warm_started, 1000);
  EXPECT_GT(static_cast<double>(hits), 0.7 * static_cast<double>(warm_started));
}

TEST(MostNormalWarmStart, OtherMethodsLeaveNoWarmStart) {
  const TriSurface s = test_surfaces::icosphere(2);
  std::vector<MostNormalWarmStart> warm;
  compute_point_normals(s, build_vertex_fans(s), NormalMethod::kAngle, default_tolerances(), &warm);
  ASSERT_EQ(warm.size(), s.points.size());
  for (const MostNormalWarmStart& w : warm) EXPECT_FALSE(w.valid);
}

}  // namespace
}  // namespace blayer
