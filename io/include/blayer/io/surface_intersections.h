// Where a wall surface passes through itself: every pair of its triangles that meet
// anywhere other than at the vertices and edges they share, decided exactly.
//
// The decision is the extruder's exact triangle-pair test (find_triangle_intersections
// in blayer/extruder/triangle_intersections.h: a bounding-volume tree over the
// triangles' boxes, then orient3d on the candidates): two triangles sharing an edge
// meet only in a coplanar fold, two sharing one vertex meet when either's opposite edge
// meets the other, and touching counts as meeting. A surface passing this check is
// embedded: it has no self-intersection, and its closed components neither cross nor
// touch each other, so each one separates space into an inside and an outside that no
// other component straddles (shell_nesting.h relies on it).
//
// `near` is for messages only: a point where the two triangles meet, computed in
// floating point (an edge of one crossing the other, else a corner of one inside the
// other), so it can be off by rounding; the pair itself is exact.
#pragma once

#include <cstddef>
#include <vector>

#include "blayer/core/surface.h"

namespace blayer {

struct TrianglePairIntersection {
  int a = 0, b = 0;  // triangle indices, a < b
  Vec3 near{0.0, 0.0, 0.0};
};

// Intersecting pairs in increasing (a, b) order, at most max_pairs of them.
std::vector<TrianglePairIntersection> find_surface_intersections(const TriSurface& s, std::size_t max_pairs);

}  // namespace blayer
