#include "visibility_boundary.h"

#include <cmath>

namespace blayer {
namespace detail {

namespace {

// Below this |from x to| the two directions are equal or opposite to about 1e-12 rad:
// the arc between them, and its tangent b, are not determined (their products carry
// ~1e-16 of rounding, so b would keep only four digits at 1e-12).
constexpr double kShortestArcSine = 1e-12;

}  // namespace

bool first_direction_at_visibility(const Vec3* face_normals, int k, const Vec3& from, const Vec3& to, double v_min,
                                   Vec3* out) {
  const double c = dot(from, to);
  const Vec3 tangent = to - c * from;
  const double s = norm(tangent);
  if (!(s > kShortestArcSine)) return false;
  const Vec3 b = tangent / s;
  const double end = std::atan2(s, c);  // the arc's length, in (0, pi)
  double first = end;
  bool crosses = false;
  for (int i = 0; i < k; ++i) {
    const double a_i = dot(face_normals[i], from), b_i = dot(face_normals[i], b);
    if (!(a_i > v_min)) return false;
    // R_i >= a_i > v_min, and |phi_i| < arccos(v_min / R_i) because f_i.n(0) = a_i >
    // v_min: the first root after t = 0 is the one where the cosine falls.
    const double r_i = std::hypot(a_i, b_i);
    const double t_i = std::atan2(b_i, a_i) + std::acos(v_min / r_i);
    if (t_i <= first) {
      first = t_i;
      crosses = true;
    }
  }
  if (!crosses) return false;
  *out = std::cos(first) * from + std::sin(first) * b;
  return true;
}

}  // namespace detail
}  // namespace blayer
