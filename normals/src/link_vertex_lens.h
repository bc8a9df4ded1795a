// Where the link-vertex bound can still reach a threshold above 90 degrees. Every link
// vertex u_j lies on the link, so D(n) <= g(n) = min_j angle(n, u_j); for thr > pi/2
// the set L = {g >= thr} is the intersection of the caps of radius pi - thr < pi/2
// around the -u_j, hence convex, and every direction with D >= thr lies in it. For the
// cap antipode n0 (the maximiser of g) this bounds L by a cap around n0: on convex
// corners and smoothly convex skins, a tiny one. Internal to blayer_normals.
#pragma once

#include <vector>

#include "blayer/core/tolerances.h"
#include "blayer/core/vec3.h"

namespace blayer {
namespace detail {

// The cap holding the link vertices (most_visible_normal of the link directions, whose
// antipode is the centre here) needs only a positive margin to bound the region (its
// radius below 90 degrees), not the visibility margin of a prism: near-flat links lie
// within 1e-4 of a great circle. 1e-12 stays six orders above the rounding of its dot
// products.
constexpr double kLensCapMargin = 1e-12;

// The tolerances the solver computes that cap with: tol, with kLensCapMargin for the
// visibility margin.
inline Tolerances lens_cap_tolerances(const Tolerances& tol) {
  Tolerances cap = tol;
  cap.min_visibility = kLensCapMargin;
  return cap;
}

// The smallest radius r of the schedule 1e-7 * 4^m (m = 0, 1, ...), up to max_radius,
// for which the circle {angle(n, centre) = r} is proved disjoint from L, so that
// L lies in B(centre, r). Preconditions: thr > pi/2, unit dirs. Returns a negative value
// when no such r <= max_radius is found, or when the centre is not inside L with a
// margin of 1e-12 in the cosines: the argument needs a point of L, and a cap antipode
// computed for a nearly flat link can miss it (Wolfe's certificate bounds V* only to
// 1e-13 / V*: on the ONERA M6 571k, a cap of V 7.7e-9 where V* is 2.4e-7, and the
// lens around it left out the optimum, 1.8e-8 higher).
double link_vertex_lens_radius(const std::vector<Vec3>& dirs, const Vec3& centre, double thr, double max_radius);

}  // namespace detail
}  // namespace blayer
