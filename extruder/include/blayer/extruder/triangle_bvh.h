// A static bounding-volume hierarchy over axis-aligned boxes (one per triangle), for the
// extruder's proximity rays and the envelope intersection checks.
//
// Why not CGAL's AABB tree: it would pull CGAL (~30 s, ~1 GB per translation unit) into
// the extruder for two simple queries. This tree is split by the binned surface-area
// heuristic down to a fixed depth and at the median below it (triangle_bvh.cpp says
// why), leaves of <= kLeafSize boxes, with the top levels built in parallel; the layout
// depends only on the input, so queries and everything derived from them are
// deterministic. It is built once per run and refitted to every front (refit), which is
// cheap next to the normal solve (see bench/extruder). Each leaf item's own box is
// stored next to it and tested before the item is visited: a leaf's box is the union of
// up to kLeafSize boxes, so without this most visited items would not overlap the query
// at all and would each cost an exact pair test. Triangle items may also carry their
// diagonal slabs (refit_triangles, diagonal_slabs.h), which rule out more pairs there.
//
// All the overlapping pairs of two trees (a new front against the wall, the current
// front and itself) are found by descending both together rather than by one query per
// item: each region of the space is then read once, not once per item near it. The
// results are the same; the memory traffic is not: on the 571k-triangle ONERA M6 the
// extrusion's checks went from 23-30 s to 8-10 s, on the 54k BWB they stayed at 1.1-1.3 s.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>

#include "blayer/core/assert.h"
#include "blayer/core/vec3.h"
#include "blayer/extruder/diagonal_slabs.h"

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

// A box in single precision, rounded outwards so that it holds the box it was made
// from. The trees only prune: every item they pass is decided by the caller's own test,
// so a box larger by a float's rounding changes which items are tried, never a result.
// Half the size of a Box: the boxes are most of a tree's memory, and a run holds three
// trees (the wall and two fronts).
struct FloatBox {
  float lo[3] = {0.0f, 0.0f, 0.0f};
  float hi[3] = {0.0f, 0.0f, 0.0f};

  static FloatBox enclosing(const Box& b) {
    FloatBox f;
    for (int i = 0; i < 3; ++i) {
      f.lo[i] = round_down(b.lo[i]);
      f.hi[i] = round_up(b.hi[i]);
    }
    return f;
  }
  bool overlaps(const FloatBox& o) const {
    for (int i = 0; i < 3; ++i)
      if (lo[i] > o.hi[i] || o.lo[i] > hi[i]) return false;
    return true;
  }
  void unite(const FloatBox& o) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], o.lo[i]);
      hi[i] = std::max(hi[i], o.hi[i]);
    }
  }

  // The largest float <= x and the smallest >= x (+-inf beyond the float range; NaN
  // stays NaN, which overlaps everything, as a NaN double box does).
  static float round_down(double x) {
    if (x > std::numeric_limits<float>::max()) return std::numeric_limits<float>::max();
    if (x < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::infinity();
    float f = static_cast<float>(x);
    // Rounded up (half the time, at random): one step of the bit pattern towards -inf,
    // -1 for a positive float, +1 for a negative one (-0.0 steps to the smallest
    // negative subnormal; +0.0 is never above an x it rounds from). Without a branch: a
    // refit rounds six bounds per item, and their mispredictions cost more than the
    // conversions.
    std::int32_t b;
    std::memcpy(&b, &f, sizeof b);
    const std::int32_t towards_minus_inf = -((b >> 31) | 1);
    b += towards_minus_inf & -static_cast<std::int32_t>(static_cast<double>(f) > x);
    std::memcpy(&f, &b, sizeof f);
    return f;
  }
  static float round_up(double x) { return -round_down(-x); }
};

class TriangleBvh {
 public:
  static constexpr int kLeafSize = 4;

