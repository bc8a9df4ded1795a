#include "blayer/core/percentile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace blayer {
namespace {

// Oracle: a full sort and the nearest rank floor(q (n - 1)).
double sorted_rank(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::floor(q * static_cast<double>(v.size() - 1)))];
}

TEST(Percentile, SmallArraysGiveTheNearestLowerRank) {
  const std::vector<double> v{5, 1, 4, 2, 3};
  EXPECT_EQ(percentile(v, 0.0), 1.0);
  EXPECT_EQ(percentile(v, 0.5), 3.0);
  EXPECT_EQ(percentile(v, 0.74), 3.0);  // floor(0.74 * 4) = 2
  EXPECT_EQ(percentile(v, 0.75), 4.0);
  EXPECT_EQ(percentile(v, 1.0), 5.0);
  EXPECT_EQ(percentile({7.5}, 0.3), 7.5);
}

TEST(Percentile, AgreesWithAFullSortOnRandomArrays) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(-1e3, 1e3);
  const std::vector<double> qs{0.0, 0.01, 0.05, 0.5, 0.95, 0.99, 1.0};
  for (int n : {1, 2, 3, 10, 101, 1000}) {
    std::vector<double> v(n);
    for (double& x : v) x = std::round(value(rng));  // rounded: many ties
    const std::vector<double> got = percentiles(v, qs);
    for (std::size_t i = 0; i < qs.size(); ++i) {
      EXPECT_EQ(got[i], sorted_rank(v, qs[i])) << "n " << n << " q " << qs[i];
      EXPECT_EQ(percentile(v, qs[i]), sorted_rank(v, qs[i])) << "n " << n << " q " << qs[i];
    }
  }
}

TEST(Percentile, EmptyArrayGivesNaN) {
  EXPECT_TRUE(std::isnan(percentile({}, 0.5)));
  EXPECT_TRUE(std::isnan(percentiles({}, {0.1, 0.9})[1]));
}

TEST(Percentile, RanksOutsideTheUnitIntervalOrDescendingAreProgrammerErrors) {
  EXPECT_THROW(percentile({1, 2}, 1.5), std::logic_error);
  EXPECT_THROW(percentile({1, 2}, -0.1), std::logic_error);
  EXPECT_THROW(percentiles({1, 2}, {0.9, 0.1}), std::logic_error);
}

}  // namespace
}  // namespace blayer
