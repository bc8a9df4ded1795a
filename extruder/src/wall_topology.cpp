#include "blayer/extruder/wall_topology.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace blayer {

namespace {

Csr vertex_triangles(const TriSurface& s) {
  const int nv = static_cast<int>(s.points.size());
  Csr c;
  c.start.assign(nv + 1, 0);
  for (const Triangle& t : s.triangles)
    for (int v : t) ++c.start[v + 1];
  for (int v = 0; v < nv; ++v) c.start[v + 1] += c.start[v];
  c.items.resize(c.start[nv]);
  std::vector<int> fill(c.start.begin(), c.start.end() - 1);
  for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f)
    for (int v : s.triangles[f]) c.items[fill[v]++] = f;
  return c;
}

Csr vertex_neighbours(const TriSurface& s, const Csr& vtri) {
  const int nv = static_cast<int>(s.points.size());
  std::vector<std::vector<int>> nb(nv);
  tbb::parallel_for(0, nv, [&](int v) {
    for (const int* f = vtri.begin(v); f != vtri.end(v); ++f)
      for (int u : s.triangles[*f])
        if (u != v) nb[v].push_back(u);
    std::sort(nb[v].begin(), nb[v].end());
    nb[v].erase(std::unique(nb[v].begin(), nb[v].end()), nb[v].end());
  });
  Csr c;
  c.start.assign(nv + 1, 0);
  for (int v = 0; v < nv; ++v) c.start[v + 1] = c.start[v] + static_cast<int>(nb[v].size());
  c.items.reserve(c.start[nv]);
  for (int v = 0; v < nv; ++v) c.items.insert(c.items.end(), nb[v].begin(), nb[v].end());
  return c;
}

}  // namespace

WallTopology build_wall_topology(const TriSurface& wall) {
  WallTopology t;
  t.fans = build_vertex_fans(wall);
  t.vertex_triangles = vertex_triangles(wall);
  t.vertex_neighbours = vertex_neighbours(wall, t.vertex_triangles);
  const int nv = static_cast<int>(wall.points.size());
  t.used.assign(nv, 0);
  for (int v = 0; v < nv; ++v) t.used[v] = t.vertex_triangles.size(v) > 0;
  return t;
}

}  // namespace blayer
