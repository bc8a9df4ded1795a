// The BVH's pair traversals (TriangleBvh::for_each_overlapping_pair) against the
// brute-force oracle: every pair of boxes tested against every other; and its segment
// queries against every box's slab test. The trees keep their boxes rounded outwards to
// floats (FloatBox), so a query must find everything the oracle finds on the exact
// boxes, and nothing the oracle does not find on the boxes grown by a float's rounding. Boxes come as the
// extruder makes them (a wavy sheet of triangles and the same sheet lifted by less than
// a triangle's size, so that most boxes overlap several others) and at random; the
// wanted masks are all, none and random.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "blayer/extruder/diagonal_slabs.h"
#include "blayer/extruder/triangle_bvh.h"
#include "blayer/extruder/unit_vector_box.h"

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

// The box grown by a float's rounding: relative 2^-23 of each bound, plus the smallest
// normal float for bounds that round to subnormals.
Box grown(const Box& b) {
  Box g;
  for (int k = 0; k < 3; ++k) {
    g.lo[k] = b.lo[k] - 0x1p-23 * std::fabs(b.lo[k]) - 0x1p-126;
    g.hi[k] = b.hi[k] + 0x1p-23 * std::fabs(b.hi[k]) + 0x1p-126;
  }
  return g;
}

std::vector<Box> grown(const std::vector<Box>& boxes) {
  std::vector<Box> g;
  for (const Box& b : boxes) g.push_back(grown(b));
  return g;
}

// Whether found holds every pair of `exact` and nothing beyond `loose`.
bool between(const Pairs& found, const Pairs& exact, const Pairs& loose) {
  return std::includes(found.begin(), found.end(), exact.begin(), exact.end()) &&
         std::includes(loose.begin(), loose.end(), found.begin(), found.end());
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
  EXPECT_TRUE(between(two.pairs, brute_pairs(a, wanted, b), brute_pairs(grown(a), wanted, grown(b))))
      << two.pairs.size() << " pairs against " << brute_pairs(a, wanted, b).size();
  EXPECT_TRUE(between(self.pairs, brute_self_pairs(a, wanted), brute_self_pairs(grown(a), wanted)))
      << self.pairs.size() << " pairs against " << brute_self_pairs(a, wanted).size();
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
  EXPECT_TRUE(between(two.pairs, brute_pairs(moved, wanted, wall), brute_pairs(grown(moved), wanted, grown(wall))));
  EXPECT_TRUE(between(self.pairs, brute_self_pairs(moved, wanted), brute_self_pairs(grown(moved), wanted)));
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

TEST(TriangleBvhPairs, LargeRefittedTreesFindTheNewOverlaps) {
  // Past a few thousand nodes the refit runs on subtrees in parallel: the node boxes
  // must still hold the new item boxes, for the node-pair descent and for the per-item
  // search alike (both masks). The sheet moves as a whole, as a front does, so that a
  // node box left out would miss items.
  const std::vector<Box> wall = sheet_boxes(92, 0.0, 0.5);
  std::vector<Box> moved = sheet_boxes(92, 0.3, 0.5);
  for (Box& b : moved)
    for (Vec3* corner : {&b.lo, &b.hi}) *corner = *corner + Vec3{3.7, -2.1, 0.0};
  std::mt19937 rng(53);
  TriangleBvh front, base;
  front.build(wall);
  front.refit(moved);
  base.build(wall);
  for (double share : {0.05, 0.01}) {
    const std::vector<char> wanted = random_mask(rng, static_cast<int>(moved.size()), share);
    std::vector<char> nodes;
    front.mark_nodes(wanted, &nodes);
    Visited two;
    front.for_each_overlapping_pair(wanted, nodes, base, [&](int i, int j) { two.add(i, j); });
    EXPECT_EQ(two.repeats, 0);
    EXPECT_TRUE(between(two.pairs, brute_pairs(moved, wanted, wall), brute_pairs(grown(moved), wanted, grown(wall))))
        << share << ": " << two.pairs.size() << " pairs against " << brute_pairs(moved, wanted, wall).size();
  }
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

// A node filter on value boxes (node_value_boxes) prunes only node pairs whose items
// all pass its test: here unit vectors near +x or -x by quarters of the space (as a
// front's normals agree locally), a few NaN, and the filter drops node
// pairs whose vectors all have positive dot products (dot_positive_throughout). Every
// pair whose vectors' dot product is not positive must still come; of the others, which
// are pairs within one quarter, most (three quarters here) do not.
TEST(TriangleBvhPairs, ANodeFilterOnValueBoxesDropsOnlyPairsItsValuesRuleOut) {
  std::mt19937 rng(41);
  std::normal_distribution<double> g;
  const std::vector<Box> a = random_boxes(rng, 1500), b = random_boxes(rng, 1200);
  auto values_of = [&](const std::vector<Box>& boxes) {
    std::vector<Vec3> v;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const double side = (boxes[i].lo[0] < 5.0) == (boxes[i].lo[1] < 7.0) ? 1.0 : -1.0;
      v.push_back(i % 97 == 5 ? Vec3{std::nan(""), 0.0, 0.0}
                              : normalized(Vec3{side, 0.3 * g(rng), 0.3 * g(rng)}));
    }
    return v;
  };
  const std::vector<Vec3> va = values_of(a), vb = values_of(b);
  TriangleBvh ta, tb;
  ta.build(a);
  tb.build(b);
  std::vector<UnitVectorBox> boxes_a, boxes_b;
  ta.node_value_boxes([&](int i) { return va[i]; }, &boxes_a);
  tb.node_value_boxes([&](int j) { return vb[j]; }, &boxes_b);
  const std::vector<char> wanted(a.size(), 1);
  std::vector<char> nodes;
  ta.mark_nodes(wanted, &nodes);
  Visited two;
  ta.for_each_overlapping_pair(
      wanted, nodes, tb, [&](int i, int j) { two.add(i, j); },
      [&](int x, int y) { return !dot_positive_throughout(boxes_a[x], boxes_b[y]); });
  EXPECT_EQ(two.repeats, 0);
  int needed = 0, missed = 0, positive = 0, positive_visited = 0;
  for (const auto& [i, j] : brute_pairs(a, wanted, b)) {
    const bool came = two.pairs.count({i, j}) > 0;
    if (dot(va[i], vb[j]) > 0.0) {
      ++positive;
      positive_visited += came;
    } else {
      ++needed;
      missed += !came;
    }
  }
  const Pairs loose = brute_pairs(grown(a), wanted, grown(b));
  EXPECT_TRUE(std::includes(loose.begin(), loose.end(), two.pairs.begin(), two.pairs.end()));
  EXPECT_EQ(missed, 0) << "of " << needed << " pairs whose dot product is not positive";
  EXPECT_GT(needed, 500);
  EXPECT_GT(positive, 500);
  EXPECT_LT(positive_visited * 2, positive) << positive_visited << " of " << positive << " positive pairs visited";
}

// Triangles as the extruder's CAD fronts have them: slivers across the axes (each a
// long diagonal of an n x n grid cell, nearly parallel to its neighbours' and a tenth
// of a cell off it), lifted copies of them and small random triangles.
using Tri = std::array<Vec3, 3>;
std::vector<Tri> sliver_triangles(std::mt19937& rng, int n, double lift) {
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  std::vector<Tri> out;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double z = lift + 0.1 * std::sin(0.5 * i + 0.3 * j);
      const Vec3 a{i + jitter(rng), j + jitter(rng), z}, b{i + 1 + jitter(rng), j + 1 + jitter(rng), z + 0.05};
      out.push_back({a, b, Vec3{a[0] + 0.5, a[1] + 0.6, z}});
      out.push_back({a, b, Vec3{a[0] + 0.6, a[1] + 0.5, z + 0.02}});
    }
  std::uniform_real_distribution<double> at(0.0, n), small(-0.3, 0.3);
  for (int k = 0; k < n * n / 4; ++k) {
    const Vec3 c{at(rng), at(rng), lift + small(rng)};
    out.push_back({c, c + Vec3{small(rng), small(rng), small(rng)}, c + Vec3{small(rng), small(rng), small(rng)}});
  }
  return out;
}

