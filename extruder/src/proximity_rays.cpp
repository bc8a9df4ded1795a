#include "blayer/extruder/proximity_rays.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace blayer {

void unit_triangle_normals(const std::vector<Triangle>& tris, const std::vector<Vec3>& points,
                           std::vector<Vec3>* out) {
  out->resize(tris.size());
  tbb::parallel_for(0, static_cast<int>(tris.size()), [&](int i) {
    const Triangle& t = tris[i];
    (*out)[i] = normalized(cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]));
  });
}

WallTree::WallTree(const TriSurface& wall) {
  tree.build_triangles(static_cast<int>(wall.triangles.size()), [&](int f, Vec3* c) {
    for (int i = 0; i < 3; ++i) c[i] = wall.points[wall.triangles[f][i]];
  });
  unit_triangle_normals(wall.triangles, wall.points, &normal);
}

ProximityRays wall_proximity_rays(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
                                  const WallTree& tree, const std::vector<Triangle>* front_triangles, const std::vector<int>* wall_point,
                                  const std::optional<SymmetryPlane>& plane, const std::vector<char>* on_plane) {
  ProximityRays r;
  r.triangles = &triangles;
  r.front_triangles = front_triangles;
  r.wall_point = wall_point;
  r.wall_points = &points;
  r.wall_tree = &tree.tree;
  r.wall_normal = &tree.normal;
  if (plane) {
    r.plane = &*plane;
    r.on_plane = on_plane;
  }
  return r;
}

double ProximityRays::first_hit(int v, const Vec3& o, const Vec3& dir, double t_max) const {
  double best = HUGE_VAL;
  const int w = wall_point ? (*wall_point)[v] : v;
  auto point_of = [&](int c) { return wall_point ? (*wall_point)[c] : c; };
  auto search = [&](const TriangleBvh& tree, const std::vector<Triangle>& tris, const std::vector<Vec3>& P,
                    const std::vector<Vec3>& normal, bool on_columns) {
    tree.for_each_on_segment(o, dir, std::min(t_max, best), [&](int i, double* tm) {
      const Triangle& t = tris[i];
      if (on_columns ? (point_of(t[0]) == w || point_of(t[1]) == w || point_of(t[2]) == w)
                     : (t[0] == w || t[1] == w || t[2] == w))
        return;
      if (!(dot(dir, normal[i]) < 0.0)) return;
      const double d = ray_triangle_distance(o, dir, P[t[0]], P[t[1]], P[t[2]], *tm);
      if (d < best) {
        best = d;
        *tm = d;
      }
    });
  };
  search(*wall_tree, *triangles, *wall_points, *wall_normal, false);
  if (front_points)
    search(*front_tree, front_triangles ? *front_triangles : *triangles, *front_points, *front_normal, true);
  if (plane && !(*on_plane)[v]) {
    // Seen from the model's side the plane faces the ray when dir points towards it.
    const double towards = -dot(dir, plane->normal);
    if (towards > 0.0) {
      const double t = plane->signed_distance(o) / towards;
      if (t >= 0.0 && t <= t_max) best = std::min(best, t);
    }
  }
  return best;
}

}  // namespace blayer
