#include "blayer/core/surface_area_split.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <vector>

namespace blayer {
namespace {

// Items as point-like boxes of a given half size around their centres.
struct Items {
  std::vector<Vec3> centre;
  std::vector<double> half;
  int split(std::vector<int>* order) const {
    Vec3 clo = centre[(*order)[0]], chi = clo;
    for (int i : *order)
      for (int k = 0; k < 3; ++k) {
        clo[k] = std::min(clo[k], centre[i][k]);
        chi[k] = std::max(chi[k], centre[i][k]);
      }
    return surface_area_split(
        order->data(), static_cast<int>(order->size()), clo, chi,
        [&](int i, Vec3* lo, Vec3* hi) {
          *lo = centre[i] - Vec3{half[i], half[i], half[i]};
          *hi = centre[i] + Vec3{half[i], half[i], half[i]};
        },
        [&](int i) -> const Vec3& { return centre[i]; });
  }
};

std::vector<int> identity(int n) {
  std::vector<int> v(n);
  std::iota(v.begin(), v.end(), 0);
  return v;
}

TEST(SurfaceAreaSplit, SeparatesTwoDistantClusters) {
  Items it;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 40; ++i) {
    it.centre.push_back(Vec3{u(rng), u(rng), u(rng)} + (i % 2 ? Vec3{0, 100, 0} : Vec3{0, 0, 0}));
    it.half.push_back(0.01);
  }
  std::vector<int> order = identity(40);
  const int l = it.split(&order);
  ASSERT_EQ(l, 20);
  // Each side holds one cluster.
  for (int i = 0; i < 40; ++i) EXPECT_EQ(order[i] % 2, i < l ? order[0] % 2 : order[39] % 2) << i;
  EXPECT_NE(order[0] % 2, order[39] % 2);
}

TEST(SurfaceAreaSplit, KeepsALongThinBoxApartFromSmallOnes) {
  // Small boxes along x and one long box centred among them: the median would put the
  // long box with half of the small ones; the least-area split isolates its bin.
  Items it;
  for (int i = 0; i < 31; ++i) {
    it.centre.push_back({static_cast<double>(i), 0.0, 0.0});
    it.half.push_back(0.1);
  }
  it.centre.push_back({31.0, 0.0, 0.0});
  it.half.push_back(50.0);
  std::vector<int> order = identity(32);
  const int l = it.split(&order);
  ASSERT_GT(l, 0);
  ASSERT_LT(l, 32);
  const auto long_at = std::find(order.begin(), order.end(), 31) - order.begin();
  const int long_side = long_at >= l ? 32 - l : l;
  EXPECT_LE(long_side, 2) << "the long box shares its side with " << long_side - 1 << " others";
}

TEST(SurfaceAreaSplit, NeverLeavesASideEmptyAndKeepsEveryItem) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    Items it;
    const int n = 2 + trial % 50;
    for (int i = 0; i < n; ++i) {
      // Graded and clustered positions, some repeated exactly.
      const double x = trial % 3 == 0 ? std::ldexp(1.0, -static_cast<int>(40 * u(rng))) : std::floor(4 * u(rng));
      it.centre.push_back({x, u(rng) < 0.5 ? 0.0 : u(rng), 0.0});
      it.half.push_back(std::ldexp(u(rng), -static_cast<int>(30 * u(rng))));
    }
    std::vector<int> order = identity(n);
    const int l = it.split(&order);
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    ASSERT_EQ(sorted, identity(n)) << "trial " << trial;
    if (l == -1) continue;
    ASSERT_GT(l, 0) << "trial " << trial;
    ASSERT_LT(l, n) << "trial " << trial;
  }
}

TEST(SurfaceAreaSplit, ReportsNoSplitWhenAllCentresCoincide) {
  Items it;
  for (int i = 0; i < 10; ++i) {
    it.centre.push_back({1.0, 2.0, 3.0});
    it.half.push_back(0.1 * (i + 1));
  }
  std::vector<int> order = identity(10);
  EXPECT_EQ(it.split(&order), -1);
}

TEST(SurfaceAreaSplit, NonFiniteCentresGoToTheFirstBin) {
  Items it;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 8; ++i) {
    it.centre.push_back({i < 2 ? nan : static_cast<double>(i), 0.0, 0.0});
    it.half.push_back(0.1);
  }
  std::vector<int> order = identity(8);
  // The centroid bounds of the finite centres; the NaN ones bin as the lowest.
  const int l = surface_area_split(
      order.data(), 8, Vec3{2.0, 0.0, 0.0}, Vec3{7.0, 0.0, 0.0},
      [&](int i, Vec3* lo, Vec3* hi) {
        *lo = it.centre[i] - Vec3{0.1, 0.1, 0.1};
        *hi = it.centre[i] + Vec3{0.1, 0.1, 0.1};
      },
      [&](int i) -> const Vec3& { return it.centre[i]; });
  ASSERT_GT(l, 0);
  ASSERT_LT(l, 8);
  for (int i = 0; i < 8; ++i)
    if (order[i] < 2) {
      EXPECT_LT(i, l) << "NaN centre " << order[i] << " right of the split";
    }
}

}  // namespace
}  // namespace blayer
