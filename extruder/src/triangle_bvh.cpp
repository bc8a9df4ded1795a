#include "blayer/extruder/triangle_bvh.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

namespace blayer {

namespace {

// Subtrees above this many items are built in parallel; below it the task overhead
// outweighs the work.
constexpr int kParallelBuildItems = 1 << 14;

// The split sizes depend only on the item count, so so does the node count: this lets
// both halves be written concurrently into preassigned node ranges.
int node_count(int n) {
  if (n <= TriangleBvh::kLeafSize) return 1;
  const int l = n / 2;
  return 1 + node_count(l) + node_count(n - l);
}

}  // namespace

void TriangleBvh::build(const std::vector<Box>& boxes) {
  const int n = static_cast<int>(boxes.size());
  nodes_.clear();
  items_.resize(n);
  item_box_.clear();
  if (n == 0) return;
  for (int i = 0; i < n; ++i) items_[i] = i;
  nodes_.resize(node_count(n));
  std::vector<Vec3> centre(n);
  for (int i = 0; i < n; ++i) centre[i] = 0.5 * (boxes[i].lo + boxes[i].hi);

  // Builds the subtree of items_[first, first+count) into nodes_[node ...].
  struct Builder {
    const std::vector<Box>& boxes;
    const std::vector<Vec3>& centre;
    std::vector<Node>& nodes;
    std::vector<int>& items;

    void operator()(int node, int first, int count) const {
      Node& nd = nodes[node];
      Box b = boxes[items[first]];
      Box cb{centre[items[first]], centre[items[first]]};
      for (int i = first + 1; i < first + count; ++i) {
        const Box& x = boxes[items[i]];
        const Vec3& c = centre[items[i]];
        for (int k = 0; k < 3; ++k) {
          b.lo[k] = std::min(b.lo[k], x.lo[k]);
          b.hi[k] = std::max(b.hi[k], x.hi[k]);
          cb.lo[k] = std::min(cb.lo[k], c[k]);
          cb.hi[k] = std::max(cb.hi[k], c[k]);
        }
      }
      nd.box = b;
      if (count <= kLeafSize) {
        nd.first = first;
        nd.count = count;
        return;
      }
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (cb.hi[k] - cb.lo[k] > cb.hi[axis] - cb.lo[axis]) axis = k;
      const int l = count / 2;
      // Ties broken by id so the split is a pure function of the input.
      std::nth_element(items.begin() + first, items.begin() + first + l, items.begin() + first + count,
                       [&](int a, int b2) {
                         const double ca = centre[a][axis], cb2 = centre[b2][axis];
                         return ca < cb2 || (ca == cb2 && a < b2);
                       });
      const int left_nodes = node_count(l);
      nd.count = 0;
      nd.first = node + 1;
      nd.left_nodes = left_nodes;
      if (count > kParallelBuildItems) {
        tbb::parallel_invoke([&] { (*this)(node + 1, first, l); },
                             [&] { (*this)(node + 1 + left_nodes, first + l, count - l); });
      } else {
        (*this)(node + 1, first, l);
        (*this)(node + 1 + left_nodes, first + l, count - l);
      }
    }
  };
  Builder{boxes, centre, nodes_, items_}(0, 0, n);
  item_box_.resize(n);
  for (int i = 0; i < n; ++i) item_box_[i] = boxes[items_[i]];
}

void TriangleBvh::refit(const std::vector<Box>& boxes) {
  const int n = static_cast<int>(items_.size());
  tbb::parallel_for(0, n, [&](int i) { item_box_[i] = boxes[items_[i]]; });
  auto unite = [](Box* a, const Box& b) {
    for (int k = 0; k < 3; ++k) {
      a->lo[k] = std::min(a->lo[k], b.lo[k]);
      a->hi[k] = std::max(a->hi[k], b.hi[k]);
    }
  };
  // Nodes are in preorder (children after their parent), so a reverse sweep sees both
  // children of a node before the node itself.
  for (int i = static_cast<int>(nodes_.size()) - 1; i >= 0; --i) {
    Node& nd = nodes_[i];
    if (nd.count > 0) {
      nd.box = item_box_[nd.first];
      for (int j = nd.first + 1; j < nd.first + nd.count; ++j) unite(&nd.box, item_box_[j]);
    } else {
      nd.box = nodes_[nd.first].box;
      unite(&nd.box, nodes_[nd.first + nd.left_nodes].box);
    }
  }
}

void TriangleBvh::mark_nodes(const std::vector<char>& wanted, std::vector<char>* node_wanted) const {
  node_wanted->assign(nodes_.size(), 0);
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
