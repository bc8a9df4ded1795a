// A triangle's extent along the six face diagonals of the axes (x + y, x - y, x + z,
// x - z, y + z, y - z), in float: with the axis-aligned box it makes an 18-sided
// bounding polytope. Two triangles whose extents are apart along any
// diagonal cannot meet (both are convex), so a pair whose boxes overlap but whose slabs
// do not is settled without the exact test.
//
// Why: the boxes of long, thin triangles lying across the axes (the planar faces of
// CAD parts, fronts a layer above them) are mostly empty. Of the envelope check's
// box-overlapping pairs that share no point, slabs apart settle 68 % on the perforated
// block, 86 % on the sliver wing, 40 % on the BWB and 34 % on the 717 wing (default
// run). A pair sharing a point always overlaps, so its cost is the 12 comparisons that
// find no gap. The trees hold them (TriangleBvh::refit_triangles) up to a size beyond
// which their memory traffic costs more than they save.
//
// Rounding: every bound is the double sum (or difference) of two exact coordinates,
// converted to float, both rounded to nearest. That is one non-decreasing function of
// the true diagonal coordinate, the same for every triangle, so it keeps the order of
// any two true bounds (ties included): where the true extents meet, the rounded ones
// meet too. Rounding can thus make a pair not apart, never apart wrongly. A triangle
// with a NaN or infinite coordinate gets NaN bounds, never apart from anything.
#pragma once

#include <algorithm>
#include <array>

#include "blayer/core/vec3.h"

namespace blayer {

struct DiagonalSlabs {
  std::array<float, 6> lo{}, hi{};

  static DiagonalSlabs of_triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    double dlo[6], dhi[6];
    diagonals(a, dlo);
    diagonals(a, dhi);
    // 0, or NaN when a coordinate is NaN or infinite (std::min and std::max would drop
    // a NaN that is not first): added to every bound, it makes them all NaN then.
    double poison = 0.0 * (dlo[0] + dlo[1] + dlo[2]);
    for (const Vec3* p : {&b, &c}) {
      double d[6];
      diagonals(*p, d);
      poison += 0.0 * (d[0] + d[1] + d[2]);
      for (int i = 0; i < 6; ++i) {
        dlo[i] = std::min(dlo[i], d[i]);
        dhi[i] = std::max(dhi[i], d[i]);
      }
    }
    DiagonalSlabs s;
    for (int i = 0; i < 6; ++i) {
      s.lo[i] = static_cast<float>(dlo[i] + poison);
      s.hi[i] = static_cast<float>(dhi[i] + poison);
    }
    return s;
  }

  // True when some diagonal separates the two triangles; false also when a bound is NaN.
  bool apart(const DiagonalSlabs& o) const {
    bool gap = false;
    for (int i = 0; i < 6; ++i) gap |= (lo[i] > o.hi[i]) | (o.lo[i] > hi[i]);
    return gap;
  }

 private:
  static void diagonals(const Vec3& p, double* d) {
    d[0] = p[0] + p[1];
    d[1] = p[0] - p[1];
    d[2] = p[0] + p[2];
    d[3] = p[0] - p[2];
    d[4] = p[1] + p[2];
    d[5] = p[1] - p[2];
  }
};

}  // namespace blayer
