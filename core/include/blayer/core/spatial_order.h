// An order of points along a space-filling curve: points near in space come near in
// the order. Arrays numbered in this order are read with few cache misses by anything
// that visits a region at a time (the extruder's bounding-volume trees visit the
// triangles of one region together and read their columns' points).
//
// The curve is the Morton (Z-order) curve of a cube on the points' bounding box: each
// coordinate from the box's low corner, over the box's largest extent, onto 2^21 cells
// (a 63-bit key). Cubic cells, not the box's own proportions: a thin shape (a wing's
// thickness) stretched to as many cells as its span would be cut into bands at every
// level of the curve, and its neighbours numbered far apart. Points in one cell and
// points with equal keys keep their input order, so the order is deterministic.
// Input: finite coordinates (all points equal, or none, is fine). Output: a
// permutation of 0..#points-1, position i holding the index of the i-th point along
// the curve. O(#points log #points).
#pragma once

#include <cstdint>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer {

// Cells per axis of the curve: 2^21, so that three axes interleave into 63 bits.
inline constexpr int kMortonBitsPerAxis = 21;

// The Morton key of cell (x, y, z), each below 2^kMortonBitsPerAxis: bit b of x, y, z
// goes to bit 3b, 3b + 1, 3b + 2 of the key.
std::uint64_t morton_key(std::uint32_t x, std::uint32_t y, std::uint32_t z);

std::vector<int> morton_order(const std::vector<Vec3>& points);

}  // namespace blayer
