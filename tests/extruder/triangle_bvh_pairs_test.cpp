// The BVH's pair traversals (TriangleBvh::for_each_overlapping_pair) against the
// brute-force oracle: every pair of boxes tested against every other. Boxes come as the
// extruder makes them (a wavy sheet of triangles and the same sheet lifted by less than
// a triangle's size, so that most boxes overlap several others) and at random; the
// wanted masks are all, none and random.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "blayer/extruder/triangle_bvh.h"

namespace blayer {
namespace {

using Pairs = std::set<std::pair<int, int>>;

// Boxes of an n x n sheet of triangles, lifted by `lift` (in triangle sizes).
std::vector<Box> sheet_boxes(int n, double lift, double wave) {
  auto point = [&](int i, int j) {
    return Vec3{static_cast<double>(i), static_cast<double>(j), lift + wave * std::sin(0.7 * i) * std::cos(0.4 * j)};
  };
  std::vector<Box> boxes;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      boxes.push_back(Box::of_triangle(point(i, j), point(i + 1, j), point(i + 1, j + 1)));
      boxes.push_back(Box::of_triangle(point(i, j), point(i + 1, j + 1), point(i, j + 1)));
    }
  return boxes;
}

std::vector<Box> random_boxes(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> at(0.0, 10.0), size(0.0, 1.5);
  std::vector<Box> boxes(n);
  for (Box& b : boxes) {
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = at(rng);
      b.hi[k] = b.lo[k] + size(rng);
    }
  }
  return boxes;
}

std::vector<char> random_mask(std::mt19937& rng, int n, double share) {
  std::bernoulli_distribution pick(share);
  std::vector<char> m(n);
  for (char& x : m) x = pick(rng) ? 1 : 0;
  return m;
}

Pairs brute_pairs(const std::vector<Box>& a, const std::vector<char>& wanted, const std::vector<Box>& b) {
  Pairs out;
  for (int i = 0; i < static_cast<int>(a.size()); ++i)
    if (wanted[i])
      for (int j = 0; j < static_cast<int>(b.size()); ++j)
        if (a[i].overlaps(b[j])) out.insert({i, j});
  return out;
}

Pairs brute_self_pairs(const std::vector<Box>& a, const std::vector<char>& wanted) {
  Pairs out;
  for (int i = 0; i < static_cast<int>(a.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(a.size()); ++j)
      if ((wanted[i] || wanted[j]) && a[i].overlaps(a[j])) out.insert({i, j});
  return out;
}

// The pairs a traversal visits, with a count of repeats (each must come once).
struct Visited {
  std::mutex m;
  Pairs pairs;
  int repeats = 0;
  void add(int i, int j) {
    const std::lock_guard<std::mutex> lock(m);
    if (!pairs.insert({i, j}).second) ++repeats;
  }
};

void expect_same_pairs_as_brute_force(const std::vector<Box>& a, const std::vector<Box>& b,
                                      const std::vector<char>& wanted) {
  TriangleBvh ta, tb;
  ta.build(a);
  tb.build(b);
  std::vector<char> nodes;
  ta.mark_nodes(wanted, &nodes);
  Visited two, self;
  ta.for_each_overlapping_pair(wanted, nodes, tb, [&](int i, int j) { two.add(i, j); });
  ta.for_each_overlapping_pair(wanted, nodes, [&](int i, int j) { self.add(std::min(i, j), std::max(i, j)); });
  EXPECT_EQ(two.repeats, 0);
  EXPECT_EQ(self.repeats, 0);
  EXPECT_TRUE(two.pairs == brute_pairs(a, wanted, b)) << two.pairs.size() << " pairs against "
                                                      << brute_pairs(a, wanted, b).size();
  EXPECT_TRUE(self.pairs == brute_self_pairs(a, wanted)) << self.pairs.size() << " pairs against "
                                                         << brute_self_pairs(a, wanted).size();
}

TEST(TriangleBvhPairs, LiftedSheetAgainstItsWallFindsEveryOverlapOnce) {
  const std::vector<Box> wall = sheet_boxes(40, 0.0, 0.5);
  const std::vector<Box> front = sheet_boxes(40, 0.3, 0.5);
  std::mt19937 rng(7);
  for (double share : {1.0, 0.0, 0.05, 0.5})
    expect_same_pairs_as_brute_force(front, wall, random_mask(rng, static_cast<int>(front.size()), share));
}

TEST(TriangleBvhPairs, RandomBoxesOfDifferentCountsFindEveryOverlapOnce) {
  std::mt19937 rng(11);
  for (int n : {1, 2, 5, 33, 700}) {
    const std::vector<Box> a = random_boxes(rng, n);
    const std::vector<Box> b = random_boxes(rng, 3 * n + 1);
    expect_same_pairs_as_brute_force(a, b, random_mask(rng, n, 0.7));
    expect_same_pairs_as_brute_force(a, b, std::vector<char>(n, 1));
  }
}

TEST(TriangleBvhPairs, RefittedTreesFindTheNewOverlaps) {
  // The extruder refits one layout to every front: the traversals must follow the
  // refitted boxes, not the ones the layout was built from.
  const std::vector<Box> wall = sheet_boxes(25, 0.0, 0.3);
  std::vector<Box> moved = sheet_boxes(25, 0.2, 0.3);
  std::mt19937 rng(3);
  std::shuffle(moved.begin(), moved.end(), rng);  // a layout that fits the new boxes badly
  TriangleBvh front, base;
  front.build(wall);
  front.refit(moved);
  base.build(wall);
  const std::vector<char> wanted = random_mask(rng, static_cast<int>(moved.size()), 0.6);
  std::vector<char> nodes;
  front.mark_nodes(wanted, &nodes);
  Visited two, self;
  front.for_each_overlapping_pair(wanted, nodes, base, [&](int i, int j) { two.add(i, j); });
  front.for_each_overlapping_pair(wanted, nodes, [&](int i, int j) { self.add(std::min(i, j), std::max(i, j)); });
  EXPECT_TRUE(two.pairs == brute_pairs(moved, wanted, wall));
  EXPECT_TRUE(self.pairs == brute_self_pairs(moved, wanted));
  EXPECT_EQ(two.repeats + self.repeats, 0);
}

}  // namespace
}  // namespace blayer
