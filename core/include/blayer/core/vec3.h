// Small fixed-size vector algebra on plain std::array<double,3>.
// Kept header-only so that hot loops in every module inline it.
#pragma once

#include <array>
#include <cmath>
#include <cstring>

namespace blayer {

using Vec3 = std::array<double, 3>;

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator-(const Vec3& a) { return {-a[0], -a[1], -a[2]}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline Vec3 operator*(const Vec3& a, double s) { return s * a; }
inline Vec3 operator/(const Vec3& a, double s) { return {a[0] / s, a[1] / s, a[2] / s}; }
inline Vec3& operator+=(Vec3& a, const Vec3& b) {
  a[0] += b[0]; a[1] += b[1]; a[2] += b[2];
  return a;
}
inline Vec3& operator-=(Vec3& a, const Vec3& b) {
  a[0] -= b[0]; a[1] -= b[1]; a[2] -= b[2];
  return a;
}
inline Vec3& operator*=(Vec3& a, double s) {
  a[0] *= s; a[1] *= s; a[2] *= s;
  return a;
}

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm2(const Vec3& a) { return dot(a, a); }
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// Unit vector along a; the zero vector stays zero (callers that need a direction
// must check the length first).
inline Vec3 normalized(const Vec3& a) {
  const double l = norm(a);
  return l > 0.0 ? a / l : Vec3{0.0, 0.0, 0.0};
}

// Angle between a and b in radians, in [0, pi]. atan2 keeps full accuracy near 0 and pi
// where acos of a dot product loses half the digits.
inline double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

inline bool is_finite(const Vec3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

// Bitwise equality, for memos of pure functions of the coordinates (-0.0 and 0.0 differ,
// a NaN equals itself): == would call distinct inputs the same.
inline bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof a) == 0; }
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace blayer