  // Builds over boxes[0..n); item ids passed to visitors are indices into boxes.
  void build(const std::vector<Box>& boxes);
  // This tree becomes one over the items of `base` (ids 0 .. n_base - 1) and those of
  // `extra` (its ids shifted by n_base): a root above base's tree and extra's, their
  // boxes and slabs as they are (slabs kept when both hold them and the sum stays
  // within kMaxSlabItems). For a set that is a known tree's items plus a few: the
  // checker's first front is the wall's triangles plus the fans' strips, whose wall
  // part then costs a copy instead of a build (0.41 s on the ONERA M6 571k).
  void join(const TriangleBvh& base, const TriangleBvh& extra);
  // Builds over n triangles given by their corners (corners_of(i, Vec3 out[3])), with
  // their diagonal slabs as refit_triangles keeps them.
  template <class CornersOf>
  void build_triangles(int n, CornersOf&& corners_of) {
    std::vector<Box> boxes(n);
    tbb::parallel_for(0, n, [&](int i) {
      Vec3 c[3];
      corners_of(i, c);
      boxes[i] = Box::of_triangle(c[0], c[1], c[2]);
    });
    build(boxes);
    if (n > kMaxSlabItems) return;
    item_slabs_.resize(n);
    tbb::parallel_for(0, n, [&](int i) {
      Vec3 c[3];
      corners_of(items_[i], c);
      item_slabs_[i] = DiagonalSlabs::of_triangle(c[0], c[1], c[2]);
    });
  }

  // Replaces the boxes, keeping the tree's layout (boxes.size() must equal the count the
  // tree was built with): O(n), no sorting. Queries stay exact for any boxes, since every
  // node box is recomputed as the union of its items'; only pruning efficiency depends on
  // the layout. The extruder's fronts share the wall's triangles and stay close to them
  // relative to the surface's extent, so the wall's layout serves every front.
  void refit(const std::vector<Box>& boxes);
  // The same with item i's box given by box_of(i), so that callers need not keep the
  // boxes of every item between refits.
  template <class BoxOf>
  void refit_each(BoxOf&& box_of) {
    const int n = static_cast<int>(items_.size());
    item_slabs_.clear();
    tbb::parallel_for(0, n, [&](int i) { item_box_[i] = FloatBox::enclosing(box_of(items_[i])); });
    refit_nodes();
  }
  // The same for triangle items, from their corners (corners_of(item, Vec3 out[3])),
  // with their diagonal slabs (diagonal_slabs.h) stored next to the boxes in leaf
  // order: the pair traversals below then skip the pairs whose slabs are apart, when
  // both trees hold slabs. build, refit and refit_each drop them. A tree of more than
  // kMaxSlabItems items keeps none: the slabs take 48 bytes per item (twice the box),
  // and the checker holds three trees while the run's memory peaks. Kept for every
  // tree, they made the ONERA M6 571k's checks 9 % slower on one thread (memory
  // traffic) and lifted the sliver wing's peak from 102 to 110 MB (its 64k-triangle
  // fronts) for 1.1 % fewer instructions, where they take 7.6 % of the instructions
  // off the perforated block's run (23k).
  static constexpr int kMaxSlabItems = 50000;
  template <class CornersOf>
  void refit_triangles(CornersOf&& corners_of) {
    refit_triangles_where(nullptr, corners_of);
  }
  // The same for the items with changed[item] != 0 only (all of them when changed is
  // null); the others keep their boxes and slabs, which must still be theirs (and
  // exist: after refit_triangles on the same tree).
  template <class CornersOf>
  void refit_triangles_where(const std::vector<char>* changed, CornersOf&& corners_of) {
    const int n = static_cast<int>(items_.size());
    const bool slabs = n <= kMaxSlabItems;
    if (slabs && static_cast<int>(item_slabs_.size()) != n) changed = nullptr;  // none kept yet: all
    if (!changed) item_slabs_.resize(slabs ? n : 0);
    tbb::parallel_for(0, n, [&](int i) {
      if (!changed || (*changed)[items_[i]]) set_triangle_item(i, slabs, corners_of);
    });
    refit_nodes();
  }

