#include "blayer/extruder/triangle_bvh.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>

#include "blayer/core/surface_area_split.h"

namespace blayer {

namespace {

// Below this depth nodes are split by surface area, deeper ones at the median. A
// surface-area split may peel off a few items per level (boxes graded over hundreds of
// orders of magnitude), and the segment query's stack holds one entry per level; the
// cap bounds the depth by kMaxSurfaceAreaDepth + log2(n / kLeafSize) + 1 < 72 for any
// int count. Real inputs stay well below it: a model of this builder gave 13 to 35
// levels on graded chains, graded sheets and 20k nested random boxes.
constexpr int kMaxSurfaceAreaDepth = 40;

void unite(Box* a, const Box& b) {
  for (int k = 0; k < 3; ++k) {
    a->lo[k] = std::min(a->lo[k], b.lo[k]);
    a->hi[k] = std::max(a->hi[k], b.hi[k]);
  }
}

// Adds b to the running union *acc of *n boxes.
void accumulate(Box* acc, int* n, const Box& b) {
  if (*n == 0) {
    *acc = b;
  } else {
    unite(acc, b);
  }
  ++*n;
}

}  // namespace

// Builds the subtree of items[first, first + count) in preorder into `nodes` (node
// indices from 0, items' indices absolute); the caller shifts the inner nodes' child
// indices when it places the subtree.
//
// Nodes are split by surface area (core/surface_area_split.h says why). Measured against
// the median split: the extrusion's checks 0.86 -> 0.65 s on the BWB (54k triangles),
// 0.43 -> 0.31 s on the 717 wing, 0.72 -> 0.49 s on the fanned sliver segment, the same
// on the ONERA M6 16k. The result is still a pure function of the input.
struct TriangleBvh::Builder {
  const std::vector<Box>& boxes;
  const std::vector<Vec3>& centre;
  std::vector<int>& items;

  void build(int first, int count, int depth, std::vector<Node>* nodes) const {
    const int node = static_cast<int>(nodes->size());
    nodes->emplace_back();
    Box b, cb;
    int n = 0, nc = 0;
    for (int i = first; i < first + count; ++i) {
      accumulate(&b, &n, boxes[items[i]]);
      accumulate(&cb, &nc, Box{centre[items[i]], centre[items[i]]});
    }
    (*nodes)[node].box = FloatBox::enclosing(b);
    if (count <= kLeafSize) {
      (*nodes)[node].first = first;
      (*nodes)[node].count = count;
      return;
    }
    const int l = depth < kMaxSurfaceAreaDepth ? surface_area_split(first, count, cb) : median_split(first, count, cb);
    (*nodes)[node].count = 0;
    (*nodes)[node].first = node + 1;
    // Each spliced level copies its subtrees once.
    if (build_halves_in_parallel(l, count - l)) {
      std::vector<Node> left, right;
      tbb::parallel_invoke([&] { build(first, l, depth + 1, &left); },
                           [&] { build(first + l, count - l, depth + 1, &right); });
      nodes->reserve(nodes->size() + left.size() + right.size());
      append(left, node + 1, nodes);
      (*nodes)[node].left_nodes = static_cast<int>(left.size());
      append(right, static_cast<int>(nodes->size()), nodes);
    } else {
      build(first, l, depth + 1, nodes);
      (*nodes)[node].left_nodes = static_cast<int>(nodes->size()) - node - 1;
      build(first + l, count - l, depth + 1, nodes);
    }
  }

  // Appends a subtree built from index 0, placed at `offset`.
  static void append(const std::vector<Node>& sub, int offset, std::vector<Node>* nodes) {
    for (Node nd : sub) {
      if (nd.count == 0) nd.first += offset;
      nodes->push_back(nd);
    }
  }

