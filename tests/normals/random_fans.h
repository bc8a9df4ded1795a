// Deterministic random fans for oracle and invariance tests: valence 3-20, convex,
// concave, saddle and sliver shapes, randomly rotated.
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer {
namespace testing_fans {

enum class Shape { kConvex, kConcave, kSaddle, kSliver, kWild };

inline const char* shape_name(Shape s) {
  switch (s) {
    case Shape::kConvex: return "convex";
    case Shape::kConcave: return "concave";
    case Shape::kSaddle: return "saddle";
    case Shape::kSliver: return "sliver";
    case Shape::kWild: return "wild";
  }
  return "";
}

inline Vec3 rotate(const Vec3& x, const Vec3 q[3]) {
  return {dot(q[0], x), dot(q[1], x), dot(q[2], x)};
}

inline void random_rotation(std::mt19937& rng, Vec3 q[3]) {
  std::normal_distribution<double> nd;
  q[0] = normalized(Vec3{nd(rng), nd(rng), nd(rng)});
  Vec3 b{nd(rng), nd(rng), nd(rng)};
  q[1] = normalized(b - dot(b, q[0]) * q[0]);
  q[2] = cross(q[0], q[1]);
}

// Ring around p = 0 with monotone azimuth (gaps < 180 degrees), so the fan is a
// height field over some plane: visible and simple.
inline std::vector<Vec3> random_fan(std::mt19937& rng, Shape shape) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int k = 3 + static_cast<int>(u(rng) * 18);
  std::vector<double> gaps(k);
  double sum = 0;
  for (int i = 0; i < k; ++i) {
    gaps[i] = shape == Shape::kSliver && u(rng) < 0.3 ? 0.01 + 0.02 * u(rng) : 0.3 + u(rng);
    sum += gaps[i];
  }
  for (double& g : gaps) g *= 2 * M_PI / sum;
  bool ok = true;
  for (double g : gaps) ok &= g < 0.9 * M_PI;
  if (!ok) return random_fan(rng, shape);
  const double amp = 0.2 + 1.5 * u(rng);
  const int waves = 2 + static_cast<int>(u(rng) * 2);
  const double phase = u(rng) * 2 * M_PI;
  std::vector<Vec3> ring;
  double az = u(rng) * 2 * M_PI;
  for (int i = 0; i < k; ++i) {
    const double r = 0.3 + u(rng);
    double z = 0;
    switch (shape) {
      case Shape::kConvex: z = -amp * r * (0.5 + u(rng)); break;
      case Shape::kConcave: z = amp * r * (0.5 + u(rng)); break;
      case Shape::kSaddle: z = amp * r * std::cos(waves * az + phase); break;
      case Shape::kSliver: z = amp * r * (u(rng) - 0.5); break;
      case Shape::kWild: z = amp * r * (2 * u(rng) - 1) * 2; break;
    }
    ring.push_back({r * std::cos(az), r * std::sin(az), z});
    az += gaps[i];
  }
  Vec3 q[3];
  random_rotation(rng, q);
  for (Vec3& x : ring) x = rotate(x, q);
  return ring;
}

// k ring points on the quadric z = -(k1 x^2 + k2 y^2) / 2 plus uniform jitter in z, at
// irregular radii and azimuths, randomly rotated: the fan of a vertex on a curved skin.
inline std::vector<Vec3> quadric_fan(std::mt19937& rng, int k, double k1, double k2, double jitter) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> ring;
  double az = u(rng) * 2 * M_PI;
  for (int i = 0; i < k; ++i) {
    const double r = 0.5 + u(rng);
    const double x = r * std::cos(az), y = r * std::sin(az);
    ring.push_back({x, y, -0.5 * (k1 * x * x + k2 * y * y) + jitter * (u(rng) - 0.5)});
    az += 2 * M_PI / k * (0.7 + 0.6 * u(rng));
  }
  Vec3 q[3];
  random_rotation(rng, q);
  for (Vec3& x : ring) x = rotate(x, q);
  return ring;
}

// Vertex of z = -(k1 x^2 + k2 y^2) / 2 plus jitter, k2 of either sign and small: the
// spanwise-flat, slightly saddle-shaped wing skin with mesh noise that makes some
// junctions reflex. A random scale shrinks the curvature towards an exactly flat fan.
inline std::vector<Vec3> near_flat_fan(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int k = 4 + static_cast<int>(u(rng) * 7);
  const double scale = std::pow(10.0, -4.0 * u(rng));
  const double k1 = scale * (u(rng) - 0.3), k2 = scale * 1e-2 * (u(rng) - 0.5);
  const double jitter = scale * 1e-2 * u(rng);
  return quadric_fan(rng, k, k1, k2, jitter);
}

// Vertex of z = -(k1 x^2 + k2 y^2) / 2 with a jittered ring: k2 near 0 gives the
// spanwise flatness of a wing, where rounding of the mesh makes some edges concave.
inline std::vector<Vec3> skin_fan(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int k = 4 + static_cast<int>(u(rng) * 6);
  const double k1 = 0.05 + u(rng), k2 = 1e-3 * u(rng);
  const double jitter = 1e-3 * u(rng);
  return quadric_fan(rng, k, k1, k2, jitter);
}

}  // namespace testing_fans
}  // namespace blayer
