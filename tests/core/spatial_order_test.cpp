#include "blayer/core/spatial_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "lcg.h"

namespace blayer {
namespace {

// Oracle: bit b of x, y, z to bit 3b, 3b + 1, 3b + 2, one bit at a time.
std::uint64_t interleaved_by_loop(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  std::uint64_t key = 0;
  for (int b = 0; b < kMortonBitsPerAxis; ++b) {
    key |= static_cast<std::uint64_t>((x >> b) & 1u) << (3 * b);
    key |= static_cast<std::uint64_t>((y >> b) & 1u) << (3 * b + 1);
    key |= static_cast<std::uint64_t>((z >> b) & 1u) << (3 * b + 2);
  }
  return key;
}

bool is_permutation_of_indices(std::vector<int> order, std::size_t n) {
  std::sort(order.begin(), order.end());
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  return order == all;
}

TEST(SpatialOrder, MortonKeysInterleaveTheCellsBitByBit) {
  testing::Lcg rng(7);
  const double cells = 1u << kMortonBitsPerAxis;
  for (int i = 0; i < 10000; ++i) {
    const auto x = static_cast<std::uint32_t>(rng.uniform() * cells);
    const auto y = static_cast<std::uint32_t>(rng.uniform() * cells);
    const auto z = static_cast<std::uint32_t>(rng.uniform() * cells);
    ASSERT_EQ(morton_key(x, y, z), interleaved_by_loop(x, y, z)) << x << " " << y << " " << z;
  }
  const std::uint32_t top = (1u << kMortonBitsPerAxis) - 1;
  EXPECT_EQ(morton_key(top, top, top), interleaved_by_loop(top, top, top));
  EXPECT_EQ(morton_key(top, top, top), (std::uint64_t{1} << 63) - 1);
}

// The Z curve visits the eight octants of the box one after the other, x fastest, then
// each octant's eight sub-octants likewise: points kept off the split planes must come
// in that order of their (octant, sub-octant) labels.
TEST(SpatialOrder, PointsComeOctantByOctantAndSubOctantBySubOctant) {
  testing::Lcg rng(11);
  std::vector<Vec3> points;
  std::vector<int> label;
  // Coordinates in [0, 8) on a grid of quarters plus a small offset: never on the split
  // planes x = 2, 4, 6 of the two levels. Corner points fix the box to [0, 8]^3.
  for (int i = 0; i < 4000; ++i) {
    Vec3 p;
    int octant = 0, sub = 0;
    for (int a = 0; a < 3; ++a) {
      p[a] = 0.25 * static_cast<int>(rng.uniform() * 32) + 0.1;
      const int cell = static_cast<int>(p[a] / 2.0);  // 0..3 along this axis
      octant |= (cell >> 1) << a;
      sub |= (cell & 1) << a;
    }
    points.push_back(p);
    label.push_back(8 * octant + sub);
  }
  points.push_back({0, 0, 0});
  points.push_back({8, 8, 8});
  const std::vector<int> order = morton_order(points);
  ASSERT_TRUE(is_permutation_of_indices(order, points.size()));
  int last = -1;
  for (int i : order) {
    if (i >= static_cast<int>(label.size())) continue;  // the corners
    ASSERT_GE(label[i], last) << "point " << i;
    last = label[i];
  }
}

TEST(SpatialOrder, EqualKeysKeepTheInputOrder) {
  // Two copies of the same points, interleaved: equal keys, so each copy's index must
  // follow the other's in the input order.
  std::vector<Vec3> points;
  for (int i = 0; i < 50; ++i) {
    const Vec3 p{static_cast<double>(i % 7), static_cast<double>(i % 5), static_cast<double>(i % 3)};
    points.push_back(p);
    points.push_back(p);
  }
  const std::vector<int> order = morton_order(points);
  ASSERT_TRUE(is_permutation_of_indices(order, points.size()));
  for (std::size_t k = 0; k + 1 < order.size(); k += 2) {
    EXPECT_EQ(order[k] % 2, 0) << "position " << k;
    EXPECT_EQ(order[k + 1], order[k] + 1) << "position " << k;
  }
}

// A strip 100 long and 0.01 thick, its points alternating between its two faces: with
// cubic cells the thickness spans a few of them and the order runs along the strip. Were
// each axis stretched over the curve's whole range, the thickness would decide first:
// one face, then the other.
TEST(SpatialOrder, AThinStripIsOrderedAlongItsLength) {
  std::vector<Vec3> points;
  for (int i = 0; i < 100; ++i) points.push_back({static_cast<double>(i), 0.0, i % 2 == 0 ? 0.0 : 0.01});
  std::vector<int> along(100);
  std::iota(along.begin(), along.end(), 0);
  EXPECT_EQ(morton_order(points), along);
}

TEST(SpatialOrder, FlatEmptyAndSinglePointSetsAreOrdered) {
  EXPECT_TRUE(morton_order({}).empty());
  EXPECT_EQ(morton_order({{1, 2, 3}}), std::vector<int>{0});
  // All z equal: a zero extent maps to cell 0, and x and y still order the points.
  const std::vector<Vec3> flat{{1, 1, 5}, {0, 0, 5}, {1, 0, 5}, {0, 1, 5}};
  EXPECT_EQ(morton_order(flat), (std::vector<int>{1, 2, 3, 0}));
}

}  // namespace
}  // namespace blayer
