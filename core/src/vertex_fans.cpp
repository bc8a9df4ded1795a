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

VertexFans build_vertex_fans(const TriSurface& s) {
  const int nv = static_cast<int>(s.points.size());
  VertexFans out;
  out.fans.resize(nv);

  // One wedge per corner, grouped by vertex as in the vertex->triangle table. A
  // triangle listed twice for v (it repeats v) gives its two corners in order.
  const CsrTable vtri = vertex_triangles(s);
  const std::vector<int>& start = vtri.start;
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
  for (int v = 0; v < nv; ++v) {
    const int b = start[v], e = start[v + 1], n = e - b;
    if (n == 0) continue;
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
    // Sized once: growing the ring and triangle lists by push_back cost more than
    // building the fans themselves.
    VertexFan fan;
    fan.ring.reserve(n + 1);
    fan.triangles.reserve(n);
    int cur = first;
    used.assign(n, 0);
    for (int step = 0; ok && step < n; ++step) {
      if (cur < 0 || used[cur - b]) {
        ok = false;
        break;
      }
      used[cur - b] = 1;
      fan.ring.push_back(wedges[cur].from);
      fan.triangles.push_back(wedges[cur].tri);
      const int next_from = wedges[cur].to;
      if (step == n - 1) {
        fan.closed = (n_starts == 0) && next_from == wedges[first].from;
        if (!fan.closed) {
          if (n_starts == 0) ok = false;
          fan.ring.push_back(next_from);
        }
        break;
      }
      cur = find_from(next_from);
      if (cur == -2) ok = false;
    }
    if (ok && static_cast<int>(fan.triangles.size()) == n) {
      out.fans[v] = std::move(fan);
    } else {
      out.non_manifold.push_back(v);
    }
  }
  return out;
}

}  // namespace blayer
