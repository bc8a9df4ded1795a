// The binned surface-area split of bounding-volume trees, shared by the extruder's
// collision tree and the quality module's nearest-triangle tree.
//
// Why the surface-area heuristic rather than the median: on surfaces that mix long, thin
// triangles with small ones (the pyHyp wings' trailing edges and tips), a median split
// puts long boxes into many nodes, whose boxes then overlap widely; the heuristic keeps
// them together. Callers cap the depth at which they use it (it may peel off a few
// items per level on boxes graded over hundreds of orders of magnitude) and split at the
// median below.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "blayer/core/vec3.h"

namespace blayer {

// Centroid bins per axis (16 is the usual choice: more bins refine the split little,
// fewer coarsen it on graded meshes).
constexpr int kSurfaceAreaBins = 16;

// Whether a tree builder builds the two halves of a split as parallel tasks: only when
// the node holds more than kParallelBuildItems items and both halves carry real work (a
// surface-area split may peel off a handful of items); below that the task overhead
// outweighs the work. Shared by both trees' builders.
constexpr int kParallelBuildItems = 1 << 12;
inline bool build_halves_in_parallel(int n_left, int n_right) {
  return n_left + n_right > kParallelBuildItems && std::min(n_left, n_right) > kParallelBuildItems / 4;
}

// Reorders items[0, count) so that the left child takes the first l of them and returns
// l, 0 < l < count: the split between two centroid bins, on any of the three axes, of
// least area(left) * n_left + area(right) * n_right, where area is half a box's surface.
// Returns -1 when no axis has two distinct centroids or no split has a finite cost.
// bounds(item, &lo, &hi) gives an item's box, centre(item) its centroid; clo and chi
// bound the centroids. One pass over the items bins them on all three axes at once. A
// non-finite centroid goes to the first bin, without an undefined conversion. The
// result is a pure function of the input.
template <class Bounds, class Centre>
int surface_area_split(int* items, int count, const Vec3& clo, const Vec3& chi, Bounds&& bounds, Centre&& centre) {
  constexpr int kBins = kSurfaceAreaBins;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double scale[3];
  for (int axis = 0; axis < 3; ++axis) {
    const double ext = chi[axis] - clo[axis];
    scale[axis] = ext > 0.0 ? kBins / ext : 0.0;
  }
  auto bin_of = [&](int item, int axis) {
    const double t = (centre(item)[axis] - clo[axis]) * scale[axis];
    if (t >= kBins - 1) return kBins - 1;
    return t > 0.0 ? static_cast<int>(t) : 0;
  };
  struct Bin {
    Vec3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
    int n = 0;
  };
  auto unite = [](Bin* into, const Vec3& lo, const Vec3& hi, int n) {
    for (int k = 0; k < 3; ++k) {
      into->lo[k] = std::min(into->lo[k], lo[k]);
      into->hi[k] = std::max(into->hi[k], hi[k]);
    }
    into->n += n;
  };
  auto area = [](const Bin& b) {
    const double x = b.hi[0] - b.lo[0], y = b.hi[1] - b.lo[1], z = b.hi[2] - b.lo[2];
    return x * y + y * z + z * x;
  };
  Bin bins[3][kBins];
  for (int i = 0; i < count; ++i) {
    Vec3 lo, hi;
    bounds(items[i], &lo, &hi);
    for (int axis = 0; axis < 3; ++axis) unite(&bins[axis][bin_of(items[i], axis)], lo, hi, 1);
  }
  double best_cost = kInf;
  int best_axis = -1, best_bin = 0;
  for (int axis = 0; axis < 3; ++axis) {
    if (!(scale[axis] > 0.0)) continue;
    // right[i]: the bins after i together.
    Bin right[kBins], acc;
    for (int bin = kBins - 1; bin > 0; --bin) {
      unite(&acc, bins[axis][bin].lo, bins[axis][bin].hi, bins[axis][bin].n);
      right[bin - 1] = acc;
    }
    acc = Bin{};
    for (int bin = 0; bin < kBins - 1; ++bin) {
      unite(&acc, bins[axis][bin].lo, bins[axis][bin].hi, bins[axis][bin].n);
      if (acc.n == 0 || right[bin].n == 0) continue;
      const double cost = area(acc) * acc.n + area(right[bin]) * right[bin].n;
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        best_bin = bin;
      }
    }
  }
  if (best_axis < 0) return -1;
  int* mid = std::partition(items, items + count, [&](int item) { return bin_of(item, best_axis) <= best_bin; });
  return static_cast<int>(mid - items);
}

}  // namespace blayer
