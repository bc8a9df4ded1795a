// Classic weighted-average vertex normals (docs/normals.md, Part 2 table):
//   n = unit(sum_i w_i f_i) with w_i = 1 (unit), A_i (area), 1/A_i (inverse-area),
//   alpha_i (angle, Thuermer-Wuethrich 1998) or sin(alpha_i)/(|e_a||e_b|) (Max 1999).
// O(k). Nothing guarantees visibility: V(n) may be <= 0 on sharp fans.
// Degenerate triangles (FanGeometry::degenerate) get weight 0. Returns the zero vector
// when the weighted sum vanishes (e.g. no usable triangle); callers must check.
#pragma once

#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/point_normals.h"

namespace blayer {

// Precondition: method is one of kAngle, kArea, kUnit, kInverseArea, kMax
// (std::invalid_argument otherwise).
Vec3 weighted_average_normal(const FanGeometry& g, NormalMethod method);

}  // namespace blayer
