#include "blayer/core/union_find.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>
#include <utility>

namespace blayer {
namespace {

// Oracle: connected components by repeated relaxation of labels over the edge list.
std::vector<int> brute_force_labels(int n, const std::vector<std::pair<int, int>>& edges) {
  std::vector<int> label(n);
  for (int i = 0; i < n; ++i) label[i] = i;
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [a, b] : edges) {
      const int m = std::min(label[a], label[b]);
      if (label[a] != m || label[b] != m) {
        label[a] = label[b] = m;
        changed = true;
      }
    }
  }
  return label;
}

TEST(UnionFind, SameSetExactlyWhenConnectedOnRandomGraphs) {
  std::mt19937 rng(3);
  for (int n : {1, 5, 50, 300}) {
    std::uniform_int_distribution<int> node(0, n - 1);
    std::vector<std::pair<int, int>> edges;
    for (int e = 0; e < n * 2 / 3; ++e) edges.emplace_back(node(rng), node(rng));
    UnionFind sets(n);
    int merges = 0;
    for (const auto& [a, b] : edges) merges += sets.unite(a, b) ? 1 : 0;
    const std::vector<int> label = brute_force_labels(n, edges);
    int n_sets = 0;
    for (int i = 0; i < n; ++i) {
      n_sets += label[i] == i;
      for (int j = 0; j < n; ++j) ASSERT_EQ(sets.find(i) == sets.find(j), label[i] == label[j]) << i << " " << j;
    }
    EXPECT_EQ(n - merges, n_sets) << "each successful unite removes one set";
  }
}

TEST(UnionFind, UniteOfOneSetReportsNoMerge) {
  UnionFind sets(3);
  EXPECT_TRUE(sets.unite(0, 1));
  EXPECT_FALSE(sets.unite(1, 0));
  EXPECT_NE(sets.find(2), sets.find(0));
}

TEST(UnionFind, ElementOutsideTheRangeIsAProgrammerError) {
  UnionFind sets(3);
  EXPECT_THROW(sets.find(3), std::logic_error);
  EXPECT_THROW(sets.unite(-1, 0), std::logic_error);
}

}  // namespace
}  // namespace blayer