  // Where the items and nodes of a tree's layout sit, for refits of a few items: per
  // item its leaf node, per node its parent (-1 at the root). Valid for every tree of
  // the same layout (copies and refits of this one).
  struct LayoutIndex {
    std::vector<int> leaf, parent;
  };
  LayoutIndex layout_index() const;
  // refit_triangles_where for the listed items (each once) on a tree that already holds
  // the other items' boxes and slabs: only the listed items and their ancestors are
  // recomputed, so the nodes end as a full refit leaves them (a union of float boxes
  // is exact). index: this layout's.
  template <class CornersOf>
  void refit_triangles_listed(const std::vector<int>& items, const LayoutIndex& index, CornersOf&& corners_of) {
    const bool slabs = !item_slabs_.empty();
    tbb::parallel_for(std::size_t(0), items.size(), [&](std::size_t k) {
      int i = nodes_[index.leaf[items[k]]].first;
      while (items_[i] != items[k]) ++i;
      set_triangle_item(i, slabs, corners_of);
    });
    refit_ancestors(items, index);
  }

  bool empty() const { return nodes_.empty(); }

  // Per node, a box of another value of its items (unit normals, directions):
  // (*out)[n] = the union of ValueBox::of(value_of(item)) over the items below node n,
  // ValueBox having empty(), of() and unite() as UnitVectorBox has. The bounds of node
  // pair filters (for_each_overlapping_pair); valid until the next build or join.
  // value_of is called from several threads.
  template <class ValueOf, class ValueBox>
  void node_value_boxes(ValueOf&& value_of, std::vector<ValueBox>* out) const {
    const int n = static_cast<int>(nodes_.size());
    out->resize(n);
    // The leaves in parallel: their items' boxes are most of the work (serially, the
    // current front's normal boxes took 22 ms of the perforated block's ten layers).
    tbb::parallel_for(0, n, [&](int i) {
      const Node& nd = nodes_[i];
      if (nd.count == 0) return;
      ValueBox& b = (*out)[i];
      b = ValueBox::empty();
      for (int j = nd.first; j < nd.first + nd.count; ++j) b.unite(ValueBox::of(value_of(items_[j])));
    });
    // Then the inner nodes; in preorder, a reverse sweep sees both children of a node
    // before the node.
    for (int i = n - 1; i >= 0; --i) {
      const Node& nd = nodes_[i];
      if (nd.count > 0) continue;
      ValueBox& b = (*out)[i];
      b = (*out)[nd.first];
      b.unite((*out)[nd.first + nd.left_nodes]);
    }
  }

  // The number of items the tree was built over.
  int size() const { return static_cast<int>(items_.size()); }

  // Which nodes hold an item with wanted[item] != 0, for the pair traversals below
  // (*node_wanted is resized to the node count). Left empty when some but fewer than
  // 1 in kFewWanted items are wanted: the traversals then search once per wanted item
  // and read no marks.
  void mark_nodes(const std::vector<char>& wanted, std::vector<char>* node_wanted) const;

