#include "normal_hull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Convex_hull_traits_3.h>
#include <CGAL/convex_hull_3.h>

#include <array>
#include <cstddef>
#include <map>
#include <vector>

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
  // The hull as an indexed triangle set (its own vertex list, copies of input points),
  // with the convex hull traits' exact plane predicates.
  using Traits = CGAL::Convex_hull_traits_3<Kernel, CGAL::Default, CGAL::Tag_true>;
  using Points = std::vector<Point>;
  using Faces = std::vector<std::array<std::size_t, 3>>;
  thread_local Points hull_points;
  thread_local Faces hull_faces;
  hull_points.clear();
  hull_faces.clear();
  CGAL::convex_hull_3<Points::iterator, Point, Points, Faces, Traits>(points.begin(), points.end(), hull_points,
                                                                      hull_faces, Traits());
  for (const auto& face : hull_faces)
    facets->push_back({index.at(hull_points[face[0]]), index.at(hull_points[face[1]]), index.at(hull_points[face[2]])});
  return !facets->empty();
}

}  // namespace detail
}  // namespace blayer
