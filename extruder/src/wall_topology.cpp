#include "blayer/extruder/wall_topology.h"

#include <algorithm>
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
  t.wall_point.resize(nv);
  for (int v = 0; v < nv; ++v) t.wall_point[v] = v;
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

WallTopology build_column_topology(const ColumnLayout& layout, const std::optional<SymmetryPlane>& plane) {
  WallTopology t = build_wall_topology(layout.front, plane);
  t.wall_point = layout.wall_point;
  // Groups in column order: a fan point's columns are contiguous from its first sector
  // column on, except the sub-normal and centre columns added later.
  const int n_wall_points =
      layout.wall_point.empty() ? 0 : 1 + *std::max_element(layout.wall_point.begin(), layout.wall_point.end());
  std::vector<int> group_of_point(n_wall_points, -1);
  std::vector<std::vector<int>> groups;
  for (int c = 0; c < layout.n_columns(); ++c) {
    if (!layout.in_fan[c]) continue;
    int& group = group_of_point[layout.wall_point[c]];
    if (group < 0) {
      group = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[group].push_back(c);
  }
  for (const std::vector<int>& g : groups) {
    t.group_columns.items.insert(t.group_columns.items.end(), g.begin(), g.end());
    t.group_columns.start.push_back(static_cast<int>(t.group_columns.items.size()));
  }
  return t;
}

}  // namespace blayer