  // visit(i, j) for every item i of this tree with wanted[i] != 0 and every item j of
  // `other` whose boxes overlap; node_wanted from mark_nodes(wanted). Both trees are
  // descended together, so a region of the space is visited once for all the items in
  // it, where one query per item walks the same upper nodes again and again. Pairs are
  // visited from several threads, in no fixed order: visit must be thread-safe.
  template <class Visit>
  void for_each_overlapping_pair(const std::vector<char>& wanted, const std::vector<char>& node_wanted,
                                 const TriangleBvh& other, Visit&& visit) const {
    for_each_overlapping_pair(wanted, node_wanted, other, visit, [](int, int) { return true; });
  }
  // The same, where node_pair_may_visit(a, b) (node a of this tree, b of `other`) may
  // also rule out every pair below a node pair: it returns false only where visit would
  // do nothing with any of them (node_value_boxes gives such filters their bounds). It
  // is a shortcut only, not applied when the search runs once per wanted item.
  template <class Visit, class NodeFilter>
  void for_each_overlapping_pair(const std::vector<char>& wanted, const std::vector<char>& node_wanted,
                                 const TriangleBvh& other, Visit&& visit, NodeFilter&& node_pair_may_visit) const {
    // A pair is tested before it is pushed (only wanted, overlapping pairs are ever
    // popped): most pairs fail, and their push and pop cost more than the test.
    auto wanted_overlap = [&](int a, int b) {
      return node_wanted[a] && nodes_[a].box.overlaps(other.nodes_[b].box) && node_pair_may_visit(a, b);
    };
    if (nodes_.empty() || other.nodes_.empty()) return;
    if (node_wanted.empty()) {
      for_each_wanted_leaf(wanted, [&](int i) { pairs_of_leaf_with(i, other, visit); });
      return;
    }
    if (!wanted_overlap(0, 0)) return;
    auto leaves = [&](const Node& a, const Node& b) {
      for (int i = a.first; i < a.first + a.count; ++i) {
        if (!wanted[items_[i]]) continue;
        for (int j = b.first; j < b.first + b.count; ++j)
          if (item_box_[i].overlaps(other.item_box_[j]) && !slabs_apart(i, other, j))
            visit(items_[i], other.items_[j]);
      }
    };
    auto descend = [&](int a, int b, auto&& push) {
      const Node& na = nodes_[a];
      const Node& nb = other.nodes_[b];
      if (na.count > 0 && nb.count > 0) {
        leaves(na, nb);
      } else {
        split_pair(nodes_, a, other.nodes_, b, [&](int x, int y) {
          if (wanted_overlap(x, y)) push(x, y);
        });
      }
    };
    traverse_pairs(descend);
  }

  // visit(i, j) once for every unordered pair of distinct items of this tree whose boxes
  // overlap and of which at least one is wanted; node_wanted from mark_nodes(wanted).
  // Thread-safe visit, no fixed order, as above.
  template <class Visit>
  void for_each_overlapping_pair(const std::vector<char>& wanted, const std::vector<char>& node_wanted,
                                 Visit&& visit) const {
    if (nodes_.empty()) return;
    if (node_wanted.empty()) {
      for_each_wanted_leaf(wanted, [&](int i) { own_pairs_of_leaf(i, wanted, visit); });
      return;
    }
    if (!node_wanted[0]) return;
    auto pair = [&](int i, int j) {
      if (own_pair_kept(i, j, wanted)) visit(items_[i], items_[j]);
    };
    // Pairs are tested before they are pushed, as above; a node always overlaps itself.
    auto keep = [&](int a, int b, auto&& push) {
      if ((node_wanted[a] || node_wanted[b]) && (a == b || nodes_[a].box.overlaps(nodes_[b].box))) push(a, b);
    };
    traverse_unordered_pairs(
        keep,
        [&](const Node& na) {
          for (int i = na.first; i < na.first + na.count; ++i)
            for (int j = i + 1; j < na.first + na.count; ++j) pair(i, j);
        },
        [&](const Node& na, const Node& nb) {
          for (int i = na.first; i < na.first + na.count; ++i)
            for (int j = nb.first; j < nb.first + nb.count; ++j) pair(i, j);
        });
  }