std::vector<Box> boxes_of(const std::vector<Tri>& t) {
  std::vector<Box> b;
  for (const Tri& x : t) b.push_back(Box::of_triangle(x[0], x[1], x[2]));
  return b;
}

TriangleBvh slabbed_tree(const std::vector<Tri>& t) {
  TriangleBvh tree;
  tree.build(boxes_of(t));
  tree.refit_triangles([&](int i, Vec3* c) { std::copy(t[i].begin(), t[i].end(), c); });
  return tree;
}

// The brute-force pairs without those whose slabs are apart.
Pairs without_apart(const Pairs& pairs, const std::vector<Tri>& a, const std::vector<Tri>& b) {
  Pairs out;
  for (const auto& [i, j] : pairs) {
    const DiagonalSlabs si = DiagonalSlabs::of_triangle(a[i][0], a[i][1], a[i][2]);
    const DiagonalSlabs sj = DiagonalSlabs::of_triangle(b[j][0], b[j][1], b[j][2]);
    if (!si.apart(sj)) out.insert({i, j});
  }
  return out;
}

TEST(TriangleBvhPairs, SlabbedTreesSkipExactlyThePairsWhoseSlabsAreApart) {
  std::mt19937 rng(23);
  const std::vector<Tri> wall = sliver_triangles(rng, 14, 0.0), front = sliver_triangles(rng, 14, 0.08);
  const TriangleBvh tw = slabbed_tree(wall), tf = slabbed_tree(front);
  const std::vector<Box> bw = boxes_of(wall), bf = boxes_of(front);
  for (double share : {1.0, 0.3}) {
    const std::vector<char> wanted = random_mask(rng, static_cast<int>(front.size()), share);
    std::vector<char> nodes;
    tf.mark_nodes(wanted, &nodes);
    Visited two, self;
    tf.for_each_overlapping_pair(wanted, nodes, tw, [&](int i, int j) { two.add(i, j); });
    tf.for_each_overlapping_pair(wanted, nodes, [&](int i, int j) { self.add(std::min(i, j), std::max(i, j)); });
    EXPECT_EQ(two.repeats + self.repeats, 0);
    const Pairs exact_two = without_apart(brute_pairs(bf, wanted, bw), front, wall);
    const Pairs exact_self = without_apart(brute_self_pairs(bf, wanted), front, front);
    EXPECT_TRUE(between(two.pairs, exact_two, without_apart(brute_pairs(grown(bf), wanted, grown(bw)), front, wall)));
    EXPECT_TRUE(between(self.pairs, exact_self, without_apart(brute_self_pairs(grown(bf), wanted), front, front)));
    // The slabs did rule pairs out: the boxes alone overlap in many more.
    EXPECT_LT(2 * exact_two.size(), brute_pairs(bf, wanted, bw).size());
    EXPECT_LT(exact_self.size() + exact_self.size() / 2, brute_self_pairs(bf, wanted).size());
  }
  // A tree refitted by boxes again drops its slabs, and then every box overlap is a pair.
  TriangleBvh boxed = tf;
  boxed.refit(bf);
  const std::vector<char> all(front.size(), 1);
  std::vector<char> nodes;
  boxed.mark_nodes(all, &nodes);
  Visited two;
  boxed.for_each_overlapping_pair(all, nodes, tw, [&](int i, int j) { two.add(i, j); });
  EXPECT_TRUE(between(two.pairs, brute_pairs(bf, all, bw), brute_pairs(grown(bf), all, grown(bw))));
}

