#include "blayer/core/surface.h"

#include <algorithm>
#include <limits>

namespace blayer {

double bounding_box_diagonal(const std::vector<Vec3>& points) {
  if (points.empty()) return 0.0;
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi = -lo;
  for (const Vec3& p : points) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  return norm(hi - lo);
}

double signed_volume(const TriSurface& s) {
  // Tetrahedra against the centroid rather than the origin: far-from-origin input
  // would otherwise lose digits in the cancellation.
  Vec3 c{0, 0, 0};
  for (const Vec3& p : s.points) c += p;
  if (!s.points.empty()) c = c / static_cast<double>(s.points.size());
  double v = 0.0;
  for (const Triangle& t : s.triangles) {
    const Vec3 a = s.points[t[0]] - c, b = s.points[t[1]] - c, d = s.points[t[2]] - c;
    v += dot(a, cross(b, d));
  }
  return v / 6.0;
}

double mean_edge_length(const TriSurface& s) {
  if (s.triangles.empty()) return 0.0;
  double sum = 0.0;
  for (const Triangle& t : s.triangles)
    for (int k = 0; k < 3; ++k) sum += norm(s.points[t[(k + 1) % 3]] - s.points[t[k]]);
  return sum / (3.0 * static_cast<double>(s.triangles.size()));
}

}  // namespace blayer
