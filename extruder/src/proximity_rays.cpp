#include "blayer/extruder/proximity_rays.h"

#include <algorithm>
#include <cmath>

namespace blayer {

double ray_triangle_distance(const Vec3& o, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c,
                             double t_max) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 pv = cross(dir, e2);
  const double det = dot(e1, pv);
  if (det == 0.0) return HUGE_VAL;
  const double inv = 1.0 / det;
  const Vec3 tv = o - a;
  const double u = dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0) return HUGE_VAL;
  const Vec3 qv = cross(tv, e1);
  const double w = dot(dir, qv) * inv;
  if (w < 0.0 || u + w > 1.0) return HUGE_VAL;
  const double t = dot(e2, qv) * inv;
  return (t >= 0.0 && t <= t_max) ? t : HUGE_VAL;
}

double ProximityRays::first_hit(int v, const Vec3& o, const Vec3& dir, double t_max) const {
  double best = HUGE_VAL;
  auto search = [&](const TriangleBvh& tree, const std::vector<Vec3>& P, const std::vector<Vec3>& normal) {
    tree.for_each_on_segment(o, dir, std::min(t_max, best), [&](int i, double* tm) {
      const Triangle& t = (*triangles)[i];
      if (t[0] == v || t[1] == v || t[2] == v) return;
      if (!(dot(dir, normal[i]) < 0.0)) return;
      const double d = ray_triangle_distance(o, dir, P[t[0]], P[t[1]], P[t[2]], *tm);
      if (d < best) {
        best = d;
        *tm = d;
      }
    });
  };
  search(*wall_tree, *wall_points, *wall_normal);
  if (front_points) search(*front_tree, *front_points, *front_normal);
  return best;
}

}  // namespace blayer
