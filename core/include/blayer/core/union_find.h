// Disjoint sets over the integers [0, n) (union-find with path halving and union by
// size): near-constant amortised time per operation.
// Precondition (BLAYER_ASSERT): every element lies in [0, n).
#pragma once

#include <vector>

namespace blayer {

class UnionFind {
 public:
  explicit UnionFind(int n);

  // Representative of x's set; the same for all members until the next unite().
  int find(int x);
  // Merges the sets of a and b; false when they were one set already.
  bool unite(int a, int b);
  int size() const { return static_cast<int>(parent_.size()); }

 private:
  std::vector<int> parent_;
  std::vector<int> set_size_;
};

}  // namespace blayer
