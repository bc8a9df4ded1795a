// A triangle as three 64-bit point ids (of a mesh or a soup of points), the key under
// which a face is found whichever way round it was listed, and the test for a triangle
// that is only a segment.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

namespace blayer {

using IndexedTriangle = std::array<std::int64_t, 3>;

// The ids in increasing order.
using TriangleKey = IndexedTriangle;
inline TriangleKey sorted_triangle(std::int64_t a, std::int64_t b, std::int64_t c) {
  TriangleKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

// A triangle that names one id twice: a segment, not a face (a fan strip's half where
// the fan did not grow). For ids of any width: the front checker keeps 32-bit ones.
template <class Id>
bool names_a_point_twice(const std::array<Id, 3>& t) {
  return t[0] == t[1] || t[1] == t[2] || t[2] == t[0];
}
inline bool names_a_point_twice(const IndexedTriangle& t) { return names_a_point_twice<std::int64_t>(t); }

}  // namespace blayer
