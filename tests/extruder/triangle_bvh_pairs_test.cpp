// The BVH's pair traversals (TriangleBvh::for_each_overlapping_pair) against the
// brute-force oracle: every pair of boxes tested against every other; and its segment
// queries against every box's slab test. Boxes come as the
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

TEST(TriangleBvhPairs, TreesLargeEnoughToBeBuiltInParallelFindEveryOverlapOnce) {
  // Above 2^14 items the two halves of a node are built concurrently and spliced.
  const std::vector<Box> wall = sheet_boxes(92, 0.0, 0.5);
  const std::vector<Box> front = sheet_boxes(92, 0.3, 0.5);
  ASSERT_GT(front.size(), 16384u);
  std::mt19937 rng(5);
  expect_same_pairs_as_brute_force(front, wall, random_mask(rng, static_cast<int>(front.size()), 0.02));
}

TEST(TriangleBvhPairs, MixedLongAndSmallBoxesFindEveryOverlapOnce) {
  // Long, thin boxes among small ones (trailing-edge slivers beside a fine mesh): the
  // case the surface-area split separates.
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> at(0.0, 10.0), small(0.0, 0.3), along(3.0, 9.0);
  std::vector<Box> a = random_boxes(rng, 300);
  for (int i = 0; i < 100; ++i) {
    Box b;
    const int axis = i % 3;
    for (int k = 0; k < 3; ++k) {
      b.lo[k] = at(rng);
      b.hi[k] = b.lo[k] + (k == axis ? along(rng) : small(rng));
    }
    a.push_back(b);
  }
  std::shuffle(a.begin(), a.end(), rng);
  const std::vector<Box> b = random_boxes(rng, 500);
  expect_same_pairs_as_brute_force(a, b, std::vector<char>(a.size(), 1));
  expect_same_pairs_as_brute_force(a, b, random_mask(rng, static_cast<int>(a.size()), 0.3));
}

// Whether the segment o + t d, t in [0, t_max], meets the box (slabs, d with no zero
// component).
bool brute_segment_hits(const Vec3& o, const Vec3& d, double t_max, const Box& b) {
  double t0 = 0.0, t1 = t_max;
  for (int k = 0; k < 3; ++k) {
    double a = (b.lo[k] - o[k]) / d[k], c = (b.hi[k] - o[k]) / d[k];
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
  }
  return t0 <= t1;
}

TEST(TriangleBvhSegments, EverySegmentVisitsExactlyTheBoxesItCrosses) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> at(0.0, 10.0), dir(-1.0, 1.0), len(0.1, 6.0);
  for (int n : {1, 7, 900, 20000}) {
    const std::vector<Box> boxes = random_boxes(rng, n);
    TriangleBvh tree;
    tree.build(boxes);
    for (int q = 0; q < 50; ++q) {
      const Vec3 o{at(rng), at(rng), at(rng)};
      Vec3 d{dir(rng), dir(rng), dir(rng)};
      if (d[0] == 0.0 || d[1] == 0.0 || d[2] == 0.0) continue;
      const double t_max = len(rng);
      std::set<int> seen, expected;
      int repeats = 0;
      tree.for_each_on_segment(o, d, t_max, [&](int i, double*) { repeats += !seen.insert(i).second; });
      for (int i = 0; i < n; ++i)
        if (brute_segment_hits(o, d, t_max, boxes[i])) expected.insert(i);
      EXPECT_EQ(repeats, 0);
      EXPECT_TRUE(seen == expected) << n << " boxes, query " << q << ": " << seen.size() << " against "
                                    << expected.size();
    }
  }
}

}  // namespace
}  // namespace blayer