TEST(TriangleBvhPairs, PartlyRefittedTreesFollowTheMovedTrianglesOnly) {
  // The checker's repair attempts move a few columns: only their triangles are refitted,
  // the others keep their boxes and slabs. First on a tree that holds no slabs yet
  // (built from boxes: every triangle gets them), then on one that does.
  std::mt19937 rng(29);
  const std::vector<Tri> wall = sliver_triangles(rng, 12, 0.0);
  std::vector<Tri> front = sliver_triangles(rng, 12, 0.08);
  const TriangleBvh tw = slabbed_tree(wall);
  TriangleBvh tf;
  tf.build(boxes_of(front));
  auto corners = [&](int i, Vec3* c) { std::copy(front[i].begin(), front[i].end(), c); };
  std::vector<char> moved(front.size(), 0);
  for (int pass = 0; pass < 3; ++pass) {
    std::fill(moved.begin(), moved.end(), 0);
    if (pass > 0)
      for (std::size_t i = 0; i < front.size(); i += 7 + pass) {
        moved[i] = 1;
        for (Vec3& p : front[i]) p = p + Vec3{0.3, -0.2, 0.05 * pass};
      }
    tf.refit_triangles_where(&moved, corners);
    const std::vector<char> all(front.size(), 1);
    std::vector<char> nodes;
    tf.mark_nodes(all, &nodes);
    Visited two;
    tf.for_each_overlapping_pair(all, nodes, tw, [&](int i, int j) { two.add(i, j); });
    const std::vector<Box> bf = boxes_of(front), bw = boxes_of(wall);
    EXPECT_TRUE(between(two.pairs, without_apart(brute_pairs(bf, all, bw), front, wall),
                        without_apart(brute_pairs(grown(bf), all, grown(bw)), front, wall)))
        << "pass " << pass;
  }
}

TEST(TriangleBvhPairs, ListedRefitsFollowTheMovedTrianglesLikeFlaggedOnes) {
  // The checker's repair attempts refit only the listed triangles and their ancestors
  // (refit_triangles_listed). Over several passes that move scattered triangles far,
  // the tree must find the same pairs as one refitted by flags, and as brute force.
  std::mt19937 rng(31);
  const std::vector<Tri> wall = sliver_triangles(rng, 12, 0.0);
  std::vector<Tri> front = sliver_triangles(rng, 12, 0.08);
  const TriangleBvh tw = slabbed_tree(wall);
  auto corners = [&](int i, Vec3* c) { std::copy(front[i].begin(), front[i].end(), c); };
  TriangleBvh listed, flagged;
  listed.build_triangles(static_cast<int>(front.size()), corners);
  flagged = listed;
  const TriangleBvh::LayoutIndex index = listed.layout_index();
  const std::vector<char> all(front.size(), 1);
  for (int pass = 1; pass <= 4; ++pass) {
    std::vector<char> moved(front.size(), 0);
    std::vector<int> list;
    for (std::size_t i = pass; i < front.size(); i += 5 + 2 * pass) {
      moved[i] = 1;
      list.push_back(static_cast<int>(i));
      for (Vec3& p : front[i]) p = p + Vec3{0.4 * pass, -0.3, 0.1 * pass};
    }
    listed.refit_triangles_listed(list, index, corners);
    flagged.refit_triangles_where(&moved, corners);
    Visited by_list, by_flags;
    std::vector<char> nodes;
    listed.mark_nodes(all, &nodes);
    listed.for_each_overlapping_pair(all, nodes, tw, [&](int i, int j) { by_list.add(i, j); });
    flagged.mark_nodes(all, &nodes);
    flagged.for_each_overlapping_pair(all, nodes, tw, [&](int i, int j) { by_flags.add(i, j); });
    EXPECT_EQ(by_list.pairs, by_flags.pairs) << "pass " << pass;
    const std::vector<Box> bf = boxes_of(front), bw = boxes_of(wall);
    EXPECT_TRUE(between(by_list.pairs, without_apart(brute_pairs(bf, all, bw), front, wall),
                        without_apart(brute_pairs(grown(bf), all, grown(bw)), front, wall)))
        << "pass " << pass;
  }
}

