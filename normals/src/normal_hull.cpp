#include "normal_hull.h"

#include <array>
#include <utility>
#include <vector>

#include "blayer/quality/filtered_orient3d.h"

namespace blayer {
namespace detail {

namespace {

using Facet = std::array<int, 3>;

// Whether p lies strictly above the plane of facet t (on the side its winding faces).
bool above(const Vec3* f, const Facet& t, int p) { return orient3d_filtered(f[t[0]], f[t[1]], f[t[2]], f[p]) > 0; }

// A facet of the hull being built, with its plane's minors: every later point is tested
// against it (O(k h) tests), and the shared minors halve a test's filter.
struct HullFacet {
  Facet t;
  PlaneSides plane;
  HullFacet(const Vec3* f, const Facet& facet) : t(facet), plane(f[facet[0]], f[facet[1]], f[facet[2]]) {}
  // Whether p sees the facet: above(f, t, p), the shared filter first.
  bool seen_by(const Vec3* f, int p) const {
    const int sign = plane.filter(f[p]);
    return (sign != 0 ? sign : orient3d_sign(f[t[0]], f[t[1]], f[t[2]], f[p])) > 0;
  }
};

// The first four points that span a volume, or false. Exact: point 0, the first point b
// apart from it, the first c not on their line, the first d after c off their plane (a c
// on the line has every d on a plane with it; a c off the line with no d off its plane
// leaves every point on one plane).
bool initial_simplex(const Vec3* f, int k, int* s) {
  int b = 1;
  while (b < k && f[b] == f[0]) ++b;
  for (int c = b + 1; c < k; ++c)
    for (int d = c + 1; d < k; ++d)
      if (orient3d_filtered(f[0], f[b], f[c], f[d]) != 0) {
        s[0] = 0;
        s[1] = b;
        s[2] = c;
        s[3] = d;
        return true;
      }
  return false;
}

}  // namespace

// Beneath-beyond: points are added in index order; a point above some facets replaces
// them by the fan from it to their horizon. "Above" is the exact strict orientation, so
// a point on the hull's surface (a repeated normal, a point in a facet's plane, inside
// it) is not added, and a point in the plane of a facet but outside it sees the facets
// beyond the convex edges of that plane's polygon, never none. O(k h) orientation tests,
// nearly all settled by the floating-point filter.
bool normal_hull_facets(const Vec3* f, int k, std::vector<std::array<int, 3>>* facets) {
  facets->clear();
  if (k < 4) return false;
  for (int i = 0; i < k; ++i)
    if (!is_finite(f[i])) return false;  // the exact predicate assumes finite coordinates
  int s[4];
  if (!initial_simplex(f, k, s)) return false;
  thread_local std::vector<HullFacet> hull, kept;
  hull.clear();
  for (int t = 0; t < 4; ++t) {
    Facet face{s[t], s[(t + 1) % 4], s[(t + 2) % 4]};
    if (above(f, face, s[(t + 3) % 4])) std::swap(face[1], face[2]);
    hull.emplace_back(f, face);
  }
  thread_local std::vector<std::array<int, 2>> rim;  // edges of the facets the point sees
  for (int p = 0; p < k; ++p) {
    if (p == s[0] || p == s[1] || p == s[2] || p == s[3]) continue;
    kept.clear();
    rim.clear();
    for (const HullFacet& h : hull) {
      if (h.seen_by(f, p)) {
        const Facet& t = h.t;
        rim.push_back({t[0], t[1]});
        rim.push_back({t[1], t[2]});
        rim.push_back({t[2], t[0]});
      } else {
        kept.push_back(h);
      }
    }
    if (rim.empty()) continue;
    // The horizon: edges of seen facets whose twin belongs to a facet not seen.
    for (const auto& [u, v] : rim) {
      bool inner = false;
      for (const auto& [x, y] : rim) inner = inner || (x == v && y == u);
      if (!inner) kept.emplace_back(f, Facet{u, v, p});
    }
    hull.swap(kept);
  }
  for (const HullFacet& h : hull) facets->push_back(h.t);
  return true;
}

}  // namespace detail
}  // namespace blayer
