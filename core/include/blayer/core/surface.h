// The wall surface as plain arrays: #V points by 3 and #F triangles by 3 (vertex indices).
// A triangle (a,b,c) has its right-hand normal (b-a)x(c-a) pointing into the fluid,
// i.e. towards the side the layers grow on.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer {

using Triangle = std::array<int, 3>;

struct TriSurface {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
};

// Unnormalised face normal (twice the area vector) of triangle t.
inline Vec3 triangle_area_vector(const TriSurface& s, const Triangle& t) {
  return cross(s.points[t[1]] - s.points[t[0]], s.points[t[2]] - s.points[t[0]]);
}

// Diagonal of the axis-aligned bounding box of the points (0 for an empty surface).
double bounding_box_diagonal(const std::vector<Vec3>& points);

// Signed enclosed volume (divergence theorem); positive when a closed surface's
// triangles face outward.
double signed_volume(const TriSurface& s);

// Mean edge length over all triangle edges (each edge counted once per triangle side).
double mean_edge_length(const TriSurface& s);

}  // namespace blayer