TEST(TriangleBvhPairs, TreesBeyondTheSlabLimitKeepNoSlabs) {
  // Two slivers whose boxes overlap and whose slabs are apart, among kMaxSlabItems
  // small triangles far from them: past the limit the pair is visited.
  std::vector<Tri> t = {Tri{Vec3{0, 0, 0}, Vec3{1, 1, 0}, Vec3{1.01, 0.99, 0}},
                        Tri{Vec3{0.1, -0.1, 0}, Vec3{1.1, 0.9, 0}, Vec3{1.11, 0.89, 0}}};
  ASSERT_TRUE(DiagonalSlabs::of_triangle(t[0][0], t[0][1], t[0][2])
                  .apart(DiagonalSlabs::of_triangle(t[1][0], t[1][1], t[1][2])));
  auto visits_the_slivers = [&] {
    const TriangleBvh tree = slabbed_tree(t);
    std::vector<char> marked(t.size(), 0), nodes;
    marked[0] = 1;
    tree.mark_nodes(marked, &nodes);
    Visited self;
    tree.for_each_overlapping_pair(marked, nodes, [&](int i, int j) { self.add(std::min(i, j), std::max(i, j)); });
    return self.pairs.count({0, 1}) == 1;
  };
  EXPECT_FALSE(visits_the_slivers());  // few items: slabs, the pair is ruled out
  for (int k = 0; static_cast<int>(t.size()) <= TriangleBvh::kMaxSlabItems; ++k) {
    const Vec3 c{10.0 + k % 1000, 10.0 + k / 1000, 5.0};
    t.push_back({c, c + Vec3{0.1, 0, 0}, c + Vec3{0, 0.1, 0}});
  }
  EXPECT_TRUE(visits_the_slivers());
}

// The front after `cur`: each corner slid a little and lifted by less than a
// triangle's size, at random, so that most triangles overlap several of `cur`'s.
std::vector<Tri> next_front(const std::vector<Tri>& cur, std::mt19937& rng) {
  std::vector<Tri> next = cur;
  std::uniform_real_distribution<double> lift(0.03, 0.12), slide(-0.2, 0.2);
  for (Tri& t : next)
    for (Vec3& p : t) p = p + Vec3{slide(rng), slide(rng), lift(rng)};
  return next;
}

// The pairs of a's twin traversal against b, and of the self and two-tree traversals
// it stands for.
struct TwinAndAlone {
  Visited self, twin, self_alone, two_alone;
};
void traverse_three_ways(const TriangleBvh& a, const TriangleBvh& b, const std::vector<char>& wanted,
                         const std::vector<char>& nodes, TwinAndAlone* v) {
  auto unordered = [](Visited& into) { return [&into](int i, int j) { into.add(std::min(i, j), std::max(i, j)); }; };
  a.for_each_overlapping_pair_with_twin(wanted, nodes, b, unordered(v->self), [&](int i, int j) { v->twin.add(i, j); });
  a.for_each_overlapping_pair(wanted, nodes, unordered(v->self_alone));
  a.for_each_overlapping_pair(wanted, nodes, b, [&](int i, int j) { v->two_alone.add(i, j); });
}