  // Both traversals above in one, against a twin: a tree of the same layout (a copy of
  // this one, or this one's copy, refitted: the same items in the same leaves), as the
  // checker's new and current fronts are. visit_self(i, j) for every unordered pair of
  // distinct items of this tree as the self traversal gives them, and visit_twin(i, j)
  // for every item i of this tree and j of the twin as the two-tree traversal gives
  // them (i == j included). One descent of the unordered node pairs {a, b} serves both
  // kinds, the twin's pairs in either order, where the two traversals descend the
  // unordered pairs and then the ordered ones: on the perforated block's fronts the
  // node pairs and their reads were most of the checks' traversal time. Thread-safe
  // visits, no fixed order, as above.
  template <class VisitSelf, class VisitTwin>
  void for_each_overlapping_pair_with_twin(const std::vector<char>& wanted, const std::vector<char>& node_wanted,
                                           const TriangleBvh& twin, VisitSelf&& visit_self,
                                           VisitTwin&& visit_twin) const {
    BLAYER_ASSERT_MSG(twin.nodes_.size() == nodes_.size() && twin.items_.size() == items_.size(),
                      "a twin tree has this tree's layout");
    BLAYER_EXPENSIVE_ASSERT(twin.items_ == items_);
    if (nodes_.empty()) return;
    if (node_wanted.empty()) {
      for_each_wanted_leaf(wanted, [&](int i) { pairs_of_leaf_with_twin(i, wanted, twin, visit_self, visit_twin); });
      return;
    }
    if (!node_wanted[0]) return;
    const std::vector<Node>& tn = twin.nodes_;
    // Item pairs at leaf positions i, j.
    auto self_pair = [&](int i, int j) {
      if (own_pair_kept(i, j, wanted)) visit_self(items_[i], items_[j]);
    };
    auto twin_pair = [&](int i, int j) {
      if (wanted[items_[i]] && item_box_[i].overlaps(twin.item_box_[j]) && !slabs_apart(i, twin, j))
        visit_twin(items_[i], items_[j]);
    };
    // Whether node pair {a, b} may hold a pair of either kind.
    auto keep = [&](int a, int b, auto&& push) {
      const bool wa = node_wanted[a], wb = node_wanted[b];
      if (!wa && !wb) return;
      if ((a == b || nodes_[a].box.overlaps(nodes_[b].box)) || (wa && nodes_[a].box.overlaps(tn[b].box)) ||
          (wb && nodes_[b].box.overlaps(tn[a].box)))
        push(a, b);
    };
    auto both_pairs = [&](int i, int j) {
      self_pair(i, j);
      twin_pair(i, j);
      twin_pair(j, i);
    };
    traverse_unordered_pairs(
        keep,
        [&](const Node& na) {
          for (int i = na.first; i < na.first + na.count; ++i) {
            twin_pair(i, i);
            for (int j = i + 1; j < na.first + na.count; ++j) both_pairs(i, j);
          }
        },
        [&](const Node& na, const Node& nb) {
          for (int i = na.first; i < na.first + na.count; ++i)
            for (int j = nb.first; j < nb.first + nb.count; ++j) both_pairs(i, j);
        });
  }

