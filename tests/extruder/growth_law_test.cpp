#include "blayer/extruder/growth_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "blayer/core/errors.h"

namespace blayer {
namespace {

// Relative agreement of derived heights: the bisection on log(ratio) converges to ~1e-15,
// and sums of <= 10 terms add a few ulps, so 1e-12 leaves room without hiding errors.
constexpr double kRelTol = 1e-12;

ResolvedGrowthLaw reference() {
  GrowthLaw g;
  g.layers = 8;
  g.first_height = 0.01;
  g.growth_ratio = 1.3;
  return resolve_growth_law(g);
}

TEST(GrowthLaw, FirstHeightAndRatioGiveGeometricHeights) {
  const ResolvedGrowthLaw r = reference();
  ASSERT_EQ(r.heights.size(), 8u);
  double total = 0.0;
  for (int k = 0; k < 8; ++k) {
    EXPECT_NEAR(r.heights[k], 0.01 * std::pow(1.3, k), kRelTol * r.heights[k]);
    total += r.heights[k];
  }
  EXPECT_NEAR(r.total_thickness, 0.01 * (std::pow(1.3, 8) - 1.0) / 0.3, kRelTol * total);
  EXPECT_NEAR(r.last_height, 0.01 * std::pow(1.3, 7), kRelTol * r.last_height);
  EXPECT_DOUBLE_EQ(r.growth_ratio, 1.3);
}

TEST(GrowthLaw, EveryPairOfQuantitiesReproducesTheSameLaw) {
  const ResolvedGrowthLaw ref = reference();
  const double values[4] = {ref.first_height, ref.last_height, ref.total_thickness, ref.growth_ratio};
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      GrowthLaw g;
      g.layers = 8;
      double* field[4] = {&g.first_height, &g.last_height, &g.total_thickness, &g.growth_ratio};
      *field[a] = values[a];
      *field[b] = values[b];
      const ResolvedGrowthLaw r = resolve_growth_law(g);
      SCOPED_TRACE(testing::Message() << "given quantities " << a << " and " << b);
      ASSERT_EQ(r.heights.size(), ref.heights.size());
      for (std::size_t k = 0; k < r.heights.size(); ++k)
        EXPECT_NEAR(r.heights[k], ref.heights[k], kRelTol * ref.heights[k]);
      EXPECT_NEAR(r.growth_ratio, ref.growth_ratio, kRelTol);
      EXPECT_NEAR(r.total_thickness, ref.total_thickness, kRelTol * ref.total_thickness);
    }
}

TEST(GrowthLaw, ShrinkingLayersFromLastAndTotal) {
  GrowthLaw g;
  g.layers = 5;
  g.last_height = 0.1;
  g.total_thickness = 1.0;  // total/last = 10 > 5: layers must shrink outward (ratio < 1)
  const ResolvedGrowthLaw r = resolve_growth_law(g);
  EXPECT_LT(r.growth_ratio, 1.0);
  EXPECT_NEAR(r.heights.back(), 0.1, kRelTol);
  double total = 0.0;
  for (double h : r.heights) total += h;
  EXPECT_NEAR(total, 1.0, kRelTol);
}

TEST(GrowthLaw, OneHeightAloneUsesTheDefaultRatio) {
  GrowthLaw g;
  g.total_thickness = 2.0;
  const ResolvedGrowthLaw r = resolve_growth_law(g);
  EXPECT_EQ(r.layers, 10);
  EXPECT_DOUBLE_EQ(r.growth_ratio, kDefaultGrowthRatio);
  EXPECT_NEAR(r.total_thickness, 2.0, kRelTol * 2.0);
}

TEST(GrowthLaw, FirstAndTotalOfUniformLayersGiveRatioOne) {
  GrowthLaw g;
  g.layers = 4;
  g.first_height = 0.25;
  g.total_thickness = 1.0;
  const ResolvedGrowthLaw r = resolve_growth_law(g);
  EXPECT_NEAR(r.growth_ratio, 1.0, 1e-12);
  for (double h : r.heights) EXPECT_NEAR(h, 0.25, kRelTol);
}

TEST(GrowthLaw, SingleLayerAcceptsConsistentPairs) {
  GrowthLaw g;
  g.layers = 1;
  g.first_height = 0.3;
  g.total_thickness = 0.3;
  const ResolvedGrowthLaw r = resolve_growth_law(g);
  ASSERT_EQ(r.heights.size(), 1u);
  EXPECT_DOUBLE_EQ(r.heights[0], 0.3);
  EXPECT_DOUBLE_EQ(r.last_height, 0.3);
}

TEST(GrowthLaw, RelativeFlagIsKept) {
  GrowthLaw g;
  g.first_height = 0.05;
  g.relative = true;
  EXPECT_TRUE(resolve_growth_law(g).relative);
}

TEST(GrowthLaw, RejectsTooFewQuantities) {
  GrowthLaw g;  // nothing but N
  EXPECT_THROW(resolve_growth_law(g), InputError);
  g.growth_ratio = 1.1;  // a ratio alone fixes no length
  EXPECT_THROW(resolve_growth_law(g), InputError);
}

// first, last and total all given: one too many.
GrowthLaw three_heights() {
  GrowthLaw g;
  g.first_height = 0.1;
  g.last_height = 0.2;
  g.total_thickness = 1.0;
  return g;
}

TEST(GrowthLaw, RejectsTooManyQuantities) {
  GrowthLaw g = three_heights();
  EXPECT_THROW(resolve_growth_law(g), InputError);
  g.total_thickness = 0.0;
  g.growth_ratio = 1.2;
  EXPECT_THROW(resolve_growth_law(g), InputError);
}

TEST(GrowthLaw, RejectsBadLayerCounts) {
  GrowthLaw g;
  g.first_height = 0.1;
  g.layers = 0;
  EXPECT_THROW(resolve_growth_law(g), InputError);
  g.layers = kMaxLayers + 1;
  EXPECT_THROW(resolve_growth_law(g), InputError);
  g.layers = kMaxLayers;
  g.growth_ratio = 1.0;
  EXPECT_NO_THROW(resolve_growth_law(g));
}

TEST(GrowthLaw, RejectsNegativeAndNonFiniteValues) {
  GrowthLaw g;
  g.first_height = -0.1;
  EXPECT_THROW(resolve_growth_law(g), InputError);
  g.first_height = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(resolve_growth_law(g), InputError);
  g.first_height = std::numeric_limits<double>::infinity();
  EXPECT_THROW(resolve_growth_law(g), InputError);
  g.first_height = 0.1;
  g.growth_ratio = -1.2;
  EXPECT_THROW(resolve_growth_law(g), InputError);
}

TEST(GrowthLaw, RejectsInconsistentPairs) {
  GrowthLaw g;
  g.layers = 5;
  g.first_height = 0.5;
  g.total_thickness = 0.4;  // total below the first layer
  EXPECT_THROW(resolve_growth_law(g), InputError);
  g.total_thickness = 0.5;  // equal: the other four layers would be empty
  EXPECT_THROW(resolve_growth_law(g), InputError);

  GrowthLaw l;
  l.layers = 5;
  l.last_height = 0.5;
  l.total_thickness = 0.3;
  EXPECT_THROW(resolve_growth_law(l), InputError);

  GrowthLaw one;
  one.layers = 1;
  one.first_height = 0.1;
  one.last_height = 0.2;
  EXPECT_THROW(resolve_growth_law(one), InputError);
}

TEST(GrowthLaw, ErrorMessageNamesTheFields) {
  const GrowthLaw g = three_heights();
  try {
    resolve_growth_law(g);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("first_height"), std::string::npos) << m;
    EXPECT_NE(m.find("growth_ratio"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace blayer
