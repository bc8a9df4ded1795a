#include "nearest_triangle.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "blayer/core/surface_area_split.h"

namespace blayer {
namespace detail {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  // The plane of the triangle is split into seven regions (three vertices, three edges,
  // the interior) by the signs of dot products with the edge vectors; each region has its
  // own closed-form nearest point.
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {
    // A collapsed triangle that slipped through the region tests (all three areas
    // zero): its nearest point lies on one of its edges.
    auto on_segment = [&](const Vec3& s, const Vec3& t) {
      const Vec3 st = t - s;
      const double l2 = norm2(st);
      const double u = l2 > 0.0 ? std::clamp(dot(p - s, st) / l2, 0.0, 1.0) : 0.0;
      return s + u * st;
    };
    Vec3 best = on_segment(a, b);
    for (const Vec3& q : {on_segment(b, c), on_segment(c, a)})
      if (norm2(q - p) < norm2(best - p)) best = q;
    return best;
  }
  return a + (vb / sum) * ab + (vc / sum) * ac;
}

namespace {

double box_distance2(const Vec3& p, const Vec3& lo, const Vec3& hi) {
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double e = std::max({lo[k] - p[k], 0.0, p[k] - hi[k]});
    d2 += e * e;
  }
  return d2;
}

}  // namespace

void NearestTriangleTree::triangle_box(int t, Vec3* lo, Vec3* hi) const {
  const Triangle& tri = surface_.triangles[t];
  *lo = *hi = surface_.points[tri[0]];
  for (int v = 1; v < 3; ++v)
    for (int k = 0; k < 3; ++k) {
      (*lo)[k] = std::min((*lo)[k], surface_.points[tri[v]][k]);
      (*hi)[k] = std::max((*hi)[k], surface_.points[tri[v]][k]);
    }
}

// Builds the subtree of order_[begin, end) in preorder into `nodes`, numbered from 0
// there; the caller shifts a subtree's child indices when it places it. Large subtrees
// (build_halves_in_parallel) build their two halves in parallel (their ranges of order_
// are disjoint) and splice them in order, so the nodes are those of a serial preorder
// build.
struct NearestTriangleTree::Builder {
  NearestTriangleTree& tree;
  const std::vector<std::array<Vec3, 2>>& boxes;

  int build(int begin, int end, int depth, std::vector<Node>* nodes) const {
    std::vector<int>& order = tree.order_;
    const std::vector<Vec3>& centroid = tree.centroid_;
    Node node;
    const double inf = std::numeric_limits<double>::infinity();
    node.lo = {inf, inf, inf};
    node.hi = {-inf, -inf, -inf};
    Vec3 clo = node.lo, chi = node.hi;
    for (int i = begin; i < end; ++i) {
      const std::array<Vec3, 2>& box = boxes[order[i]];
      for (int k = 0; k < 3; ++k) {
        node.lo[k] = std::min(node.lo[k], box[0][k]);
        node.hi[k] = std::max(node.hi[k], box[1][k]);
        clo[k] = std::min(clo[k], centroid[order[i]][k]);
        chi[k] = std::max(chi[k], centroid[order[i]][k]);
      }
    }
    node.begin = begin;
    node.end = end;
    const int id = static_cast<int>(nodes->size());
    nodes->push_back(node);
    if (end - begin <= kLeafSize) return id;
    int mid = -1;
    if (depth < kMaxSurfaceAreaDepth) {
      const int l = surface_area_split(
          order.data() + begin, end - begin, clo, chi,
          [&](int t, Vec3* lo, Vec3* hi) {
            *lo = boxes[t][0];
            *hi = boxes[t][1];
          },
          [&](int t) -> const Vec3& { return centroid[t]; });
      if (l > 0) mid = begin + l;
    }
    if (mid < 0) {
      int axis = 0;
      for (int k = 1; k < 3; ++k)
        if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
      mid = begin + (end - begin) / 2;
      std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                       [&](int x, int y) { return centroid[x][axis] < centroid[y][axis]; });
    }
    if (build_halves_in_parallel(mid - begin, end - mid)) {
      std::vector<Node> left, right;
      tbb::parallel_invoke([&] { build(begin, mid, depth + 1, &left); },
                           [&] { build(mid, end, depth + 1, &right); });
      nodes->reserve(nodes->size() + left.size() + right.size());
      (*nodes)[id].left = append(left, nodes);
      (*nodes)[id].right = append(right, nodes);
    } else {
      const int left = build(begin, mid, depth + 1, nodes);
      const int right = build(mid, end, depth + 1, nodes);
      (*nodes)[id].left = left;
      (*nodes)[id].right = right;
    }
    return id;
  }

  // Appends a subtree numbered from 0 and returns the index of its root.
  static int append(const std::vector<Node>& sub, std::vector<Node>* nodes) {
    const int offset = static_cast<int>(nodes->size());
    for (Node nd : sub) {
      if (nd.left >= 0) {
        nd.left += offset;
        nd.right += offset;
      }
      nodes->push_back(nd);
    }
    return offset;
  }
};

