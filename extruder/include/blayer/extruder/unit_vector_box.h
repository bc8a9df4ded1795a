// A box around a set of unit vectors, in 8-bit fixed point: each bound a whole number of
// 127ths, rounded outwards. Per node of a tree (TriangleBvh::node_value_boxes), it lets a
// pair traversal rule out whole node pairs by the directions of their items: the
// proximity rays skip the triangles that face away from them (proximity_rays.h). Six
// bytes a node, a quarter of a float box: the trees it serves are live while a run's
// memory peaks.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "blayer/core/vec3.h"

namespace blayer {

struct UnitVectorBox {
  static constexpr int kScale = 127;
  std::int8_t lo[3] = {kScale, kScale, kScale};
  std::int8_t hi[3] = {-kScale, -kScale, -kScale};

  // The box that holds nothing (lo above hi): a union with it is the other box.
  static UnitVectorBox empty() { return UnitVectorBox{}; }

  // The box of one unit vector. A component is clamped to [-1, 1] first: a normalised
  // vector's may pass 1 by a rounding (about 1e-16), far below what the tests below
  // resolve. The bounds are taken 1e-9 outwards of the scaled component, so that the
  // rounding of u[i] * 127 cannot put a bound past it. A vector with a NaN component or
  // one beyond 1 + 1e-6 (not a unit vector) gets the whole cube, with which
  // dot_positive_throughout never holds.
  static UnitVectorBox of(const Vec3& u) {
    UnitVectorBox b;
    for (int i = 0; i < 3; ++i)
      if (!(std::fabs(u[i]) <= 1.0 + 1e-6)) return whole();
    for (int i = 0; i < 3; ++i) {
      const double x = std::clamp(u[i], -1.0, 1.0) * kScale;
      b.lo[i] = static_cast<std::int8_t>(std::max(-kScale, static_cast<int>(std::floor(x - 1e-9))));
      b.hi[i] = static_cast<std::int8_t>(std::min(kScale, static_cast<int>(std::ceil(x + 1e-9))));
    }
    return b;
  }

  // Every vector of the cube [-1, 1]^3.
  static UnitVectorBox whole() {
    UnitVectorBox b;
    for (int i = 0; i < 3; ++i) b.lo[i] = -kScale, b.hi[i] = kScale;
    return b;
  }

  void unite(const UnitVectorBox& o) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], o.lo[i]);
      hi[i] = std::max(hi[i], o.hi[i]);
    }
  }
};

// Whether every vector of box a has a positive dot product with every vector of box b:
// the least corner product of each axis, summed, in integers (exact). It is then at
// least 1 / 127^2 (6.2e-5) for the vectors the boxes hold, so a dot product of two
// such unit vectors rounded in doubles is positive too. False for an empty box and for
// the whole cube (each axis's least product is then at most zero).
inline bool dot_positive_throughout(const UnitVectorBox& a, const UnitVectorBox& b) {
  int least = 0;
  for (int i = 0; i < 3; ++i) {
    const int p = a.lo[i] * b.lo[i], q = a.lo[i] * b.hi[i], r = a.hi[i] * b.lo[i], s = a.hi[i] * b.hi[i];
    least += std::min(std::min(p, q), std::min(r, s));
  }
  return least > 0;
}

}  // namespace blayer
