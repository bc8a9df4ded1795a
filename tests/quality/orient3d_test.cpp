#include "blayer/quality/orient3d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace blayer {
namespace {

TEST(Orient3d, PositiveWhenFourthPointIsOnTheRightHandNormalSide) {
  EXPECT_EQ(orient3d_sign({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}), 1);
  EXPECT_EQ(orient3d_sign({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}), -1);
  EXPECT_EQ(orient3d_sign({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}), -1);
}

TEST(Orient3d, ZeroForExactlyCoplanarPoints) {
  EXPECT_EQ(orient3d_sign({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.7, 0}), 0);
  // Coplanar points in a tilted plane x + y + z = 1 with binary-exact coordinates.
  EXPECT_EQ(orient3d_sign({1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.25, 0.25, 0.5}), 0);
}

// Sign of det[b-a, c-a, d-a] for integer points, exact in 128-bit arithmetic
// (coordinate differences below 2^41 keep every triple product below 2^123).
int exact_integer_orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  auto diff = [](const Vec3& p, const Vec3& q, int i) {
    return static_cast<__int128>(static_cast<std::int64_t>(p[i]) - static_cast<std::int64_t>(q[i]));
  };
  const __int128 u0 = diff(b, a, 0), u1 = diff(b, a, 1), u2 = diff(b, a, 2);
  const __int128 v0 = diff(c, a, 0), v1 = diff(c, a, 1), v2 = diff(c, a, 2);
  const __int128 w0 = diff(d, a, 0), w1 = diff(d, a, 1), w2 = diff(d, a, 2);
  const __int128 det = u0 * (v1 * w2 - v2 * w1) - u1 * (v0 * w2 - v2 * w0) + u2 * (v0 * w1 - v1 * w0);
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

int naive_double_orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 u = b - a, v = c - a, w = d - a;
  const double det = dot(u, cross(v, w));
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

TEST(Orient3d, MatchesExactIntegerArithmeticOnNearlyCoplanarPointsWhereDoublesFail) {
  // b = a + p, c = a + q with |p|, |q| ~ 2^20, and d = a + s p + t q + r with |s|, |t| ~ 2^19
  // and r in {-1,0,1}^3: det = det(p, q, r) is a small integer (often 0) while the
  // products in a double evaluation reach 2^80 and carry rounding errors near 2^27.
  // All coordinates and differences are integers below 2^53, so the inputs are exact
  // and the true sign is known from 128-bit integers.
  std::mt19937_64 rng(12345);
  std::uniform_int_distribution<std::int64_t> base(0, std::int64_t{1} << 40);
  std::uniform_int_distribution<std::int64_t> edge(-(std::int64_t{1} << 20), std::int64_t{1} << 20);
  std::uniform_int_distribution<std::int64_t> step(-(std::int64_t{1} << 19), std::int64_t{1} << 19);
  std::uniform_int_distribution<std::int64_t> nudge(-1, 1);
  int naive_wrong = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    std::int64_t a[3], p[3], q[3];
    for (int i = 0; i < 3; ++i) a[i] = base(rng), p[i] = edge(rng), q[i] = edge(rng);
    const std::int64_t s = step(rng), t = step(rng);
    Vec3 pa, pb, pc, pd;
    for (int i = 0; i < 3; ++i) {
      pa[i] = static_cast<double>(a[i]);
      pb[i] = static_cast<double>(a[i] + p[i]);
      pc[i] = static_cast<double>(a[i] + q[i]);
      pd[i] = static_cast<double>(a[i] + s * p[i] + t * q[i] + nudge(rng));
    }
    const int exact = exact_integer_orientation(pa, pb, pc, pd);
    ASSERT_EQ(orient3d_sign(pa, pb, pc, pd), exact) << "trial " << trial;
    if (naive_double_orientation(pa, pb, pc, pd) != exact) ++naive_wrong;
  }
  // The test is only meaningful if plain doubles get some of these signs wrong.
  EXPECT_GT(naive_wrong, 100);
}

TEST(Orient3d, AntisymmetricUnderSwapsOnNearlyCoplanarPoints) {
  const Vec3 a{0.1, 0.2, 0.3};
  const Vec3 b{0.4, 0.5, 0.6};
  const Vec3 c{0.7, 0.8, 0.9000000000000001};
  const Vec3 d{1.0, 1.1, 1.2};
  const int s = orient3d_sign(a, b, c, d);
  EXPECT_EQ(orient3d_sign(b, a, c, d), -s);
  EXPECT_EQ(orient3d_sign(a, b, d, c), -s);
  EXPECT_EQ(orient3d_sign(b, c, d, a), -s);  // a cyclic shift of four points is odd
}

}  // namespace
}  // namespace blayer
