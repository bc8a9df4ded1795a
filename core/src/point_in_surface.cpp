#include "blayer/core/point_in_surface.h"

#include <cmath>

#include "blayer/core/assert.h"
#include "blayer/core/edge_topology.h"
#include "blayer/core/ray_triangle.h"

namespace blayer {

int count_ray_crossings(const TriSurface& s, const Vec3& p, const Vec3& dir, double length_scale) {
  const double m = kRayParityMargin;
  int count = 0;
  for (const Triangle& t : s.triangles) {
    const Vec3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    const RayTriangleHit h = intersect_ray_triangle(p, dir, a, b, c);
    if (h.det == 0.0) {
      // Parallel to the triangle's plane: harmless unless the ray lies in it.
      const Vec3 n = cross(b - a, c - a);
      if (std::abs(dot(p - a, n)) <= m * norm(n) * length_scale) return -1;
      continue;
    }
    if (h.u < -m || h.v < -m || h.u + h.v > 1.0 + m) continue;  // clear miss
    if (h.t < -m * length_scale) continue;                      // behind the point
    if (h.u < m || h.v < m || h.u + h.v > 1.0 - m || h.t < m * length_scale) return -1;
    ++count;
  }
  return count;
}

Containment point_in_closed_surface(const TriSurface& s, const Vec3& p, double length_scale) {
  BLAYER_ASSERT_MSG(length_scale > 0.0, "the on-surface margin needs a positive length scale");
  BLAYER_EXPENSIVE_ASSERT(build_edge_topology(s).n_boundary == 0);
  static const Vec3 kDirections[] = {{0.5773, 0.6133, 0.5391},
                                     {-0.3187, 0.8419, 0.4357},
                                     {0.7071, -0.2113, -0.6747},
                                     {-0.6019, -0.5023, 0.6213},
                                     {0.1234, 0.4321, -0.8932}};
  for (const Vec3& d : kDirections) {
    const int n = count_ray_crossings(s, p, normalized(d), length_scale);
    if (n >= 0) return n % 2 == 1 ? Containment::kInside : Containment::kOutside;
  }
  return Containment::kUndecided;
}

}  // namespace blayer
