// Where the visibility constraint V >= V_min is first met on the way from one direction
// to another. Under a binding constraint the constrained optimum lies on that boundary;
// a point of it with its exact D is a floor for the search (most_normal.cpp).
// Internal to blayer_normals.
#pragma once

#include "blayer/core/vec3.h"

namespace blayer {
namespace detail {

// Along the shorter great-circle arc from `from` to `to` (unit vectors), the first
// direction where V(n) = min_i n.f_i over the unit face normals f_0..f_{k-1} falls to
// v_min, given V(from) > v_min. On the arc n(t) = cos t from + sin t b (b the unit
// tangent towards `to`), each face gives f_i.n(t) = R_i cos(t - phi_i), which first
// falls to v_min at t_i = phi_i + arccos(v_min / R_i); the answer is n(min_i t_i). Its V
// is v_min up to the rounding of those closed forms (a few 1e-16). Returns false, *out
// untouched, where `from` and `to` are too nearly equal or opposite to span an arc
// (|from x to| <= kShortestArcSine = 1e-12), where V(from) <= v_min, or where V stays above v_min up to `to`.
bool first_direction_at_visibility(const Vec3* face_normals, int k, const Vec3& from, const Vec3& to, double v_min,
                                   Vec3* out);

}  // namespace detail
}  // namespace blayer
