// The public fans T1-T11 of docs/normals.md: most-visible and most-normal normals, their
// V and D against closed forms, uniqueness flags and plateau tie-breaks.
#include <gtest/gtest.h>

#include <cmath>

#include "blayer/normals/most_normal.h"
#include "blayer/normals/most_visible.h"
#include "blayer/normals/vertex_normal.h"
#include "oracle.h"
#include "test_fans.h"

namespace blayer {
namespace {

using testing_fans::deg;

// |D - D*| for closed forms (docs/normals.md, Part 7).
constexpr double kNormalityAccuracy = 1e-9;
// |V - V*| and direction accuracy of the most-visible normal (docs/normals.md, Part 7).
constexpr double kVisibilityAccuracy = 1e-12;

struct Expected {
  const char* name;
  Vec3 mv;         // most-visible direction (normalised below)
  double d_mv;     // D(MV), radians
  Vec3 mn;         // most-normal direction after tie-break (plateaus: the tie-break point)
  double d_mn;     // D*, radians
  bool plateau;
};

std::vector<Expected> expected() {
  const double s15 = std::sin(deg(15)), c15 = std::cos(deg(15));
  const double asin3 = std::asin(1.0 / std::sqrt(3.0));
  return {
      {"T1", {0, 0, 1}, deg(90), {0, 0, 1}, deg(90), false},
      {"T2", {1, 1, 1}, deg(90) + asin3, {1, 1, 1}, deg(90) + asin3, false},
      {"T3", {1, 1, 1}, asin3, {1, 1, 1}, asin3, false},
      {"T4", {1, 0, 1}, deg(90), {1, 0, 1}, deg(90), true},
      {"T5", {1, 0, 0}, deg(90), {1, 0, 0}, deg(90), true},
      {"T6", {1, 0, 1}, deg(45), {1, 0, 1}, deg(45), false},
      {"T7", {1, 0, 0}, deg(90), {1, 0, 0}, deg(90), true},
      {"T8", {0, 0, 1}, deg(90) - std::atan(0.5), {0, 0, 1}, deg(90) - std::atan(0.5), false},
      {"T9", {0, 0, 1}, deg(120), {0, 0, 1}, deg(120), false},
      {"T10", {1, 1, 1}, asin3, {0.5, 0.5, std::sqrt(0.5)}, deg(45), true},
      {"T11", {1, s15, 0}, deg(104.510819), {1, c15, 0},
       M_PI - std::acos(c15 / std::sqrt(1 + c15 * c15)), false},
  };
}

class PublicFan : public ::testing::TestWithParam<int> {};

TEST_P(PublicFan, MostVisibleMatchesClosedForm) {
  const auto fans = testing_fans::public_fans();
  const Expected e = expected()[GetParam()];
  const FanGeometry g = testing_fans::geometry(fans[GetParam()].ring);
  const oracle::Link link = oracle::make_link(fans[GetParam()].ring);
  const Vec3 n_star = normalized(e.mv);
  const double v_star = oracle::visibility(link, n_star);
  const MostVisibleResult mv = most_visible_normal(g.face_normals);
  ASSERT_TRUE(mv.feasible);
  EXPECT_NEAR(norm(mv.normal - n_star), 0.0, kVisibilityAccuracy) << e.name;
  EXPECT_NEAR(mv.visibility, v_star, kVisibilityAccuracy) << e.name;
  const MostVisibleResult en = most_visible_by_enumeration(g.face_normals.data(), g.n_faces());
  EXPECT_NEAR(norm(en.normal - n_star), 0.0, kVisibilityAccuracy) << e.name;
  // T11's D(MV) is tabulated to 6 decimals of a degree.
  const double d_accuracy = std::string(e.name) == "T11" ? deg(1e-6) : kNormalityAccuracy;
  EXPECT_NEAR(oracle::normality(link, mv.normal), e.d_mv, d_accuracy) << e.name;
  const VertexNormal vn = compute_vertex_normal(g, NormalMethod::kMostVisible);
  EXPECT_EQ(vn.status, NormalStatus::kOk);
  EXPECT_NEAR(vn.normality, e.d_mv, d_accuracy) << e.name;
}

TEST_P(PublicFan, MostNormalMatchesClosedForm) {
  const auto fans = testing_fans::public_fans();
  const Expected e = expected()[GetParam()];
  const FanGeometry g = testing_fans::geometry(fans[GetParam()].ring);
  const oracle::Link link = oracle::make_link(fans[GetParam()].ring);
  const MostNormalResult mn = most_normal_normal(g);
  const double d_indep = oracle::normality(link, mn.normal);
  EXPECT_NEAR(d_indep, e.d_mn, kNormalityAccuracy) << e.name;
  EXPECT_NEAR(mn.normality, d_indep, kNormalityAccuracy) << e.name;
  EXPECT_EQ(oracle::fluid(link, mn.normal), 1) << e.name;
  const Vec3 n_tb = normalized(e.mn);
  const double v_tb = oracle::visibility(link, n_tb);
  if (e.plateau) {
    EXPECT_EQ(mn.status, NormalStatus::kNonUnique) << e.name;
    EXPECT_GE(oracle::visibility(link, mn.normal), v_tb - kNormalityAccuracy) << e.name;
  } else {
    EXPECT_EQ(mn.status, NormalStatus::kOk) << e.name;
    EXPECT_NEAR(norm(mn.normal - n_tb), 0.0, kNormalityAccuracy) << e.name;
  }
  EXPECT_NEAR(mn.visibility, oracle::visibility(link, mn.normal), kVisibilityAccuracy) << e.name;
}

TEST_P(PublicFan, MostNormalIsUnbeatenByOracle) {
  const auto fans = testing_fans::public_fans();
  const FanGeometry g = testing_fans::geometry(fans[GetParam()].ring);
  const oracle::Link link = oracle::make_link(fans[GetParam()].ring);
  const MostNormalResult mn = most_normal_normal(g, default_tolerances(), false);
  const oracle::Best best = oracle::maximise(link, -2.0, 20000, 7u + GetParam());
  EXPECT_GE(mn.normality, best.d - 1e-7) << fans[GetParam()].name;
}

std::string fan_name(const ::testing::TestParamInfo<int>& info) {
  return testing_fans::public_fans()[info.param].name;
}

INSTANTIATE_TEST_SUITE_P(T1toT11, PublicFan, ::testing::Range(0, 11), fan_name);

TEST(PublicFan, PlateauEndsAreHalfADegreeLower) {
  // 0.5 degrees past the plateau end D drops to 89.5 (T4: psi = -0.5 deg).
  const auto fans = testing_fans::public_fans();
  const oracle::Link t4 = oracle::make_link(fans[3].ring);
  const Vec3 past{std::cos(deg(-0.5)), 0.0, std::sin(deg(-0.5))};
  EXPECT_NEAR(oracle::normality(t4, past), deg(89.5), kNormalityAccuracy);
  const FanGeometry g = testing_fans::geometry(fans[3].ring);
  EXPECT_NEAR(fan_normality(g, past), deg(89.5), kNormalityAccuracy);
}

TEST(PublicFan, ReversedConvexCornerGetsConcaveAnswer) {
  auto fans = testing_fans::public_fans();
  std::vector<Vec3> ring(fans[1].ring.rbegin(), fans[1].ring.rend());
  const MostNormalResult mn = most_normal_normal(testing_fans::geometry(ring));
  EXPECT_NEAR(norm(mn.normal + normalized(Vec3{1, 1, 1})), 0.0, kNormalityAccuracy);
  EXPECT_NEAR(mn.normality, std::asin(1.0 / std::sqrt(3.0)), kNormalityAccuracy);
}

}  // namespace
}  // namespace blayer
