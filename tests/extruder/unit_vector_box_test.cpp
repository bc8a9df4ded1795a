// UnitVectorBox against brute force: a box holds the unit vectors it was made from, to
// the exact rational value of its bounds, and dot_positive_throughout claims a positive
// dot product only where every pair of the vectors two boxes were made from has one.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "blayer/extruder/unit_vector_box.h"

namespace blayer {
namespace {

// Whether lo / 127 <= x <= hi / 127 exactly: x * 127 is rounded, so the bounds are
// compared on x with the rational bound's two neighbouring doubles instead.
bool holds(const UnitVectorBox& b, const Vec3& u) {
  for (int i = 0; i < 3; ++i) {
    const double x = u[i];
    const double lo = static_cast<double>(b.lo[i]) / UnitVectorBox::kScale;
    const double hi = static_cast<double>(b.hi[i]) / UnitVectorBox::kScale;
    // lo / 127 rounded may lie above the rational lo / 127 by half an ulp: step down.
    if (!(std::nextafter(lo, -2.0) <= x && x <= std::nextafter(hi, 2.0))) return false;
    if (b.lo[i] > b.hi[i]) return false;
  }
  return true;
}

std::vector<Vec3> cluster(std::mt19937& rng, const Vec3& axis, double spread, int n) {
  std::normal_distribution<double> g;
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) out.push_back(normalized(axis + spread * Vec3{g(rng), g(rng), g(rng)}));
  return out;
}

UnitVectorBox box_of(const std::vector<Vec3>& us) {
  UnitVectorBox b = UnitVectorBox::empty();
  for (const Vec3& u : us) b.unite(UnitVectorBox::of(u));
  return b;
}

TEST(UnitVectorBox, HoldsEveryVectorItIsMadeFrom) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 2000; ++trial) {
    std::normal_distribution<double> g;
    const std::vector<Vec3> us = cluster(rng, normalized(Vec3{g(rng), g(rng), g(rng)}), trial % 2 ? 0.05 : 1.0, 5);
    const UnitVectorBox b = box_of(us);
    for (const Vec3& u : us) EXPECT_TRUE(holds(b, u)) << trial;
  }
  // Exact axes and multiples of 1/127: the bounds may meet the component, never pass it.
  for (const Vec3& u : {Vec3{1.0, 0.0, 0.0}, Vec3{0.0, -1.0, 0.0}, Vec3{3.0 / 127.0, 0.0, 0.0}})
    EXPECT_TRUE(holds(UnitVectorBox::of(u), u));
  // Rounded past 1: clamped, still within a step of the bound.
  const UnitVectorBox over = UnitVectorBox::of(Vec3{std::nextafter(1.0, 2.0), 0.0, 0.0});
  EXPECT_EQ(over.hi[0], UnitVectorBox::kScale);
  // NaN or not a unit vector: the whole cube, which never claims a positive dot
  // product, even against a box of one vector. Clamped to (1, -1, 0), the non-unit
  // (2, -3, 0) would have claimed one with (0.8, 0.6, 0), whose dot product with it is
  // -0.2.
  for (const Vec3& u : {Vec3{std::nan(""), 0.0, 0.0}, Vec3{2.0, -3.0, 0.0}}) {
    const UnitVectorBox b = UnitVectorBox::of(u);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(b.lo[i], -UnitVectorBox::kScale);
      EXPECT_EQ(b.hi[i], UnitVectorBox::kScale);
    }
    EXPECT_FALSE(dot_positive_throughout(b, UnitVectorBox::of(Vec3{0.8, 0.6, 0.0})));
    EXPECT_FALSE(dot_positive_throughout(b, UnitVectorBox::of(Vec3{1.0, 0.0, 0.0})));
  }
}

TEST(UnitVectorBox, PositiveThroughoutOnlyWhereEveryPairHasAPositiveDotProduct) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  int claimed = 0, trials = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Vec3 axis = normalized(Vec3{g(rng), g(rng), g(rng)});
    // The second cluster's axis at a random angle from the first, up to 120 degrees.
    const Vec3 side = normalized(cross(axis, normalized(Vec3{g(rng), g(rng), g(rng)})));
    const double angle = std::uniform_real_distribution<double>(0.0, 2.1)(rng);
    const Vec3 other = std::cos(angle) * axis + std::sin(angle) * side;
    const double spread = trial % 3 == 0 ? 0.02 : trial % 3 == 1 ? 0.2 : 0.6;
    const std::vector<Vec3> a = cluster(rng, axis, spread, 4), b = cluster(rng, other, spread, 4);
    const bool claim = dot_positive_throughout(box_of(a), box_of(b));
    bool all_positive = true;
    for (const Vec3& x : a)
      for (const Vec3& y : b) all_positive = all_positive && dot(x, y) > 0.0;
    ++trials;
    if (claim) {
      ++claimed;
      EXPECT_TRUE(all_positive) << trial;
    }
  }
  EXPECT_GT(claimed, trials / 5);  // the test exercises claims, not only refusals
  EXPECT_FALSE(dot_positive_throughout(UnitVectorBox::empty(), UnitVectorBox::of(Vec3{1.0, 0.0, 0.0})));
  EXPECT_FALSE(dot_positive_throughout(UnitVectorBox::of(Vec3{1.0, 0.0, 0.0}), UnitVectorBox::of(Vec3{0.0, 1.0, 0.0})));
  EXPECT_TRUE(dot_positive_throughout(UnitVectorBox::of(Vec3{1.0, 0.0, 0.0}), UnitVectorBox::of(Vec3{0.6, 0.8, 0.0})));
}

}  // namespace
}  // namespace blayer
