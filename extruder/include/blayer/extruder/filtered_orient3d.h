// An inlined floating-point filter in front of the exact orient3d_sign, for the extruder's
// hot loops (the per-layer front intersection check and cell validity check make
// hundreds of orientation tests per triangle; the out-of-line exact predicate, with its
// point conversions, dominated their cost).
//
// The determinant is evaluated exactly as in Shewchuk's orient3d (differences against
// the fourth point, then the 3x3 expansion), and its sign is returned only when
// |det| > (7 + 56 eps) eps * permanent, eps = 2^-53: Shewchuk's proven bound on the
// rounding error of that evaluation ("Adaptive Precision Floating-Point Arithmetic and
// Fast Robust Geometric Predicates", 1997, errboundA of orient3d). The bound assumes
// neither underflow nor overflow, so a permanent outside [1e-200, 1e200] (or not
// finite) also goes to the exact predicate. Every answer therefore equals
// orient3d_sign's; the filter only decides the easy cases faster.
#pragma once

#include <cmath>

#include "blayer/core/vec3.h"
#include "blayer/quality/orient3d.h"

namespace blayer {
namespace detail {

// Same contract as orient3d_sign: the sign of det[b-a, c-a, d-a].
inline int orient3d_filtered(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Shewchuk's orient3d(pa, pb, pc, pd) = det[pa-pd, pb-pd, pc-pd] = -det[b-a, c-a, d-a].
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  constexpr double kEps = 1.1102230246251565e-16;  // 2^-53
  constexpr double kErrBound = (7.0 + 56.0 * kEps) * kEps;
  if (permanent >= 1e-200 && permanent <= 1e200) {
    const double err = kErrBound * permanent;
    if (det > err) return -1;
    if (-det > err) return 1;
  }
  return orient3d_sign(a, b, c, d);
}

}  // namespace detail
}  // namespace blayer
