#include "blayer/io/surface_intersections.h"

#include <cmath>

#include "blayer/extruder/triangle_intersections.h"

namespace blayer {

namespace {

// The point where segment pq crosses the plane of triangle abc, when it does so inside
// the triangle (floating point, with a small tolerance: this only places a message).
bool segment_crossing(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, Vec3* out) {
  const Vec3 n = cross(b - a, c - a);
  const double dp = dot(p - a, n), dq = dot(q - a, n);
  if (dp * dq > 0.0 || dp == dq) return false;
  const Vec3 x = p + (dp / (dp - dq)) * (q - p);
  const double area = dot(n, n);
  const double u = dot(cross(b - x, c - x), n) / area, v = dot(cross(c - x, a - x), n) / area;
  constexpr double kSlack = 1e-9;
  if (u < -kSlack || v < -kSlack || u + v > 1.0 + kSlack) return false;
  *out = x;
  return true;
}

bool is_shared_corner(const Vec3& x, const Triangle& A, const Triangle& B, const Vec3* P) {
  for (int i : A)
    for (int j : B) {
      if (i != j) continue;
      const Vec3 d = x - P[i];
      if (dot(d, d) <= 1e-24 * (dot(P[i], P[i]) + 1e-300)) return true;
    }
  return false;
}

// Where the two triangles meet, away from the corners they share (an edge crossing
// through a shared corner says nothing about where the surfaces pass through each
// other); the centroid of both when no edge crossing is found.
Vec3 meeting_point(const TriSurface& s, int ta, int tb) {
  const Triangle& A = s.triangles[ta];
  const Triangle& B = s.triangles[tb];
  const Vec3* P = s.points.data();
  Vec3 x;
  for (int k = 0; k < 3; ++k) {
    if (segment_crossing(P[A[k]], P[A[(k + 1) % 3]], P[B[0]], P[B[1]], P[B[2]], &x) && !is_shared_corner(x, A, B, P))
      return x;
    if (segment_crossing(P[B[k]], P[B[(k + 1) % 3]], P[A[0]], P[A[1]], P[A[2]], &x) && !is_shared_corner(x, A, B, P))
      return x;
  }
  Vec3 c{0.0, 0.0, 0.0};
  for (int k = 0; k < 3; ++k) c = c + P[A[k]] + P[B[k]];
  return (1.0 / 6.0) * c;
}

}  // namespace

std::vector<TrianglePairIntersection> find_surface_intersections(const TriSurface& s, std::size_t max_pairs) {
  std::vector<IndexedTriangle> tris(s.triangles.size());
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) tris[t][k] = s.triangles[t][k];
  const std::vector<std::pair<int, int>> pairs = find_triangle_intersections(s.points, tris, nullptr, max_pairs);
  std::vector<TrianglePairIntersection> out;
  out.reserve(pairs.size());
  for (const auto& [a, b] : pairs) out.push_back({a, b, meeting_point(s, a, b)});
  return out;
}

}  // namespace blayer
