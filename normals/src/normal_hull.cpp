#include "normal_hull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <map>

namespace blayer {
namespace detail {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

// Whether the points span a volume: some four of them are not coplanar (exact).
bool spans_volume(const std::vector<Point>& p) {
  const int k = static_cast<int>(p.size());
  int b = 1;
  while (b < k && p[b] == p[0]) ++b;
  if (b == k) return false;
  int c = b + 1;
  while (c < k && CGAL::collinear(p[0], p[b], p[c])) ++c;
  if (c >= k) return false;
  for (int d = c + 1; d < k; ++d)
    if (CGAL::orientation(p[0], p[b], p[c], p[d]) != CGAL::COPLANAR) return true;
  return false;
}

}  // namespace

bool normal_hull_facets(const Vec3* f, int k, std::vector<std::array<int, 3>>* facets) {
  facets->clear();
  if (k < 4) return false;
  for (int i = 0; i < k; ++i)
    if (!is_finite(f[i])) return false;  // CGAL's predicates assume finite coordinates
  std::vector<Point> points;
  points.reserve(k);
  std::map<Point, int> index;
  for (int i = 0; i < k; ++i) {
    points.emplace_back(f[i][0], f[i][1], f[i][2]);
    index.emplace(points.back(), i);
  }
  if (!spans_volume(points)) return false;
  CGAL::Surface_mesh<Point> hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  for (const auto face : hull.faces()) {
    std::array<int, 3> t{};
    int n = 0;
    for (const auto v : CGAL::vertices_around_face(hull.halfedge(face), hull)) {
      if (n < 3) t[n] = index.at(hull.point(v));
      ++n;
    }
    if (n != 3) {  // convex_hull_3 triangulates its facets: not expected
      facets->clear();
      return false;
    }
    facets->push_back(t);
  }
  return !facets->empty();
}

}  // namespace detail
}  // namespace blayer
