#include "blayer/core/edge_topology.h"

#include <algorithm>

#include "blayer/core/assert.h"

namespace blayer {

namespace {

struct EdgeUse {
  int hi;
  int triangle;
  bool forward;
};

// Stable sort of one point's uses by their upper point: an insertion sort, since a
// point has a few edges (std::stable_sort took a buffer from the heap for each point);
// the library's for the rare point with many.
void sort_by_hi(EdgeUse* first, EdgeUse* last) {
  if (last - first > 32) {
    std::stable_sort(first, last, [](const EdgeUse& x, const EdgeUse& y) { return x.hi < y.hi; });
    return;
  }
  for (EdgeUse* i = first + 1; i < last; ++i) {
    const EdgeUse x = *i;
    EdgeUse* j = i;
    for (; j > first && (j - 1)->hi > x.hi; --j) *j = *(j - 1);
    *j = x;
  }
}

EdgeKind classify(const SurfaceEdge& e, int n_forward) {
  if (e.n_uses == 1) return EdgeKind::kBoundary;
  if (e.n_uses > 2) return EdgeKind::kNonManifold;
  return n_forward == 1 ? EdgeKind::kManifold : EdgeKind::kInconsistent;
}

}  // namespace

EdgeTopology build_edge_topology(const TriSurface& s) {
  const int nv = static_cast<int>(s.points.size());
  // Uses bucketed by their lower point (counting sort), in triangle order.
  std::vector<int> start(nv + 1, 0);
  for (const Triangle& t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      BLAYER_ASSERT_MSG(a >= 0 && a < nv, "triangle refers to a point outside the surface");
      if (a != b) ++start[std::min(a, b) + 1];
    }
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<EdgeUse> uses(start[nv]);
  std::vector<int> next(start.begin(), start.end() - 1);
  for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = s.triangles[f][k], b = s.triangles[f][(k + 1) % 3];
      if (a != b) uses[next[std::min(a, b)]++] = {std::max(a, b), f, a < b};
    }

  EdgeTopology out;
  // A closed surface has half as many edges as uses; an open one a few more.
  out.edges.reserve(uses.size() / 2 + 16);
  [[maybe_unused]] std::size_t n_uses = 0;
  for (int lo = 0; lo < nv; ++lo) {
    // Stable: uses of one edge stay in triangle order.
    sort_by_hi(uses.data() + start[lo], uses.data() + start[lo + 1]);
    for (int i = start[lo]; i < start[lo + 1];) {
      SurfaceEdge e;
      e.lo = lo;
      e.hi = uses[i].hi;
      int n_forward = 0;
      int j = i;
      for (; j < start[lo + 1] && uses[j].hi == e.hi; ++j) {
        if (e.n_uses < 2) {
          e.triangle[e.n_uses] = uses[j].triangle;
          e.forward[e.n_uses] = uses[j].forward;
        }
        ++e.n_uses;
        n_forward += uses[j].forward ? 1 : 0;
      }
      e.kind = classify(e, n_forward);
      n_uses += static_cast<std::size_t>(e.n_uses);
      out.n_boundary += e.kind == EdgeKind::kBoundary;
      out.n_non_manifold += e.kind == EdgeKind::kNonManifold;
      out.n_inconsistent += e.kind == EdgeKind::kInconsistent;
      out.edges.push_back(e);
      i = j;
    }
  }
  BLAYER_EXPENSIVE_ASSERT(n_uses == uses.size());  // every use lands in exactly one edge
  return out;
}

}  // namespace blayer
