// Exact orientation predicate: the sign of det[b-a, c-a, d-a], i.e. +1 when d lies on the
// side of plane (a,b,c) that its right-hand normal (b-a)x(c-a) points to, -1 on the other
// side, 0 when the four points are exactly coplanar. Exact for all finite doubles
// (filtered, with an exact fallback), so every validity decision is reproducible.
#pragma once

#include "blayer/core/vec3.h"

namespace blayer {

int orient3d_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

}  // namespace blayer