// The checker's new front against its current front, a copy of the same tree refitted
// (TriangleBvh::for_each_overlapping_pair_with_twin): one descent must find exactly
// the pairs of the self traversal and of the two-tree traversal, with and without
// slabs, for all, none and some wanted triangles, and after a partial refit.
TEST(TriangleBvhPairs, ATwinTraversalFindsTheSelfAndTwoTreePairsOnce) {
  std::mt19937 rng(37);
  const std::vector<Tri> cur = sliver_triangles(rng, 13, 0.0);
  std::vector<Tri> next = next_front(cur, rng);
  auto corners_of = [](const std::vector<Tri>& t) {
    return [&t](int i, Vec3* c) { std::copy(t[i].begin(), t[i].end(), c); };
  };
  const TriangleBvh current = slabbed_tree(cur);
  TriangleBvh fresh = current;
  fresh.refit_triangles(corners_of(next));
  TriangleBvh boxed_current = current, boxed_fresh = fresh;  // no slabs: every box overlap
  boxed_current.refit(boxes_of(cur));
  boxed_fresh.refit(boxes_of(next));
  auto expect_as_two_traversals = [&](const TriangleBvh& a, const TriangleBvh& b, const std::vector<char>& wanted,
                                      const char* what) {
    std::vector<char> nodes;
    a.mark_nodes(wanted, &nodes);
    TwinAndAlone v;
    traverse_three_ways(a, b, wanted, nodes, &v);
    EXPECT_EQ(v.self.repeats + v.twin.repeats, 0) << what;
    EXPECT_EQ(v.self.pairs, v.self_alone.pairs) << what;
    EXPECT_EQ(v.twin.pairs, v.two_alone.pairs) << what;
    return std::make_pair(v.self.pairs, v.twin.pairs);
  };
  for (double share : {1.0, 0.0, 0.2}) {
    const std::vector<char> wanted = random_mask(rng, static_cast<int>(next.size()), share);
    const auto [self, twin] = expect_as_two_traversals(fresh, current, wanted, "slabs");
    const std::vector<Box> bn = boxes_of(next), bc = boxes_of(cur);
    EXPECT_TRUE(between(self, without_apart(brute_self_pairs(bn, wanted), next, next),
                        without_apart(brute_self_pairs(grown(bn), wanted), next, next)));
    EXPECT_TRUE(between(twin, without_apart(brute_pairs(bn, wanted, bc), next, cur),
                        without_apart(brute_pairs(grown(bn), wanted, grown(bc)), next, cur)));
    const auto [boxed_self, boxed_twin] = expect_as_two_traversals(boxed_fresh, boxed_current, wanted, "boxes");
    EXPECT_TRUE(between(boxed_self, brute_self_pairs(bn, wanted), brute_self_pairs(grown(bn), wanted)));
    EXPECT_TRUE(between(boxed_twin, brute_pairs(bn, wanted, bc), brute_pairs(grown(bn), wanted, grown(bc))));
    if (share > 0.0) {
      // A triangle against its own current place is a pair.
      int own = 0;
      for (const auto& [i, j] : twin) own += i == j;
      EXPECT_GT(own, 0);
    }
  }
  // A repair attempt moves some triangles again; the current front stays.
  std::vector<char> moved(next.size(), 0);
  for (std::size_t i = 0; i < next.size(); i += 5) {
    moved[i] = 1;
    for (Vec3& p : next[i]) p = p + Vec3{0.25, 0.1, -0.05};
  }
  fresh.refit_triangles_where(&moved, corners_of(next));
  const auto [self, twin] = expect_as_two_traversals(fresh, current, moved, "partly refitted");
  const std::vector<Box> bn = boxes_of(next), bc = boxes_of(cur);
  EXPECT_TRUE(between(twin, without_apart(brute_pairs(bn, moved, bc), next, cur),
                      without_apart(brute_pairs(grown(bn), moved, grown(bc)), next, cur)));
}

// The repair attempts' masks: so few wanted triangles (under 1 in kFewWanted) that the
// traversals descend once per wanted triangle. The pairs must be those of brute force,
// each once, in all three traversals: wanted triangles side by side (pairs of two wanted
// ones), alone, one, and none.
TEST(TriangleBvhPairs, FewWantedTrianglesFindEveryPairOnce) {
  std::mt19937 rng(43);
  const std::vector<Tri> cur = sliver_triangles(rng, 20, 0.0);
  const std::vector<Tri> next = next_front(cur, rng);
  const TriangleBvh current = slabbed_tree(cur);
  TriangleBvh fresh = current;
  fresh.refit_triangles([&](int i, Vec3* c) { std::copy(next[i].begin(), next[i].end(), c); });
  const std::vector<Tri> wall_tris = sliver_triangles(rng, 20, -0.05);
  const TriangleBvh wall = slabbed_tree(wall_tris);
  const int n = static_cast<int>(next.size());
  std::vector<std::vector<char>> masks;
  std::vector<char> runs(n, 0);  // neighbours in the sheet's order: many pairs of two wanted ones
  for (int i = 100; i < 100 + n / TriangleBvh::kFewWanted - 1; ++i) runs[i] = 1;
  masks.push_back(runs);
  std::vector<char> scattered(n, 0), one(n, 0);
  for (int i = 7; i < n; i += 2 * TriangleBvh::kFewWanted) scattered[i] = 1;
  masks.push_back(scattered);
  one[n / 2] = 1;
  masks.push_back(one);
  masks.emplace_back(n, 0);
  const std::vector<Box> bn = boxes_of(next), bc = boxes_of(cur), bw = boxes_of(wall_tris);
  for (const std::vector<char>& wanted : masks) {
    const int count = static_cast<int>(std::count(wanted.begin(), wanted.end(), 1));
    ASSERT_LT(count * TriangleBvh::kFewWanted, n);
    std::vector<char> nodes;
    fresh.mark_nodes(wanted, &nodes);
    EXPECT_EQ(nodes.empty(), count > 0) << count;  // no marks: the per-item search
    TwinAndAlone v;
    traverse_three_ways(fresh, current, wanted, nodes, &v);
    const Visited &self = v.self, &twin = v.twin, &self_alone = v.self_alone, &two_alone = v.two_alone;
    EXPECT_EQ(self.repeats + twin.repeats + self_alone.repeats + two_alone.repeats, 0) << count;
    const Pairs exact_self = without_apart(brute_self_pairs(bn, wanted), next, next);
    const Pairs exact_twin = without_apart(brute_pairs(bn, wanted, bc), next, cur);
    const Pairs loose_self = without_apart(brute_self_pairs(grown(bn), wanted), next, next);
    const Pairs loose_twin = without_apart(brute_pairs(grown(bn), wanted, grown(bc)), next, cur);
    for (const Pairs* found : {&self.pairs, &self_alone.pairs})
      EXPECT_TRUE(between(*found, exact_self, loose_self)) << count << ": " << found->size() << " against " << exact_self.size();
    for (const Pairs* found : {&twin.pairs, &two_alone.pairs})
      EXPECT_TRUE(between(*found, exact_twin, loose_twin)) << count << ": " << found->size() << " against " << exact_twin.size();
    if (count > 1) {
      EXPECT_FALSE(exact_twin.empty()) << count;
    }
    if (&wanted == &masks.front()) {  // the run: pairs of two wanted triangles, found from one side only
      int both = 0;
      for (const auto& [i, j] : exact_self) both += wanted[i] && wanted[j];
      EXPECT_GT(both, 0);
    }
    // Against another tree (the wall).
    Visited on_wall;
    fresh.for_each_overlapping_pair(wanted, nodes, wall, [&](int i, int j) { on_wall.add(i, j); });
    EXPECT_EQ(on_wall.repeats, 0);
    EXPECT_TRUE(between(on_wall.pairs, without_apart(brute_pairs(bn, wanted, bw), next, wall_tris),
                        without_apart(brute_pairs(grown(bn), wanted, grown(bw)), next, wall_tris)))
        << count;
  }
}

