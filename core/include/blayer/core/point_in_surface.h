// Is a point inside a closed triangle surface? Ray parity: a ray from the point crosses
// a closed surface an odd number of times exactly when the point is inside.
//
// A crossing that lies within kRayParityMargin of a triangle's edge or vertex (in
// barycentric coordinates), a ray that lies in a triangle's plane, or a point on a
// triangle (ray parameter below kRayParityMargin x length_scale) could be counted
// twice or not at all under rounding; the ray is then cast again in the next of five
// fixed directions with no simple relation to the coordinate axes (so grid-aligned
// input rarely puts two rays through edges). When all five are unreliable, or the
// point lies on the surface, the answer is kUndecided.
//
// Input: s closed (every edge used by two triangles), orientation irrelevant;
// length_scale a size of s (its bounding-box diagonal), scaling the on-surface margin.
// Cost O(#F) per ray. Precondition (BLAYER_ASSERT): length_scale > 0.
// BLAYER_EXPENSIVE_ASSERT: s is closed.
#pragma once

#include "blayer/core/surface.h"

namespace blayer {

// 1e-9: a thousand times the rounding of the products in the barycentric coordinates
// of well-scaled input (1e-16 relative, amplified by the ratio of triangle size to ray
// length), and far below any feature a mesh resolves.
inline constexpr double kRayParityMargin = 1e-9;

enum class Containment { kOutside, kInside, kUndecided };

Containment point_in_closed_surface(const TriSurface& s, const Vec3& p, double length_scale);

// Crossings of the ray p + t * dir (t > 0) with the triangles of s, or -1 when one of
// them lies within the margins above. The building block of point_in_closed_surface,
// public for its tests.
int count_ray_crossings(const TriSurface& s, const Vec3& p, const Vec3& dir, double length_scale);

}  // namespace blayer
