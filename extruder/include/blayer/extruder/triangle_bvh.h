// A static bounding-volume hierarchy over axis-aligned boxes (one per triangle), for the
// extruder's proximity rays and the envelope intersection checks.
//
// Why not CGAL's AABB tree: it would pull CGAL (~30 s, ~1 GB per translation unit) into
// the extruder for two simple queries. This tree is a median split on the longest axis
// of the centroid bounds, leaves of <= kLeafSize boxes, built in O(n log n) with the top
// levels in parallel; the layout depends only on the input, so queries and everything
// derived from them are deterministic. Rebuilding it per layer is cheap next to the
// normal solve (see bench/extruder). Each leaf item's own box is stored next to it and
// tested before the item is visited: a leaf's box is the union of up to kLeafSize
// boxes, so without this most visited items would not overlap the query at all and
// would each cost an exact pair test.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer {

struct Box {
  Vec3 lo{0.0, 0.0, 0.0};
  Vec3 hi{0.0, 0.0, 0.0};

  static Box of_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    Box x;
    for (int i = 0; i < 3; ++i) {
      x.lo[i] = std::min({a[i], b[i], c[i]});
      x.hi[i] = std::max({a[i], b[i], c[i]});
    }
    return x;
  }
  bool overlaps(const Box& o) const {
    for (int i = 0; i < 3; ++i)
      if (lo[i] > o.hi[i] || o.lo[i] > hi[i]) return false;
    return true;
  }
};

class TriangleBvh {
 public:
  static constexpr int kLeafSize = 4;

  // Builds over boxes[0..n); item ids passed to visitors are indices into boxes.
  void build(const std::vector<Box>& boxes);

  // Replaces the boxes, keeping the tree's layout (boxes.size() must equal the count the
  // tree was built with): O(n), no sorting. Queries stay exact for any boxes, since every
  // node box is recomputed as the union of its items'; only pruning efficiency depends on
  // the layout. The extruder's fronts share the wall's triangles and stay close to them
  // relative to the surface's extent, so the wall's layout serves every front.
  void refit(const std::vector<Box>& boxes);

  bool empty() const { return nodes_.empty(); }

  // visit(id) for every item whose box overlaps q.
  template <class Visit>
  void for_each_overlap(const Box& q, Visit&& visit) const {
    if (nodes_.empty()) return;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!n.box.overlaps(q)) continue;
      if (n.count > 0) {
        for (int i = n.first; i < n.first + n.count; ++i)
          if (item_box_[i].overlaps(q)) visit(items_[i]);
      } else {
        stack[top++] = n.first;
        stack[top++] = n.first + n.left_nodes;
      }
    }
  }

  // visit(id, &t_max) for every item whose box the segment origin + t*dir, t in
  // [0, t_max], crosses; the visitor may shrink t_max to prune the rest of the search
  // (closest-hit queries).
  template <class Visit>
  void for_each_on_segment(const Vec3& origin, const Vec3& dir, double t_max, Visit&& visit) const {
    if (nodes_.empty()) return;
    Vec3 inv;
    // +inf for an axis-parallel ray, also when the component is -0.0: 1 / -0.0 = -inf
    // would turn the slab of a box whose face holds the origin into (+inf, NaN) and
    // miss it, where (-inf, NaN) keeps it (a NaN bound counts as inside).
    for (int i = 0; i < 3; ++i) inv[i] = 1.0 / (dir[i] == 0.0 ? 0.0 : dir[i]);
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!segment_hits_box(origin, inv, t_max, n.box)) continue;
      if (n.count > 0) {
        for (int i = n.first; i < n.first + n.count; ++i)
          if (segment_hits_box(origin, inv, t_max, item_box_[i])) visit(items_[i], &t_max);
      } else {
        stack[top++] = n.first;
        stack[top++] = n.first + n.left_nodes;
      }
    }
  }

 private:
  struct Node {
    Box box;
    int first = 0;       // leaf: first index into items_; inner: index of the left child
    int count = 0;       // leaf: number of items (> 0); inner: 0
    int left_nodes = 0;  // inner: node count of the left subtree (right child follows it)
  };

  static bool segment_hits_box(const Vec3& o, const Vec3& inv, double t_max, const Box& b) {
    double t0 = 0.0, t1 = t_max;
    for (int i = 0; i < 3; ++i) {
      double a = (b.lo[i] - o[i]) * inv[i], c = (b.hi[i] - o[i]) * inv[i];
      if (a > c) std::swap(a, c);
      // NaN from 0 * inf (origin on a slab plane of a parallel ray) counts as inside.
      if (a == a) t0 = std::max(t0, a);
      if (c == c) t1 = std::min(t1, c);
      if (t0 > t1) return false;
    }
    return true;
  }

  std::vector<Node> nodes_;
  std::vector<int> items_;
  std::vector<Box> item_box_;  // item_box_[i] = boxes[items_[i]]
};

}  // namespace blayer