TEST(TriangleBvhPairs, ATwinOfAnotherLayoutIsRefused) {
  std::mt19937 rng(41);
  TriangleBvh a, b;
  a.build(random_boxes(rng, 40));
  b.build(random_boxes(rng, 41));
  const std::vector<char> all(40, 1);
  std::vector<char> nodes;
  a.mark_nodes(all, &nodes);
  EXPECT_THROW(a.for_each_overlapping_pair_with_twin(all, nodes, b, [](int, int) {}, [](int, int) {}),
               std::logic_error);
}

// Whether the segment o + t d, t in [0, t_max], meets the box: the slab test with the
// reciprocal direction, as the tree computes it (d with no zero component here).
bool brute_segment_hits(const Vec3& o, const Vec3& d, double t_max, const Box& b) {
  double t0 = 0.0, t1 = t_max;
  for (int k = 0; k < 3; ++k) {
    const double inv = 1.0 / d[k];
    double a = (b.lo[k] - o[k]) * inv, c = (b.hi[k] - o[k]) * inv;
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
  }
  return t0 <= t1;
}

// The items a segment query visits, in visiting order, and whether any came twice.
std::vector<int> visited_on_segment(const TriangleBvh& tree, const Vec3& o, const Vec3& d, double t_max,
                                    bool* repeated) {
  std::vector<int> order;
  std::set<int> seen;
  *repeated = false;
  tree.for_each_on_segment(o, d, t_max, [&](int i, double*) {
    order.push_back(i);
    *repeated = *repeated || !seen.insert(i).second;
  });
  return order;
}

void expect_segment_visits_as_brute_force(const TriangleBvh& tree, const std::vector<Box>& boxes, const Vec3& o,
                                          const Vec3& d, double t_max) {
  bool repeated = false;
  const std::vector<int> order = visited_on_segment(tree, o, d, t_max, &repeated);
  std::set<int> expected, loose;
  for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
    if (brute_segment_hits(o, d, t_max, boxes[i])) expected.insert(i);
    if (brute_segment_hits(o, d, t_max, grown(boxes[i]))) loose.insert(i);
  }
  EXPECT_FALSE(repeated);
  const std::set<int> visited(order.begin(), order.end());
  EXPECT_TRUE(std::includes(visited.begin(), visited.end(), expected.begin(), expected.end()) &&
              std::includes(loose.begin(), loose.end(), visited.begin(), visited.end()))
      << boxes.size() << " boxes: " << order.size() << " visited against " << expected.size();
}

TEST(TriangleBvhSegments, EverySegmentVisitsTheBoxesItCrosses) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> at(0.0, 10.0), dir(-1.0, 1.0), len(0.1, 6.0);
  // 70,000 boxes: the subtrees spliced after a parallel build are themselves spliced.
  for (int n : {1, 7, 900, 70000}) {
    const std::vector<Box> boxes = random_boxes(rng, n);
    TriangleBvh tree;
    tree.build(boxes);
    for (int q = 0; q < 20; ++q) {
      const Vec3 d{dir(rng), dir(rng), dir(rng)};
      if (d[0] == 0.0 || d[1] == 0.0 || d[2] == 0.0) continue;
      expect_segment_visits_as_brute_force(tree, boxes, Vec3{at(rng), at(rng), at(rng)}, d, len(rng));
    }
  }
}

