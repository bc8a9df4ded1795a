#include "blayer/extruder/wall_topology.h"

#include <cmath>

namespace blayer {

WallTopology build_wall_topology(const TriSurface& wall, const std::optional<SymmetryPlane>& plane) {
  WallTopology t;
  t.fans = build_vertex_fans(wall);
  t.vertex_triangles = vertex_triangles(wall);
  t.vertex_neighbours = vertex_neighbours(wall, t.vertex_triangles);
  const int nv = static_cast<int>(wall.points.size());
  t.used.assign(nv, 0);
  for (int v = 0; v < nv; ++v) t.used[v] = t.vertex_triangles.count(v) > 0;
  t.on_plane.assign(nv, 0);
  t.plane = plane;
  if (plane) {
    const double tol = kOnSymmetryPlaneRelTol * bounding_box_diagonal(wall.points);
    for (int v = 0; v < nv; ++v) {
      const VertexFan& fan = t.fans.fans[v];
      t.on_plane[v] = !fan.triangles.empty() && !fan.closed && std::fabs(plane->signed_distance(wall.points[v])) <= tol;
    }
  }
  return t;
}

}  // namespace blayer