  // visit(id, &t_max) for every item whose box the segment origin + t*dir, t in
  // [0, t_max], crosses; the visitor may shrink t_max to prune the rest of the search
  // (closest-hit queries).
  template <class Visit>
  void for_each_on_segment(const Vec3& origin, const Vec3& dir, double t_max, Visit&& visit) const {
    for_each_on_segment(origin, dir, t_max, visit, [](int) { return true; });
  }
  // The same, where node_may_visit(n) may rule out every item below node n: it returns
  // false only where visit would do nothing with any of them.
  template <class Visit, class NodeFilter>
  void for_each_on_segment(const Vec3& origin, const Vec3& dir, double t_max, Visit&& visit,
                           NodeFilter&& node_may_visit) const {
    if (nodes_.empty()) return;
    Vec3 inv;
    // +inf for an axis-parallel ray, also when the component is -0.0: 1 / -0.0 = -inf
    // would turn the slab of a box whose face holds the origin into (+inf, NaN) and
    // miss it, where (-inf, NaN) keeps it (a NaN bound counts as inside).
    for (int i = 0; i < 3; ++i) inv[i] = 1.0 / (dir[i] == 0.0 ? 0.0 : dir[i]);
    // Holds one entry per level of the current path plus one: the builder caps the
    // depth below 72 (kMaxSurfaceAreaDepth in triangle_bvh.cpp).
    // A node is tested before it is pushed, and again when popped only if a visit has
    // shortened the segment since: the nodes visited are those whose boxes the segment
    // meets when their turn comes, as if each were tested then.
    int stack[128];
    int top = 0;
    const double t_start = t_max;
    if (segment_hits_box(origin, inv, t_max, nodes_[0].box) && node_may_visit(0)) stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (t_max < t_start && !segment_hits_box(origin, inv, t_max, n.box)) continue;
      if (n.count > 0) {
        for (int i = n.first; i < n.first + n.count; ++i)
          if (segment_hits_box(origin, inv, t_max, item_box_[i])) visit(items_[i], &t_max);
      } else {
        for (const int child : {n.first, n.first + n.left_nodes})
          if (segment_hits_box(origin, inv, t_max, nodes_[child].box) && node_may_visit(child)) stack[top++] = child;
      }
    }
  }

  // Below this share of wanted items (1 in kFewWanted; mark_nodes decides), the pair
  // traversals run one descent per wanted item instead of descending node pairs: the
  // checker's repair attempts want a few hundred of the front's triangles, scattered,
  // and the node pairs that lead to them are mostly pairs of their unwanted
  // neighbours' nodes.
  static constexpr int kFewWanted = 32;

 private:
  // Node boxes from the item boxes.
  void refit_nodes();
  // The same for the subtree of node root, whose nodes are [root, end).
  void refit_subtree(int root, int end);
  void refit_node(int i);
  // The box (and slabs) of the triangle at leaf position i, from its corners.
  template <class CornersOf>
  void set_triangle_item(int i, bool slabs, CornersOf& corners_of) {
    Vec3 c[3];
    corners_of(items_[i], c);
    item_box_[i] = FloatBox::enclosing(Box::of_triangle(c[0], c[1], c[2]));
    if (slabs) item_slabs_[i] = DiagonalSlabs::of_triangle(c[0], c[1], c[2]);
  }
  // The leaves of the listed items and every node above them, children first.
  void refit_ancestors(const std::vector<int>& items, const LayoutIndex& index);

  // at_wanted(i) for the leaf position i of every wanted item, in parallel.
  template <class AtWanted>
  void for_each_wanted_leaf(const std::vector<char>& wanted, AtWanted&& at_wanted) const {
    tbb::parallel_for(0, static_cast<int>(items_.size()), [&](int i) {
      if (wanted[items_[i]]) at_wanted(i);
    });
  }

  // visit(j) for the leaf position j of every item of the leaves reached from the root
  // through nodes n with enter(n) (the root's included).
  template <class Enter, class Visit>
  void for_each_leaf_entered(Enter&& enter, Visit&& visit) const {
    if (nodes_.empty() || !enter(0)) return;
    int stack[128];  // one entry per level of the path plus one (depth below 72)
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (n.count > 0) {
        for (int j = n.first; j < n.first + n.count; ++j) visit(j);
      } else {
        for (const int child : {n.first, n.first + n.left_nodes})
          if (enter(child)) stack[top++] = child;
      }
    }
  }

  // visit(j) for the leaf position j of every item whose box overlaps b.
  template <class Visit>
  void for_each_leaf_overlapping(const FloatBox& b, Visit&& visit) const {
    for_each_leaf_entered([&](int node) { return nodes_[node].box.overlaps(b); },
                          [&](int j) {
                            if (item_box_[j].overlaps(b)) visit(j);
                          });
  }

  // Whether the self traversals visit the items at leaf positions i and j: one of them
  // wanted, their boxes overlapping and their slabs (if any) not apart.
  bool own_pair_kept(int i, int j, const std::vector<char>& wanted) const {
    return (wanted[items_[i]] || wanted[items_[j]]) && item_box_[i].overlaps(item_box_[j]) && !slabs_apart(i, *this, j);
  }

  // visit(item at leaf position i, item of `other`) for every item of `other` whose box
  // overlaps leaf position i's and whose slabs (if both have them) are not apart.
  template <class Visit>
  void pairs_of_leaf_with(int i, const TriangleBvh& other, Visit&& visit) const {
    other.for_each_leaf_overlapping(item_box_[i], [&](int j) {
      if (!slabs_apart(i, other, j)) visit(items_[i], other.items_[j]);
    });
  }

  // The self traversal's pairs of wanted leaf position i: each unordered pair once, by
  // the smaller position when both items are wanted.
  template <class Visit>
  void own_pairs_of_leaf(int i, const std::vector<char>& wanted, Visit&& visit) const {
    for_each_leaf_overlapping(item_box_[i], [&](int j) {
      if (j != i && (i < j || !wanted[items_[j]]) && !slabs_apart(i, *this, j)) visit(items_[i], items_[j]);
    });
  }

  // own_pairs_of_leaf(i, wanted, visit_self) and pairs_of_leaf_with(i, twin,
  // visit_twin) in one descent of the layout the two trees share: a node is entered
  // where leaf position i's box overlaps its box in either tree, and each item is
  // tested against i's box in each tree, so the pairs are those of the two descents.
  template <class VisitSelf, class VisitTwin>
  void pairs_of_leaf_with_twin(int i, const std::vector<char>& wanted, const TriangleBvh& twin,
                               VisitSelf&& visit_self, VisitTwin&& visit_twin) const {
    const FloatBox& b = item_box_[i];
    for_each_leaf_entered(
        [&](int node) { return nodes_[node].box.overlaps(b) || twin.nodes_[node].box.overlaps(b); },
        [&](int j) {
          if (j != i && (i < j || !wanted[items_[j]]) && item_box_[j].overlaps(b) && !slabs_apart(i, *this, j))
            visit_self(items_[i], items_[j]);
          if (twin.item_box_[j].overlaps(b) && !slabs_apart(i, twin, j)) visit_twin(items_[i], twin.items_[j]);
        });
  }

  // Which of two nodes the pair traversals split: the larger by the sum of its box's
  // extents (volumes would tie at 0 for the flat boxes of axis-aligned faces).
  static double extent(const FloatBox& b) {
    return (double{b.hi[0]} - b.lo[0]) + (double{b.hi[1]} - b.lo[1]) + (double{b.hi[2]} - b.lo[2]);
  }

  // The unordered node pairs {a, b} of this tree from (0, 0), a pair with a == b
  // standing for the pairs inside node a: within(leaf) for the pairs inside a leaf,
  // across(leaf, leaf) for two leaves, keep(x, y, push) pushing the child pairs worth
  // descending.
  template <class Keep, class Within, class Across>
  void traverse_unordered_pairs(Keep&& keep, Within&& within, Across&& across) const {
    auto descend = [&](int a, int b, auto&& push) {
      const Node& na = nodes_[a];
      const Node& nb = nodes_[b];
      if (a == b) {
        if (na.count > 0) {
          within(na);
        } else {
          const int l = na.first, r = na.first + na.left_nodes;
          keep(l, l, push);
          keep(r, r, push);
          keep(l, r, push);
        }
      } else if (na.count > 0 && nb.count > 0) {
        across(na, nb);
      } else {
        split_pair(nodes_, a, nodes_, b, [&](int x, int y) { keep(x, y, push); });
      }
    };
    traverse_pairs(descend);
  }

  // Node pairs from (0, 0): expanded breadth-first by descend(a, b, push) until there
  // are enough for the threads, then each seed pair's subtree pairs on a stack of its
  // own, in parallel.
  template <class Descend>
  void traverse_pairs(Descend&& descend) const {
    std::vector<std::pair<int, int>> seeds{{0, 0}}, next;
    for (int round = 0; round < 24 && !seeds.empty() && seeds.size() < kPairSeeds; ++round) {
      next.clear();
      for (const auto& [a, b] : seeds) descend(a, b, [&](int x, int y) { next.emplace_back(x, y); });
      seeds.swap(next);
    }
    parallel_pairs(seeds, [&](int a0, int b0) {
      std::pair<int, int> stack[kPairStack];
      int top = 0;
      stack[top++] = {a0, b0};
      while (top > 0) {
        const auto [a, b] = stack[--top];
        descend(a, b, [&](int x, int y) { stack[top++] = {x, y}; });
      }
    });
  }
  static constexpr std::size_t kPairSeeds = 1024;
  // A fixed stack for the depth-first pair traversal (a vector's growth checks were 3 %
  // of a fan-heavy run). Each step pops one pair and pushes at most three, all one level
  // deeper in at least one of the trees, so the stack holds at most two pairs per level
  // of the current path plus one; a path descends each tree below 72 levels (the depth
  // cap of triangle_bvh.cpp), so 2 * 2 * 72 + 1 pairs at most.
  static constexpr int kPairStack = 2 * 2 * 72 + 1;
  // Runs fn(a, b) for every seed pair, in parallel (triangle_bvh.cpp: keeps TBB out of
  // this header).
  static void parallel_pairs(const std::vector<std::pair<int, int>>& seeds,
                             const std::function<void(int, int)>& fn);

  struct Builder;
  struct Node {
    FloatBox box;
    int first = 0;       // leaf: first index into items_; inner: index of the left child
    int count = 0;       // leaf: number of items (> 0); inner: 0
    int left_nodes = 0;  // inner: node count of the left subtree (right child follows it)
  };

  // The slab test in doubles: its bounds grow with the box's (each rounded step is
  // monotone), so a float box passes every segment its double box would.
  static bool segment_hits_box(const Vec3& o, const Vec3& inv, double t_max, const FloatBox& b) {
    double t0 = 0.0, t1 = t_max;
    for (int i = 0; i < 3; ++i) {
      double a = (double{b.lo[i]} - o[i]) * inv[i], c = (double{b.hi[i]} - o[i]) * inv[i];
      if (a > c) std::swap(a, c);
      // NaN from 0 * inf (origin on a slab plane of a parallel ray) counts as inside.
      if (a == a) t0 = std::max(t0, a);
      if (c == c) t1 = std::min(t1, c);
      if (t0 > t1) return false;
    }
    return true;
  }

  // Whether leaf positions i of this tree and j of `other` hold slabs that are apart.
  bool slabs_apart(int i, const TriangleBvh& other, int j) const {
    return !item_slabs_.empty() && !other.item_slabs_.empty() && item_slabs_[i].apart(other.item_slabs_[j]);
  }

  // Pushes the child pairs of node pair (a, b), a node of `an` and b of `bn`, not both
  // leaves: the inner node with the larger box is split (b when a is a leaf).
  template <class Push>
  static void split_pair(const std::vector<Node>& an, int a, const std::vector<Node>& bn, int b, Push&& push) {
    const Node& na = an[a];
    const Node& nb = bn[b];
    if (nb.count > 0 || (na.count == 0 && extent(na.box) >= extent(nb.box))) {
      push(na.first, b);
      push(na.first + na.left_nodes, b);
    } else {
      push(a, nb.first);
      push(a, nb.first + nb.left_nodes);
    }
  }

  std::vector<Node> nodes_;
  std::vector<int> items_;
  std::vector<FloatBox> item_box_;  // item_box_[i] encloses boxes[items_[i]]
  std::vector<DiagonalSlabs> item_slabs_;  // empty, or item i's slabs (refit_triangles)
};

}  // namespace blayer
