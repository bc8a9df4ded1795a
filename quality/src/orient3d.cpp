// The only translation unit that includes CGAL: its filtered predicates give the exact
// sign with a floating-point fast path (static and interval filters) and an exact
// multiprecision fallback when the filters cannot decide.
#include "blayer/quality/orient3d.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace blayer {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
}  // namespace

int orient3d_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // CGAL::orientation(p, q, r, s) is the sign of det[q-p, r-p, s-p], the same
  // determinant as the header's contract (pinned by a unit test).
  static const Kernel::Orientation_3 orientation = Kernel().orientation_3_object();
  const CGAL::Orientation o = orientation(Point(a[0], a[1], a[2]), Point(b[0], b[1], b[2]),
                                          Point(c[0], c[1], c[2]), Point(d[0], d[1], d[2]));
  return o == CGAL::POSITIVE ? 1 : (o == CGAL::NEGATIVE ? -1 : 0);
}

}  // namespace blayer
