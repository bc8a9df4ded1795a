#include "link_vertex_lens.h"

#include <cmath>

#include "sphere_solvers.h"

namespace blayer {
namespace detail {

namespace {

// A circle point counts as outside L when some n.u_j exceeds cos(thr) by this: the dot
// products carry ~1e-16 rounding, so such a point has angle(n, u_j) < thr for certain.
constexpr double kOutsideMargin = 1e-12;

// A computed boundary point of one vertex's arc counts as covered by another vertex
// only with this much to spare: it lies within ~1e-15 of the exact boundary point, whose
// coverage the test must not overstate (the argument of circle_screened_off in
// most_normal_enumeration.cpp).
constexpr double kBoundaryRounding = 1e-14;

// Whether the circle {n.centre = cos r} lies outside L: the open arcs
// G_j = {n on the circle : n.u_j > lambda} cover it. If they do not, a component of the
// uncovered part has an end on the boundary of some G_j that no other G_i covers, and
// that end is found below; if every such end is covered, the circle is.
bool circle_outside_lens(const std::vector<Vec3>& dirs, const Vec3& centre, const Vec3& e1, const Vec3& e2,
                         double r, double lambda) {
  const double cr = std::cos(r), sr = std::sin(r);
  bool any_arc = false;
  for (const Vec3& u : dirs) {
    // Only vertices within thr + r of the centre reach the circle.
    const double alpha = dot(centre, u), a = dot(e1, u), b = dot(e2, u);
    const double rr = a * a + b * b;
    // On the circle, n.u = cr alpha + sr (a cos t + b sin t) > lambda.
    const double mu = sr > 0.0 ? (lambda - cr * alpha) / sr : 0.0;
    if (!(rr > 0.0) || mu * mu >= rr) {
      if (mu < 0.0 && rr >= 0.0 && cr * alpha - sr * std::sqrt(rr) > lambda + kBoundaryRounding) return true;
      continue;
    }
    any_arc = true;
    const double q = std::sqrt(rr - mu * mu);
    for (double sign : {1.0, -1.0}) {
      const double x = (mu * a - sign * q * b) / rr, y = (mu * b + sign * q * a) / rr;
      const Vec3 n = cr * centre + sr * (x * e1 + y * e2);
      bool covered = false;
      for (const Vec3& w : dirs)
        if (dot(n, w) > lambda + kBoundaryRounding) {
          covered = true;
          break;
        }
      if (!covered) return false;
    }
  }
  return any_arc;
}

}  // namespace

double link_vertex_lens_radius(const std::vector<Vec3>& dirs, const Vec3& centre, double thr, double max_radius) {
  // The circle test bounds L only around a point of L: checked, not assumed, since the
  // centre is a computed cap antipode (see the header).
  const double cos_thr = std::cos(thr);
  const double inside = cos_thr - kOutsideMargin;
  for (const Vec3& u : dirs)
    if (!(dot(centre, u) <= inside)) return -1.0;
  Vec3 e1, e2;
  orthonormal_complement(centre, &e1, &e2);
  const double lambda = cos_thr + kOutsideMargin;
  thread_local std::vector<Vec3> near;
  for (double r = 1e-7; r <= max_radius; r *= 4.0) {
    // Vertices farther than thr + r from the centre cannot cover a point of the circle.
    const double reach = std::cos(std::min(M_PI, thr + r)) - 1e-15;
    near.clear();
    for (const Vec3& u : dirs)
      if (dot(centre, u) >= reach) near.push_back(u);
    if (circle_outside_lens(near, centre, e1, e2, r, lambda)) return r;
  }
  return -1.0;
}

}  // namespace detail
}  // namespace blayer
