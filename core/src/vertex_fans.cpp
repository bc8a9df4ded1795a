#include "blayer/core/vertex_fans.h"

#include "blayer/core/vertex_adjacency.h"

namespace blayer {

namespace {

// Corner k of triangle t seen from its vertex: the two other vertices in winding order.
struct Wedge {
  int from;
  int to;
  int tri;
};

}  // namespace

void FanTable::append(const std::vector<int>& ring, const std::vector<int>& triangles, bool closed) {
  ring_.insert(ring_.end(), ring.begin(), ring.end());
  triangles_.insert(triangles_.end(), triangles.begin(), triangles.end());
  ring_start_.push_back(static_cast<int>(ring_.size()));
  triangle_start_.push_back(static_cast<int>(triangles_.size()));
  closed_.push_back(closed);
}

void FanTable::reserve(std::size_t points, std::size_t ids) {
  ring_start_.reserve(points + 1);
  triangle_start_.reserve(points + 1);
  closed_.reserve(points);
  ring_.reserve(ids + points);  // an open fan's ring has one id more than its triangles
  triangles_.reserve(ids);
}

VertexFans build_vertex_fans(const TriSurface& s) {
  const int nv = static_cast<int>(s.points.size());
  VertexFans out;

  // One wedge per corner, grouped by vertex as in the vertex->triangle table. A
  // triangle listed twice for v (it repeats v) gives its two corners in order.
  const CsrTable vtri = vertex_triangles(s);
  const std::vector<int>& start = vtri.start;
  out.fans.reserve(nv, vtri.items.size());
  std::vector<Wedge> wedges(vtri.items.size());
  for (int v = 0; v < nv; ++v) {
    int k = -1;
    for (int i = start[v]; i < start[v + 1]; ++i) {
      const int f = vtri.items[i];
      const Triangle& t = s.triangles[f];
      k = (i > start[v] && vtri.items[i - 1] == f) ? k + 1 : 0;
      while (t[k] != v) ++k;
      wedges[i] = {t[(k + 1) % 3], t[(k + 2) % 3], f};
    }
  }

  std::vector<char> used;
  std::vector<int> ring, triangles;
  const std::vector<int> none;
  for (int v = 0; v < nv; ++v) {
    const int b = start[v], e = start[v + 1], n = e - b;
    if (n == 0) {
      out.fans.append(none, none, false);
      continue;
    }
    // Valences are small (typically < 20): quadratic search beats hashing here.
    auto find_from = [&](int from) {
      int hit = -1;
      for (int i = b; i < e; ++i)
        if (wedges[i].from == from) {
          if (hit >= 0) return -2;  // two wedges leave the same ring vertex
          hit = i;
        }
      return hit;
    };
    // Start at a wedge whose `from` is nobody's `to` (boundary), else anywhere.
    int first = b;
    int n_starts = 0;
    for (int i = b; i < e; ++i) {
      bool is_to = false;
      for (int j = b; j < e; ++j) is_to |= (wedges[j].to == wedges[i].from);
      if (!is_to) {
        first = i;
        ++n_starts;
      }
    }
    bool ok = n_starts <= 1;
    bool closed = false;
    ring.clear();
    triangles.clear();
    int cur = first;
    used.assign(n, 0);
    for (int step = 0; ok && step < n; ++step) {
      if (cur < 0 || used[cur - b]) {
        ok = false;
        break;
      }
      used[cur - b] = 1;
      ring.push_back(wedges[cur].from);
      triangles.push_back(wedges[cur].tri);
      const int next_from = wedges[cur].to;
      if (step == n - 1) {
        closed = (n_starts == 0) && next_from == wedges[first].from;
        if (!closed) {
          if (n_starts == 0) ok = false;
          ring.push_back(next_from);
        }
        break;
      }
      cur = find_from(next_from);
      if (cur == -2) ok = false;
    }
    if (ok && static_cast<int>(triangles.size()) == n) {
      out.fans.append(ring, triangles, closed);
    } else {
      out.fans.append(none, none, false);
      out.non_manifold.push_back(v);
    }
  }
  return out;
}

}  // namespace blayer
