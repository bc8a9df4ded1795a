// Small closed-form and polynomial solvers on the unit sphere used by the most-normal
// candidate enumeration. Internal to blayer_normals.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "blayer/core/vec3.h"

namespace blayer {
namespace detail {

// Relative size below which a leading polynomial coefficient or a Gram determinant is
// zero: inputs are unit-vector products with ~1e-16 rounding, so 1e-14 relative has lost
// all but two digits.
constexpr double kNegligibleRelative = 1e-14;

// Two unit vectors spanning the plane orthogonal to unit h.
inline void orthonormal_complement(const Vec3& h, Vec3* e1, Vec3* e2) {
  const Vec3 a = std::fabs(h[0]) < 0.6 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  *e1 = normalized(cross(h, a));
  *e2 = cross(h, *e1);
}

// Points n with n.a = alpha, n.b = beta, |n| = 1 (0 or 2 of them; none when a || b).
template <class F>
void plane_plane_sphere(const Vec3& a, double alpha, const Vec3& b, double beta, F&& emit) {
  const double aa = dot(a, a), ab = dot(a, b), bb = dot(b, b);
  const double det = aa * bb - ab * ab;
  if (!(det > kNegligibleRelative * aa * bb)) return;
  const double x = (alpha * bb - beta * ab) / det;
  const double y = (beta * aa - alpha * ab) / det;
  const Vec3 p = x * a + y * b;
  const Vec3 c = cross(a, b);
  const double z2 = (1.0 - norm2(p)) / norm2(c);
  if (z2 < 0.0) return;
  const double z = std::sqrt(z2);
  emit(p + z * c);
  emit(p - z * c);
}

// Real roots of c[0] + c[1] x + ... + c[n] x^n, n <= 4, by splitting the line at the
// derivative's roots into monotone pieces and bisecting each sign change to full
// precision. Writes at most n roots to out and returns their count. Tangential (even
// multiplicity) roots are reported only when the polynomial vanishes at a derivative root.
inline int poly_real_roots(const double* coef, int n, double* out) {
  double c[5];
  double scale = 0.0;
  for (int i = 0; i <= n; ++i) {
    c[i] = coef[i];
    scale = std::max(scale, std::fabs(c[i]));
  }
  if (scale == 0.0) return 0;
  while (n > 0 && std::fabs(c[n]) <= kNegligibleRelative * scale) --n;
  if (n == 0) return 0;
  if (n == 1) {
    out[0] = -c[0] / c[1];
    return 1;
  }
  if (n == 2) {
    const double disc = c[1] * c[1] - 4.0 * c[2] * c[0];
    if (disc < 0.0) return 0;
    const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
    int m = 0;
    if (q != 0.0) out[m++] = c[0] / q;
    out[m++] = q / c[2];
    return m;
  }
  double d[4];
  for (int i = 1; i <= n; ++i) d[i - 1] = i * c[i];
  double crit[4];
  int nc = poly_real_roots(d, n - 1, crit);
  for (int i = 1; i < nc; ++i)
    for (int j = i; j > 0 && crit[j] < crit[j - 1]; --j) std::swap(crit[j], crit[j - 1]);
  double bound = 0.0;
  for (int i = 0; i < n; ++i) bound = std::max(bound, std::fabs(c[i] / c[n]));
  bound += 1.0;
  auto p = [&](double x) {
    double s = c[n];
    for (int i = n - 1; i >= 0; --i) s = s * x + c[i];
    return s;
  };
  double knots[6];
  int nk = 0;
  knots[nk++] = -bound;
  for (int i = 0; i < nc; ++i)
    if (crit[i] > -bound && crit[i] < bound) knots[nk++] = crit[i];
  knots[nk++] = bound;
  int m = 0;
  for (int i = 0; i + 1 < nk && m < n; ++i) {
    double lo = knots[i], hi = knots[i + 1];
    double plo = p(lo), phi = p(hi);
    if (plo == 0.0) {
      out[m++] = lo;
      continue;
    }
    if ((plo < 0.0) == (phi < 0.0)) continue;
    for (int it = 0; it < 200 && lo < hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      const double pm = p(mid);
      if ((pm < 0.0) == (plo < 0.0)) {
        lo = mid;
        plo = pm;
      } else {
        hi = mid;
      }
    }
    out[m++] = 0.5 * (lo + hi);
  }
  return m;
}

// Quadratic form of the point-arc bisector cone, n^T (w w^T + f f^T - I) n, on x, y.
inline double cone_form(const Vec3& w, const Vec3& f, const Vec3& x, const Vec3& y) {
  return dot(w, x) * dot(w, y) + dot(f, x) * dot(f, y) - dot(x, y);
}

// An arc of the circle {n.h = c0, |n| = 1} (h unit), n(t) = c0 h + s (cos t e1 + sin t e2)
// with e1, e2 from orthonormal_complement(h) and s = sqrt(1 - c0^2): the t within
// half_width of centre. The default is the whole circle.
struct CircleWindow {
  double centre = 0.0;
  double half_width = 4.0;
  bool whole() const { return half_width >= M_PI; }
};

// Residual |F| of a point of circle_cone's quartic, F = n^T(ww^T + ff^T - I)n at the
// root's direction: the quartic's value there is (1 + x^2)^2 F (x = tan(t / 2)), left by
// bisection to adjacent doubles or by a closed-form root at its rounding, below 1e-12
// for coefficients of unit-vector products (|K| <= 6); 1e-9 covers it by three orders,
// and the rounding of the window test's own F and slopes.
constexpr double kConeRootResidual = 1e-9;

// Whether the quartic of circle_cone can have a root in the window, from its terms
// F(t) = K0 + K1 cos t + K2 sin t + K3 cos 2t + K4 sin 2t: on |t - centre| <= w,
// |F| >= |F(centre)| - |F'(centre)| w - M w^2 / 2, M bounding |F''|.
inline bool cone_terms_reach_window(const double k[5], const CircleWindow& window) {
  if (window.whole()) return true;
  if (window.half_width < 0.0) return false;
  const double ct = std::cos(window.centre), st = std::sin(window.centre);
  const double c2 = ct * ct - st * st, s2 = 2.0 * st * ct;
  const double value = k[0] + k[1] * ct + k[2] * st + k[3] * c2 + k[4] * s2;
  const double slope = -k[1] * st + k[2] * ct - 2.0 * k[3] * s2 + 2.0 * k[4] * c2;
  const double curvature = std::hypot(k[1], k[2]) + 4.0 * std::hypot(k[3], k[4]);
  const double w = window.half_width;
  return std::fabs(value) - std::fabs(slope) * w - 0.5 * curvature * w * w <= kConeRootResidual;
}

// Points of the circle {n.h = c0, |n| = 1} (h unit) on the cone n^T(ww^T + ff^T - I)n = 0.
// Where the circle is not a great one, only those in `window` are sought; the point at
// t = pi is offered in any case.
template <class F>
void circle_cone(const Vec3& h, double c0, const Vec3& w, const Vec3& f, F&& emit, const CircleWindow& window = {}) {
  Vec3 e1, e2;
  orthonormal_complement(h, &e1, &e2);
  const double s2 = 1.0 - c0 * c0;
  if (!(s2 > 0.0)) return;
  const double s = std::sqrt(s2);
  const double a = cone_form(w, f, e1, e1), b = cone_form(w, f, e1, e2), c = cone_form(w, f, e2, e2);
  if (c0 == 0.0) {
    // Great circle: (a+c)/2 + (a-c)/2 cos 2t + b sin 2t = 0.
    const double r = std::hypot(0.5 * (a - c), b);
    if (!(r > 0.0)) return;
    const double cv = -0.5 * (a + c) / r;
    if (std::fabs(cv) > 1.0) return;
    const double phi = std::atan2(b, 0.5 * (a - c));
    const double da = std::acos(cv);
    for (double two_t : {phi + da, phi - da}) {
      const double t = 0.5 * two_t;
      const Vec3 n = std::cos(t) * e1 + std::sin(t) * e2;
      emit(n);
      emit(-n);
    }
    return;
  }
  // K0 + K1 cos t + K2 sin t + K3 cos 2t + K4 sin 2t = 0, then x = tan(t/2).
  const double k0 = c0 * c0 * cone_form(w, f, h, h) + s2 * 0.5 * (a + c);
  const double k1 = 2.0 * c0 * s * cone_form(w, f, h, e1);
  const double k2 = 2.0 * c0 * s * cone_form(w, f, h, e2);
  const double k3 = s2 * 0.5 * (a - c);
  const double k4 = s2 * b;
  const double terms[5] = {k0, k1, k2, k3, k4};
  const double poly[5] = {k0 + k1 + k3, 2.0 * k2 + 4.0 * k4, 2.0 * k0 - 6.0 * k3, 2.0 * k2 - 4.0 * k4,
                          k0 - k1 + k3};
  double roots[4];
  const int nr = cone_terms_reach_window(terms, window) ? poly_real_roots(poly, 4, roots) : 0;
  for (int i = 0; i < nr; ++i) {
    const double t = 2.0 * std::atan(roots[i]);
    emit(c0 * h + s * (std::cos(t) * e1 + std::sin(t) * e2));
  }
  // t = pi is x = infinity, invisible to the polynomial.
  emit(c0 * h - s * e1);
}

}  // namespace detail
}  // namespace blayer