  // Reorders items[first, first + count) so that the left child takes the first l of
  // them, and returns l (0 < l < count): the binned surface-area split
  // (core/surface_area_split.h), or the median split when it finds none.
  int surface_area_split(int first, int count, const Box& cb) const {
    const int l = ::blayer::surface_area_split(
        items.data() + first, count, cb.lo, cb.hi,
        [&](int item, Vec3* lo, Vec3* hi) {
          *lo = boxes[item].lo;
          *hi = boxes[item].hi;
        },
        [&](int item) -> const Vec3& { return centre[item]; });
    return l < 0 ? median_split(first, count, cb) : l;
  }

  // Halves items[first, first + count) at the median centroid of the longest axis of
  // the centroid bounds cb; returns count / 2.
  int median_split(int first, int count, const Box& cb) const {
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (cb.hi[k] - cb.lo[k] > cb.hi[axis] - cb.lo[axis]) axis = k;
    const int l = count / 2;
    // Ties broken by id so the split is a pure function of the input.
    std::nth_element(items.begin() + first, items.begin() + first + l, items.begin() + first + count,
                     [&](int a, int b) {
                       const double ca = centre[a][axis], cb2 = centre[b][axis];
                       return ca < cb2 || (ca == cb2 && a < b);
                     });
    return l;
  }
};

void TriangleBvh::build(const std::vector<Box>& boxes) {
  const int n = static_cast<int>(boxes.size());
  nodes_.clear();
  items_.resize(n);
  item_box_.clear();
  item_slabs_.clear();
  if (n == 0) return;
  for (int i = 0; i < n; ++i) items_[i] = i;
  std::vector<Vec3> centre(n);
  for (int i = 0; i < n; ++i) centre[i] = 0.5 * (boxes[i].lo + boxes[i].hi);
  Builder{boxes, centre, items_}.build(0, n, 0, &nodes_);
  // The node count is known only as the tree grows (leaves hold 1 to kLeafSize items);
  // the vector's growth would otherwise leave up to half of it spare for the run.
  nodes_.shrink_to_fit();
  item_box_.resize(n);
  for (int i = 0; i < n; ++i) item_box_[i] = FloatBox::enclosing(boxes[items_[i]]);
}

void TriangleBvh::join(const TriangleBvh& base, const TriangleBvh& extra) {
  if (extra.nodes_.empty() || base.nodes_.empty()) {
    const bool from_base = extra.nodes_.empty();
    *this = from_base ? base : extra;
    if (!from_base)
      for (int& item : items_) item += static_cast<int>(base.items_.size());
    return;
  }
  const int n_base = static_cast<int>(base.items_.size());
  const int base_nodes = static_cast<int>(base.nodes_.size());
  nodes_.clear();
  nodes_.reserve(1 + base.nodes_.size() + extra.nodes_.size());
  Node root;
  root.box = base.nodes_[0].box;
  root.box.unite(extra.nodes_[0].box);
  root.first = 1;
  root.left_nodes = base_nodes;
  nodes_.push_back(root);
  // Inner nodes name their left child by index, leaves their first item.
  for (Node nd : base.nodes_) {
    if (nd.count == 0) nd.first += 1;
    nodes_.push_back(nd);
  }
  for (Node nd : extra.nodes_) {
    nd.first += nd.count == 0 ? 1 + base_nodes : n_base;
    nodes_.push_back(nd);
  }
  items_ = base.items_;
  items_.reserve(base.items_.size() + extra.items_.size());
  for (int item : extra.items_) items_.push_back(item + n_base);
  item_box_ = base.item_box_;
  item_box_.insert(item_box_.end(), extra.item_box_.begin(), extra.item_box_.end());
  item_slabs_.clear();
  const bool slabs = base.item_slabs_.size() == base.items_.size() && extra.item_slabs_.size() == extra.items_.size() &&
                     items_.size() <= static_cast<std::size_t>(kMaxSlabItems);
  if (slabs) {
    item_slabs_ = base.item_slabs_;
    item_slabs_.insert(item_slabs_.end(), extra.item_slabs_.begin(), extra.item_slabs_.end());
  }
}

void TriangleBvh::refit(const std::vector<Box>& boxes) {
  refit_each([&](int item) { return boxes[item]; });
}

// Node i's box from its items' (a leaf) or its children's boxes.
void TriangleBvh::refit_node(int i) {
  Node& nd = nodes_[i];
  if (nd.count > 0) {
    nd.box = item_box_[nd.first];
    for (int j = nd.first + 1; j < nd.first + nd.count; ++j) nd.box.unite(item_box_[j]);
  } else {
    nd.box = nodes_[nd.first].box;
    nd.box.unite(nodes_[nd.first + nd.left_nodes].box);
  }
}

TriangleBvh::LayoutIndex TriangleBvh::layout_index() const {
  LayoutIndex x;
  x.leaf.resize(items_.size());
  x.parent.assign(nodes_.size(), -1);
  for (int i = 0; i < static_cast<int>(nodes_.size()); ++i) {
    const Node& nd = nodes_[i];
    if (nd.count > 0) {
      for (int j = nd.first; j < nd.first + nd.count; ++j) x.leaf[items_[j]] = i;
    } else {
      x.parent[nd.first] = x.parent[nd.first + nd.left_nodes] = i;
    }
  }
  return x;
}

void TriangleBvh::refit_ancestors(const std::vector<int>& items, const LayoutIndex& index) {
  if (items.empty()) return;
  // Each path stops at the first node already marked, whose ancestors are marked too.
  std::vector<char> marked(nodes_.size(), 0);
  for (int item : items)
    for (int i = index.leaf[item]; i >= 0 && !marked[i]; i = index.parent[i]) marked[i] = 1;
  // Preorder puts every child after its parent: a reverse sweep refits children first.
  for (int i = static_cast<int>(nodes_.size()) - 1; i >= 0; --i)
    if (marked[i]) refit_node(i);
}

void TriangleBvh::refit_nodes() {
  if (!nodes_.empty()) refit_subtree(0, static_cast<int>(nodes_.size()));
}

// Nodes are in preorder: node i's subtree is [i, end), its left child i + 1 and its
// right child i + 1 + left_nodes. Large subtrees refit their halves in parallel (a
// union of float boxes is exact in any order); the others in a reverse sweep, which
// sees both children of a node before the node itself.
void TriangleBvh::refit_subtree(int root, int end) {
  constexpr int kSerialNodes = 4096;
  Node& top = nodes_[root];
  if (top.count == 0 && end - root > kSerialNodes) {
    const int right = top.first + top.left_nodes;
    tbb::parallel_invoke([&] { refit_subtree(top.first, right); }, [&] { refit_subtree(right, end); });
    refit_node(root);
    return;
  }
  for (int i = end - 1; i >= root; --i) refit_node(i);
}

void TriangleBvh::mark_nodes(const std::vector<char>& wanted, std::vector<char>* node_wanted) const {
  const int n = static_cast<int>(items_.size());
  int count = 0;
  for (int i = 0; i < n; ++i) count += wanted[i] != 0;
  if (count > 0 && static_cast<std::int64_t>(count) * kFewWanted < n) {
    node_wanted->clear();
    return;
  }
  node_wanted->assign(nodes_.size(), 0);
  if (count == 0) return;
  // Preorder: a reverse sweep sees both children of a node before the node.
  for (int i = static_cast<int>(nodes_.size()) - 1; i >= 0; --i) {
    const Node& nd = nodes_[i];
    char any = 0;
    if (nd.count > 0) {
      for (int j = nd.first; j < nd.first + nd.count && !any; ++j) any = wanted[items_[j]] != 0;
    } else {
      any = (*node_wanted)[nd.first] || (*node_wanted)[nd.first + nd.left_nodes];
    }
    (*node_wanted)[i] = any;
  }
}

void TriangleBvh::parallel_pairs(const std::vector<std::pair<int, int>>& seeds,
                                 const std::function<void(int, int)>& fn) {
  tbb::parallel_for(std::size_t(0), seeds.size(), [&](std::size_t s) { fn(seeds[s].first, seeds[s].second); });
}

}  // namespace blayer