TEST(TriangleBvhSegments, SegmentsTouchingBoxFacesAndCornersCountAsCrossing) {
  // Unit boxes on an integer grid and power-of-two directions: the slab bounds are exact,
  // so segments end exactly on faces, run along them and pass through corners.
  std::vector<Box> boxes;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k)
        if ((i + j + k) % 2 == 0) boxes.push_back(Box{{1.0 * i, 1.0 * j, 1.0 * k}, {i + 1.0, j + 1.0, k + 1.0}});
  TriangleBvh tree;
  tree.build(boxes);
  const Vec3 d{0.5, 0.25, 1.0};
  for (double t_max : {1.0, 2.0, 4.0, 8.0})
    for (const Vec3& o : {Vec3{0.0, 0.0, 0.0}, Vec3{1.0, 1.0, -1.0}, Vec3{2.0, 3.0, 0.0}, Vec3{0.5, 2.0, 1.0}})
      expect_segment_visits_as_brute_force(tree, boxes, o, d, t_max);
}

TEST(TriangleBvhSegments, DeeplyGradedBoxesKeepTheTreeShallowEnoughForTheSegmentStack) {
  // 2,000 nested boxes [-2^i, 0] x [0, 1]^2 (i from -1000 to 999): a surface-area split
  // peels off a few of the largest per level, so without a depth cap the tree is
  // hundreds of levels deep and the query's fixed stack overflows.
  std::vector<Box> boxes;
  for (int i = -1000; i < 1000; ++i) boxes.push_back(Box{{-std::ldexp(1.0, i), 0.0, 0.0}, {0.0, 1.0, 1.0}});
  TriangleBvh tree;
  tree.build(boxes);
  // A segment along y at x = -2^-1001, z = 1/2 crosses every box.
  bool repeated = false;
  const std::vector<int> order =
      visited_on_segment(tree, Vec3{-std::ldexp(1.0, -1001), -0.5, 0.5}, Vec3{0.0, 1.0, 0.0}, 2.0, &repeated);
  EXPECT_FALSE(repeated);
  EXPECT_EQ(order.size(), boxes.size());
}

TEST(TriangleBvhPairs, BoxesWithOneCommonCentreAreSplitAndFoundLikeAnyOthers) {
  // 40 identical boxes and 40 concentric ones of growing size: no axis has two distinct
  // centroids, so every split is the median one.
  std::vector<Box> a;
  for (int i = 0; i < 40; ++i) a.push_back(Box{{1.0, 1.0, 1.0}, {2.0, 2.0, 2.0}});
  for (int i = 1; i <= 40; ++i) a.push_back(Box{{1.5 - 0.05 * i, 1.5 - 0.05 * i, 1.5 - 0.05 * i},
                                                {1.5 + 0.05 * i, 1.5 + 0.05 * i, 1.5 + 0.05 * i}});
  std::mt19937 rng(29);
  const std::vector<Box> b = random_boxes(rng, 60);
  expect_same_pairs_as_brute_force(a, b, std::vector<char>(a.size(), 1));
  TriangleBvh tree;
  tree.build(a);
  expect_segment_visits_as_brute_force(tree, a, Vec3{1.31, 0.2, 0.4}, Vec3{0.1, 0.9, 0.7}, 3.0);
}

TEST(TriangleBvhSegments, TheTreeIsTheSameWhateverTheNumberOfThreads) {
  // Above 2^14 items the halves are built concurrently: the layout, and so the order of
  // every query's visits, must not depend on it.
  std::mt19937 rng(31);
  const std::vector<Box> boxes = random_boxes(rng, 40000);
  TriangleBvh parallel, serial;
  parallel.build(boxes);
  tbb::task_arena(1).execute([&] { serial.build(boxes); });
  std::uniform_real_distribution<double> at(0.0, 10.0), dir(0.1, 1.0);
  for (int q = 0; q < 10; ++q) {
    const Vec3 o{at(rng), at(rng), at(rng)}, d{dir(rng), dir(rng), dir(rng)};
    bool r1 = false, r2 = false;
    const std::vector<int> a = visited_on_segment(parallel, o, d, 4.0, &r1);
    const std::vector<int> b = visited_on_segment(serial, o, d, 4.0, &r2);
    EXPECT_FALSE(a.empty());
    EXPECT_TRUE(a == b) << "query " << q;
  }
}

TEST(FloatBox, BoundsAreTheNearestFloatsOutside) {
  const float inf = std::numeric_limits<float>::infinity();
  for (double x : {0.0, -0.0, 0.1, -0.1, 1.0 / 3.0, 1.5, -1.5, 1e-300, -1e-300, 5e-324, 1e-40, 1e300, -1e300,
                   3.4028235677973366e38, 3.5e38, 123456789.123}) {
    const float lo = FloatBox::round_down(x), hi = FloatBox::round_up(x);
    EXPECT_LE(lo, x) << x;
    EXPECT_GE(hi, x) << x;
    // The nearest: the next float inwards is on the other side of x (or x is that float).
    if (lo != x) {
      EXPECT_GT(std::nextafter(lo, inf), x) << x;
    }
    if (hi != x) {
      EXPECT_LT(std::nextafter(hi, -inf), x) << x;
    }
  }
  EXPECT_EQ(FloatBox::round_down(0.75), 0.75f);  // floats stay themselves
  EXPECT_EQ(FloatBox::round_up(0.75), 0.75f);
  EXPECT_TRUE(std::isnan(FloatBox::round_down(std::nan(""))));
}