NearestTriangleTree::NearestTriangleTree(const TriSurface& surface) : surface_(surface) {
  const int n = static_cast<int>(surface.triangles.size());
  order_.resize(n);
  centroid_.resize(n);
  // The triangles' boxes, once: the build reads each at every level of the tree.
  std::vector<std::array<Vec3, 2>> boxes(n);
  tbb::parallel_for(0, n, [&](int t) {
    order_[t] = t;
    const Triangle& tri = surface.triangles[t];
    centroid_[t] = (surface.points[tri[0]] + surface.points[tri[1]] + surface.points[tri[2]]) / 3.0;
    triangle_box(t, &boxes[t][0], &boxes[t][1]);
  });
  nodes_.reserve(n > 0 ? 2 * (n / kLeafSize + 1) : 0);
  if (n > 0) Builder{*this, boxes}.build(0, n, 0, &nodes_);
}

bool NearestTriangleTree::well_formed() const {
  if (nodes_.empty()) return order_.empty();
  std::vector<char> seen(nodes_.size(), 0), held(order_.size(), 0);
  auto inside = [](const Node& in, const Node& out) {
    for (int k = 0; k < 3; ++k)
      if (in.lo[k] < out.lo[k] || in.hi[k] > out.hi[k]) return false;
    return true;
  };
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    if (id < 0 || id >= static_cast<int>(nodes_.size()) || seen[id]) return false;
    seen[id] = 1;
    const Node& node = nodes_[id];
    if (node.left < 0) {
      for (int i = node.begin; i < node.end; ++i) {
        if (held[order_[i]]) return false;
        held[order_[i]] = 1;
      }
      continue;
    }
    if (node.right < 0 || node.right >= static_cast<int>(nodes_.size()) || node.left >= static_cast<int>(nodes_.size()))
      return false;
    const Node& l = nodes_[node.left];
    const Node& r = nodes_[node.right];
    if (l.begin != node.begin || l.end != r.begin || r.end != node.end || !inside(l, node) || !inside(r, node))
      return false;
    stack.push_back(node.left);
    stack.push_back(node.right);
  }
  return std::all_of(seen.begin(), seen.end(), [](char x) { return x != 0; }) &&
         std::all_of(held.begin(), held.end(), [](char x) { return x != 0; });
}

NearestTriangleTree::Hit NearestTriangleTree::nearest(const Vec3& p) const {
  Hit hit;
  if (nodes_.empty()) {
    hit.distance = std::numeric_limits<double>::infinity();
    return hit;
  }
  double best2 = std::numeric_limits<double>::infinity();
  // Depth-first, nearer child first; a box no nearer than the best so far cannot hold a
  // nearer triangle, and ties (equal squared distance) keep the first triangle found.
  // The stack holds at most one entry per level plus one (depth bound: the header).
  std::pair<double, int> stack[kMaxStack];
  int top = 0;
  stack[top++] = {box_distance2(p, nodes_[0].lo, nodes_[0].hi), 0};
  while (top > 0) {
    const auto [d2, id] = stack[--top];
    if (d2 >= best2) continue;
    const Node& node = nodes_[id];
    if (node.left < 0) {
      for (int i = node.begin; i < node.end; ++i) {
        const Triangle& tri = surface_.triangles[order_[i]];
        const Vec3 q = closest_point_on_triangle(p, surface_.points[tri[0]], surface_.points[tri[1]],
                                                 surface_.points[tri[2]]);
        const double e2 = norm2(q - p);
        if (e2 < best2) {
          best2 = e2;
          hit.triangle = order_[i];
          hit.point = q;
        }
      }
      continue;
    }
    const double dl = box_distance2(p, nodes_[node.left].lo, nodes_[node.left].hi);
    const double dr = box_distance2(p, nodes_[node.right].lo, nodes_[node.right].hi);
    // Pushed farther first, so the nearer child is popped next.
    if (dl <= dr) {
      stack[top++] = {dr, node.right};
      stack[top++] = {dl, node.left};
    } else {
      stack[top++] = {dl, node.left};
      stack[top++] = {dr, node.right};
    }
  }
  hit.distance = std::sqrt(best2);
  return hit;
}

}  // namespace detail
}  // namespace blayer
