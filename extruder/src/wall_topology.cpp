#include "blayer/extruder/wall_topology.h"

namespace blayer {

WallTopology build_wall_topology(const TriSurface& wall) {
  WallTopology t;
  t.fans = build_vertex_fans(wall);
  t.vertex_triangles = vertex_triangles(wall);
  t.vertex_neighbours = vertex_neighbours(wall, t.vertex_triangles);
  const int nv = static_cast<int>(wall.points.size());
  t.used.assign(nv, 0);
  for (int v = 0; v < nv; ++v) t.used[v] = t.vertex_triangles.count(v) > 0;
  return t;
}

}  // namespace blayer