TEST(TriangleBvhPairs, BoxesTouchingAtBoundsNoFloatHoldsStillOverlap) {
  // 0.1 has no float: each pair touches (or misses by 1e-12, far below a float step)
  // at such a bound. The touching pairs must be found; the near misses may be.
  std::vector<Box> a, b;
  for (int i = 0; i < 50; ++i) {
    const double x = 0.1 * (i + 1);
    a.push_back(Box{{x - 0.05, 0.0, 0.0}, {x, 1.0, 1.0}});
    b.push_back(Box{{x + (i % 2 ? 1e-12 : 0.0), 0.0, 0.0}, {x + 0.01, 1.0, 1.0}});
  }
  const std::vector<char> all(a.size(), 1);
  const Pairs exact = brute_pairs(a, all, b);
  ASSERT_EQ(exact.size(), 25u);  // the touching half; the misses are not exact overlaps
  expect_same_pairs_as_brute_force(a, b, all);
}

// A joined tree (TriangleBvh::join: a known tree's items plus a few, the checker's
// first front) finds the pairs and segment crossings of all its items under their new
// ids, with the slabs of both parts, and keeps finding them after a partial refit.
TEST(TriangleBvhPairs, JoinedTreesFindEveryPairUnderTheShiftedIds) {
  std::mt19937 rng(31);
  const std::vector<Tri> base = sliver_triangles(rng, 12, 0.0), extra = sliver_triangles(rng, 5, 0.04);
  const std::vector<Tri> other = sliver_triangles(rng, 12, 0.08);
  std::vector<Tri> all_tris = base;
  all_tris.insert(all_tris.end(), extra.begin(), extra.end());
  TriangleBvh joined;
  joined.join(slabbed_tree(base), slabbed_tree(extra));
  const TriangleBvh to = slabbed_tree(other);
  auto expect_pairs = [&](const char* when) {
    const std::vector<Box> ba = boxes_of(all_tris), bo = boxes_of(other);
    const std::vector<char> all(all_tris.size(), 1);
    std::vector<char> nodes;
    joined.mark_nodes(all, &nodes);
    Visited two, self;
    joined.for_each_overlapping_pair(all, nodes, to, [&](int i, int j) { two.add(i, j); });
    joined.for_each_overlapping_pair(all, nodes, [&](int i, int j) { self.add(std::min(i, j), std::max(i, j)); });
    EXPECT_EQ(two.repeats + self.repeats, 0) << when;
    EXPECT_TRUE(between(two.pairs, without_apart(brute_pairs(ba, all, bo), all_tris, other),
                        without_apart(brute_pairs(grown(ba), all, grown(bo)), all_tris, other)))
        << when;
    EXPECT_TRUE(between(self.pairs, without_apart(brute_self_pairs(ba, all), all_tris, all_tris),
                        without_apart(brute_self_pairs(grown(ba), all), all_tris, all_tris)))
        << when;
    // The slabs of both parts are kept: pairs were ruled out.
    EXPECT_LT(self.pairs.size(), brute_self_pairs(ba, all).size()) << when;
    for (int s = 0; s < 20; ++s) {
      std::uniform_real_distribution<double> at(0.0, 12.0);
      const Vec3 o{at(rng), at(rng), -1.0}, d = normalized(Vec3{at(rng) - 6.0, at(rng) - 6.0, 3.0});
      expect_segment_visits_as_brute_force(joined, ba, o, d, 5.0);
    }
  };
  expect_pairs("joined");
  // Triangles of both parts move; only they are refitted.
  std::vector<char> moved(all_tris.size(), 0);
  for (std::size_t i = 3; i < all_tris.size(); i += 9) {
    moved[i] = 1;
    for (Vec3& p : all_tris[i]) p = p + Vec3{0.4, 0.1, 0.03};
  }
  joined.refit_triangles_where(&moved, [&](int i, Vec3* c) { std::copy(all_tris[i].begin(), all_tris[i].end(), c); });
  expect_pairs("refitted");
  // An empty part leaves the other's tree.
  TriangleBvh only_base, only_extra;
  only_base.join(slabbed_tree(base), TriangleBvh{});
  only_extra.join(slabbed_tree(std::vector<Tri>{}), slabbed_tree(extra));
  const Vec3 o{0.5, 0.5, -1.0}, d{0.0, 0.0, 1.0};
  expect_segment_visits_as_brute_force(only_base, boxes_of(base), o, d, 5.0);
  expect_segment_visits_as_brute_force(only_extra, boxes_of(extra), o, d, 5.0);
}

}  // namespace
}  // namespace blayer
