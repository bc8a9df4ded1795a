// An inlined floating-point filter in front of the exact orient3d_sign, for the hot
// loops: cell_validity (12 to 24 orientations per cell, run on every cell of every layer
// and of the final check) and the extruder's per-layer front intersection test. The
// out-of-line exact predicate, with its point conversions, dominated their cost.
//
// The determinant is evaluated exactly as in Shewchuk's orient3d (differences against
// the fourth point, then the 3x3 expansion). His proven bound on the rounding error of
// that evaluation is (7 + 56 eps) eps * permanent, eps = 2^-53, computed in floating
// point ("Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
// Predicates", 1997, errboundA of orient3d); it assumes neither underflow nor overflow.
// The sign is returned only when |det| > (7 + 68 eps) eps * permanent +
// kUnderflowSlack: the 12 eps^2 more pay for the one more rounding of that sum (1.5 eps
// relative), so the computed threshold exceeds Shewchuk's bound plus any underflow
// error below the slack, whether or not the slack is absorbed in the sum. Overflow
// yields an infinite or NaN permanent, which fails the range test [1e-200, 1e200].
// Underflow is not excluded by that test: a product of two small differences may be
// subnormal while the permanent is not. Such a product carries an absolute error of at
// most 2^-1075 instead of a relative one, and the evaluation multiplies it by one more
// difference only (the z differences here, the point's in orient3d_sides), so those are
// required to be at most kMaxDifference = 1e100: then the at most nine underflowing
// products add less than 1e-222 in all, which kUnderflowSlack = 1e-220 covers.
// Everything else goes to the exact predicate, so every answer equals orient3d_sign's;
// the filter only decides the easy cases faster.
//
// orient3d_sides evaluates one plane against several points: the determinant
// det[b - a, c - a, p - a] expanded along the row of p is Shewchuk's expansion of the
// transposed matrix, whose entries are the same rounded differences, so the same bound
// holds; the 2x2 minors of b - a and c - a are computed once for all points.
#pragma once

#include <algorithm>
#include <cmath>

#include "blayer/core/vec3.h"
#include "blayer/quality/orient3d.h"

namespace blayer {
namespace detail {

constexpr double kMaxDifference = 1e100;
constexpr double kUnderflowSlack = 1e-220;
constexpr double kOrient3dErrBound = (7.0 + 68.0 * 1.1102230246251565e-16) * 1.1102230246251565e-16;

// The sign of a determinant evaluated as above, given its permanent and the largest
// difference that multiplies a minor; 0 when the filter cannot decide.
inline int certain_sign(double det, double permanent, double largest_factor) {
  if (!(permanent >= 1e-200 && permanent <= 1e200 && largest_factor <= kMaxDifference)) return 0;
  const double err = kOrient3dErrBound * permanent + kUnderflowSlack;
  return det > err ? 1 : -det > err ? -1 : 0;
}

// The sign of det[b-a, c-a, d-a] where the filter certifies it, else 0 ("cannot
// decide", never "flat"): for callers that can settle an undecided case by another
// argument before paying for the exact predicate.
inline int orient3d_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Shewchuk's orient3d(pa, pb, pc, pd) = det[pa-pd, pb-pd, pc-pd] = -det[b-a, c-a, d-a].
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double az = std::fabs(adz), bz = std::fabs(bdz), cz = std::fabs(cdz);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * az + (std::fabs(cdxady) + std::fabs(adxcdy)) * bz +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * cz;
  return -certain_sign(det, permanent, std::max(az, std::max(bz, cz)));
}

// Same contract as orient3d_sign: the sign of det[b-a, c-a, d-a].
inline int orient3d_filtered(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const int sign = orient3d_filter(a, b, c, d);
  return sign != 0 ? sign : orient3d_sign(a, b, c, d);
}

// The plane through a, b, c with its minors computed once, for the signs of
// det[b - a, c - a, q - a] at many points q (orient3d_filter and orient3d_sign's sign).
class PlaneSides {
 public:
  PlaneSides(const Vec3& a, const Vec3& b, const Vec3& c) : a_(a) {
    const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
    const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
    const double bycz = by * cz, bzcy = bz * cy, bzcx = bz * cx, bxcz = bx * cz, bxcy = bx * cy, bycx = by * cx;
    m_ = {bycz - bzcy, bzcx - bxcz, bxcy - bycx};
    perm_ = {std::fabs(bycz) + std::fabs(bzcy), std::fabs(bzcx) + std::fabs(bxcz), std::fabs(bxcy) + std::fabs(bycx)};
  }
  // The sign where the filter certifies it, else 0.
  int filter(const Vec3& q) const {
    const double qx = q[0] - a_[0], qy = q[1] - a_[1], qz = q[2] - a_[2];
    const double ax = std::fabs(qx), ay = std::fabs(qy), az = std::fabs(qz);
    return certain_sign(qx * m_[0] + qy * m_[1] + qz * m_[2], ax * perm_[0] + ay * perm_[1] + az * perm_[2],
                        std::max(ax, std::max(ay, az)));
  }

 private:
  Vec3 a_, m_, perm_;
};

// out[i] = orient3d_filter(a, b, c, *p[i]) for i < n (0: the filter cannot decide),
// with the plane's minors shared; true when every sign was decided. The points are
// passed by address: the hot callers name them in a shared point array.
inline bool orient3d_sides_filter(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3* const* p, int n,
                                  int* out) {
  const PlaneSides plane(a, b, c);
  bool all = true;
  for (int i = 0; i < n; ++i) {
    out[i] = plane.filter(*p[i]);
    all = all && out[i] != 0;
  }
  return all;
}

// The exact sign for every out[i] that orient3d_sides_filter left undecided.
inline void orient3d_sides_settle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3* const* p, int n,
                                  int* out) {
  for (int i = 0; i < n; ++i)
    if (out[i] == 0) out[i] = orient3d_sign(a, b, c, *p[i]);
}

// out[i] = orient3d_filtered(a, b, c, *p[i]) for i < n, with the plane's minors shared.
inline void orient3d_sides(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3* const* p, int n, int* out) {
  if (!orient3d_sides_filter(a, b, c, p, n, out)) orient3d_sides_settle(a, b, c, p, n, out);
}

}  // namespace detail
}  // namespace blayer
