#include "blayer/extruder/proximity_rays.h"

#include <algorithm>
#include <cmath>

namespace blayer {

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
