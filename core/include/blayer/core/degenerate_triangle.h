// Is a triangle too flat to have a normal? The test the surface input and the
// tetrahedral fill both apply to their triangles.
#pragma once

#include <algorithm>

#include "blayer/core/surface.h"

namespace blayer {

// True when twice the area is not above relative_height times the square of the
// longest edge (Tolerances::degenerate_relative_height says why 1e-12), i.e. the
// height over the longest edge is at most relative_height times its length. Non-finite
// coordinates count as degenerate. Indices must be valid.
inline bool is_degenerate_triangle(const TriSurface& s, const Triangle& t, double relative_height) {
  double longest2 = 0.0;
  for (int k = 0; k < 3; ++k) longest2 = std::max(longest2, norm2(s.points[t[(k + 1) % 3]] - s.points[t[k]]));
  const double twice_area = norm(triangle_area_vector(s, t));
  return !(twice_area > relative_height * longest2);
}

}  // namespace blayer
