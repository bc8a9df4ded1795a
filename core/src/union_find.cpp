#include "blayer/core/union_find.h"

#include <numeric>
#include <utility>

#include "blayer/core/assert.h"

namespace blayer {

UnionFind::UnionFind(int n) : parent_(n), set_size_(n, 1) {
  BLAYER_ASSERT(n >= 0);
  std::iota(parent_.begin(), parent_.end(), 0);
}

int UnionFind::find(int x) {
  BLAYER_ASSERT_MSG(x >= 0 && x < size(), "element outside the union-find's range");
  while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
  return x;
}

bool UnionFind::unite(int a, int b) {
  a = find(a);
  b = find(b);
  if (a == b) return false;
  if (set_size_[a] < set_size_[b]) std::swap(a, b);
  parent_[b] = a;
  set_size_[a] += set_size_[b];
  return true;
}

}  // namespace blayer
