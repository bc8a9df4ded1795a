// Invariances of docs/normals.md, Part 7: rotation, scaling, translation, re-indexing,
// moving ring points along their rays, planar re-triangulation, orientation reversal.
#include <gtest/gtest.h>

#include <random>

#include "blayer/normals/most_normal.h"
#include "blayer/normals/most_visible.h"
#include "blayer/normals/vertex_normal.h"
#include "blayer/normals/weighted_normal.h"
#include "random_fans.h"
#include "test_fans.h"

namespace blayer {
namespace {

using testing_fans::Shape;

// Invariance accuracy for V, D and MV directions (docs/normals.md, Part 7).
constexpr double kInvariance = 1e-12;
// Most-normal directions are intersections of bisectors: allow the conditioning of
// those small solves on top of rounding.
constexpr double kDirection = 1e-9;

std::vector<std::vector<Vec3>> sample_fans() {
  std::vector<std::vector<Vec3>> fans;
  for (const auto& f : testing_fans::public_fans()) fans.push_back(f.ring);
  std::mt19937 rng(2024);
  for (Shape s : {Shape::kConvex, Shape::kSaddle, Shape::kSliver, Shape::kWild})
    for (int i = 0; i < 10; ++i) fans.push_back(testing_fans::random_fan(rng, s));
  return fans;
}

void expect_same(const FanGeometry& a, const FanGeometry& b, const Vec3 q[3], const std::string& what) {
  auto rot = [&](const Vec3& x) { return q ? testing_fans::rotate(x, q) : x; };
  const MostVisibleResult mva = most_visible_normal(a.face_normals), mvb = most_visible_normal(b.face_normals);
  EXPECT_NEAR(norm(rot(mva.normal) - mvb.normal), 0.0, kInvariance) << what;
  EXPECT_NEAR(mva.visibility, mvb.visibility, kInvariance) << what;
  const MostNormalResult mna = most_normal_normal(a), mnb = most_normal_normal(b);
  EXPECT_EQ(mna.status, mnb.status) << what;
  EXPECT_NEAR(mna.normality, mnb.normality, kInvariance) << what;
  EXPECT_NEAR(mna.visibility, mnb.visibility, kDirection) << what;
  if (mna.status == NormalStatus::kOk) {
    EXPECT_NEAR(norm(rot(mna.normal) - mnb.normal), 0.0, kDirection) << what;
  }
  const Vec3 an_a = weighted_average_normal(a, NormalMethod::kAngle);
  const Vec3 an_b = weighted_average_normal(b, NormalMethod::kAngle);
  EXPECT_NEAR(norm(rot(an_a) - an_b), 0.0, kInvariance) << what;
}

TEST(Invariance, RotationScalingTranslationAndReindexing) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.1, 10.0);
  int id = 0;
  for (const auto& ring : sample_fans()) {
    const FanGeometry g = testing_fans::geometry(ring);
    Vec3 q[3];
    testing_fans::random_rotation(rng, q);
    const double scale = u(rng);
    const Vec3 p{u(rng), -u(rng), u(rng)};
    std::vector<Vec3> moved;
    for (const Vec3& r : ring) moved.push_back(p + scale * testing_fans::rotate(r, q));
    expect_same(g, build_fan_geometry(p, moved, true), q, "rigid+scale fan " + std::to_string(id));
    std::vector<Vec3> shifted(ring.begin() + 1, ring.end());
    shifted.push_back(ring.front());
    expect_same(g, testing_fans::geometry(shifted), nullptr, "reindexed fan " + std::to_string(id));
    std::vector<Vec3> rays;
    for (const Vec3& r : ring) rays.push_back(u(rng) * r);
    const FanGeometry gr = testing_fans::geometry(rays);
    EXPECT_NEAR(norm(most_visible_normal(g.face_normals).normal - most_visible_normal(gr.face_normals).normal), 0.0,
                kInvariance);
    EXPECT_NEAR(most_normal_normal(g).normality, most_normal_normal(gr).normality, kInvariance) << id;
    ++id;
  }
}

TEST(Invariance, ReversedOrientationNegatesMostVisible) {
  for (const auto& ring : sample_fans()) {
    const std::vector<Vec3> rev(ring.rbegin(), ring.rend());
    const MostVisibleResult a = most_visible_normal(testing_fans::geometry(ring).face_normals);
    const MostVisibleResult b = most_visible_normal(testing_fans::geometry(rev).face_normals);
    EXPECT_NEAR(norm(a.normal + b.normal), 0.0, kInvariance);
    EXPECT_NEAR(a.visibility, b.visibility, kInvariance);
  }
}

TEST(Invariance, PlanarRetriangulationKeepsMostVisibleMostNormalAndAngle) {
  // T1 with an extra ring point in the middle of a planar edge, and a convex corner with
  // a split face: the distinct normals and the link are unchanged.
  for (int fan : {0, 1, 9}) {
    const std::vector<Vec3> ring = testing_fans::public_fans()[fan].ring;
    std::vector<Vec3> split = ring;
    split.insert(split.begin() + 1, 0.5 * (ring[0] + ring[1]));
    const FanGeometry a = testing_fans::geometry(ring), b = testing_fans::geometry(split);
    EXPECT_NEAR(norm(most_visible_normal(a.face_normals).normal - most_visible_normal(b.face_normals).normal), 0.0,
                kInvariance);
    const MostNormalResult ma = most_normal_normal(a), mb = most_normal_normal(b);
    EXPECT_NEAR(ma.normality, mb.normality, kInvariance);
    EXPECT_NEAR(norm(weighted_average_normal(a, NormalMethod::kAngle) - weighted_average_normal(b, NormalMethod::kAngle)),
                0.0, kInvariance);
  }
}

TEST(Invariance, OffPlateauPerturbationMovesNormalProportionally) {
  const std::vector<Vec3> t11 = testing_fans::public_fans()[10].ring;
  std::vector<Vec3> moved = t11;
  moved[1][2] += 1e-6;
  const MostNormalResult a = most_normal_normal(testing_fans::geometry(t11));
  const MostNormalResult b = most_normal_normal(testing_fans::geometry(moved));
  EXPECT_LT(angle_between(a.normal, b.normal), 1e-5);
  EXPECT_GT(angle_between(a.normal, b.normal), 0.0);
}

}  // namespace
}  // namespace blayer
