// Where a ray meets the plane of a triangle, in the triangle's barycentric coordinates
// (Moller and Trumbore, "Fast, minimum storage ray-triangle intersection", 1997).
//
// Floating point, no tolerance: callers that need a decision near an edge or a vertex
// either accept the rounding (a heuristic such as a proximity limiter) or add their
// own margin and retry (point_in_surface.h). Exact predicates decide mesh validity
// elsewhere (quality/orient3d.h). Header-only so that hot loops inline it.
#pragma once

#include <cmath>

#include "blayer/core/vec3.h"

namespace blayer {

// The ray o + t * dir against triangle (a, b, c). det == 0: the ray is parallel to the
// triangle's plane and u, v, t are not meaningful. Otherwise the ray meets the plane at
// o + t * dir = a + u (b - a) + v (c - a); the crossing lies inside the triangle when
// u >= 0, v >= 0 and u + v <= 1. det > 0 when dir points against the triangle's
// right-hand normal (b - a) x (c - a). dir need not be unit: t is in units of |dir|.
struct RayTriangleHit {
  double det = 0.0;
  double u = 0.0, v = 0.0, t = 0.0;
};

inline RayTriangleHit intersect_ray_triangle(const Vec3& o, const Vec3& dir, const Vec3& a, const Vec3& b,
                                             const Vec3& c) {
  RayTriangleHit h;
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 pv = cross(dir, e2);
  h.det = dot(e1, pv);
  if (h.det == 0.0) return h;
  const double inv = 1.0 / h.det;
  const Vec3 tv = o - a;
  const Vec3 qv = cross(tv, e1);
  h.u = dot(tv, pv) * inv;
  h.v = dot(dir, qv) * inv;
  h.t = dot(e2, qv) * inv;
  return h;
}

// Distance t in [0, t_max] along dir from o to the triangle, +inf (HUGE_VAL) when the
// ray misses it or is parallel to it. Edges and vertices count as hits.
inline double ray_triangle_distance(const Vec3& o, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c,
                                    double t_max) {
  const RayTriangleHit h = intersect_ray_triangle(o, dir, a, b, c);
  if (h.det == 0.0 || h.u < 0.0 || h.u > 1.0 || h.v < 0.0 || h.u + h.v > 1.0) return HUGE_VAL;
  return (h.t >= 0.0 && h.t <= t_max) ? h.t : HUGE_VAL;
}

}  // namespace blayer
