// Deterministic CAD-like vertex fans: a vertex of a tessellated box, cylinder or wing
// where one incident face is triangulated as a fan of many thin triangles from the
// vertex (what CAD exporters do with planar faces), valence 12-80, randomly rotated and
// scaled, with optional offsets that make the faces non-planar the way offset fronts are
// (the faces' junctions then turn reflex or convex at random).
//   kRidge     an edge of a box: a fan face and a few-triangle face meeting at a
//              dihedral angle, convex or concave (fluid outside or inside);
//   kCorner    a box corner: one fan face and two plain faces;
//   kRim       a cylinder rim: the cap fan-triangulated from the vertex, the side strips;
//   kSliver    a wing skin vertex whose spanwise triangles are slivers spanning the span.
#pragma once

#include <cmath>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

#include "blayer/core/vec3.h"
#include "random_fans.h"
#include "test_fans.h"

namespace blayer {
namespace testing_fans {

enum class CadShape { kRidge, kCorner, kRim, kSliver };

// Every shape, in the enum's order: the order in which the sets below and the
// benchmarks' sets draw them (another order would draw other fans).
inline constexpr CadShape kCadShapes[] = {CadShape::kRidge, CadShape::kCorner, CadShape::kRim, CadShape::kSliver};

inline const char* cad_shape_name(CadShape s) {
  switch (s) {
    case CadShape::kRidge: return "ridge";
    case CadShape::kCorner: return "corner";
    case CadShape::kRim: return "rim";
    case CadShape::kSliver: return "sliver";
  }
  return "";
}

// Ring of valence about k around p = 0 (the exact valence depends on the shape), with
// every ring point moved by `offset` times its distance in a random direction.
inline std::vector<Vec3> cad_like_fan(std::mt19937& rng, CadShape shape, int k, double offset) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> ring;
  auto in_plane = [](const Vec3& a, const Vec3& b, double angle, double r) {
    return r * (std::cos(angle) * a + std::sin(angle) * b);
  };
  // Thin fan triangles: uneven angular steps and radii, as a fan over a polygon's
  // vertices has.
  auto fan_sector = [&](const Vec3& from, const Vec3& to_dir, double span, int n, bool include_start) {
    std::vector<double> steps(n);
    double sum = 0.0;
    for (double& s : steps) sum += (s = 0.2 + u(rng));
    double angle = 0.0;
    for (int j = 0; j < n; ++j) {
      if (j > 0 || include_start) ring.push_back(in_plane(from, to_dir, angle, 0.3 + 2.7 * u(rng)));
      angle += span * steps[j] / sum;
    }
  };
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  switch (shape) {
    case CadShape::kRidge: {
      // Ridge along y; the fan face holds directions (cos t) y + (sin t) a, the other
      // face (cos t)(-y) + (sin t) b. delta > 0 bends both faces down: convex.
      const double delta = (u(rng) - 0.5) * 2.6;  // about -75 to 75 degrees
      const Vec3 a{-std::cos(delta), 0.0, -std::sin(delta)}, b{std::cos(delta), 0.0, -std::sin(delta)};
      fan_sector(y, a, M_PI, k - 3, true);
      fan_sector(-y, b, M_PI, 3, true);
      break;
    }
    case CadShape::kCorner: {
      // Edges -y, -z, -x (convex corner of the solid [-1,0]^3, as T2) or +y, +z, +x
      // (concave, fluid in the positive octant, as T3); the first face fan-triangulated.
      const double s = u(rng) < 0.5 ? -1.0 : 1.0;
      const Vec3 e1 = s * y, e2 = s * z, e3 = s * x;
      fan_sector(e1, e2, 0.5 * M_PI, k - 4, true);
      fan_sector(e2, e3, 0.5 * M_PI, 2, true);
      fan_sector(e3, e1, 0.5 * M_PI, 2, true);
      break;
    }
    case CadShape::kRim: {
      // Cap: the disc of radius R centred at (R, 0, 0) in z = 0, its m polygon vertices
      // joined to p = 0; side: the cylinder below, strips down to z = -h.
      const int m = k - 2;
      const double radius = 1.0, h = 0.2 + 2.0 * u(rng);
      const Vec3 c{radius, 0.0, 0.0};
      std::vector<Vec3> cap;
      for (int j = 1; j < m; ++j) {
        const double phi = M_PI + 2.0 * M_PI * j / m;
        cap.push_back(c + radius * Vec3{std::cos(phi), std::sin(phi), 0.0});
      }
      // Walking around p: the cap vertices (counter-clockwise seen from +z), then the
      // side: the last cap vertex below, p below, the first cap vertex below.
      for (const Vec3& q : cap) ring.push_back(q);
      ring.push_back(cap.back() - h * z);
      ring.push_back(-h * z);
      ring.push_back(cap.front() - h * z);
      // Cap faces (p, q_j, q_j+1) with q counter-clockwise have normal +z: fluid above
      // and outside the cylinder (fluid side of the side strips outward).
      break;
    }
    case CadShape::kSliver: {
      // Near-flat skin z = -(c x^2)/2: a few chordwise triangles and, on each side, a fan
      // of slivers towards far spanwise points.
      const double curv = 0.2 * u(rng);
      auto skin = [&](double px, double py) { return Vec3{px, py, -0.5 * curv * px * px}; };
      const int side = (k - 2) / 2;
      ring.push_back(skin(0.3 + 0.2 * u(rng), 0.0));
      for (int j = 0; j < side; ++j) ring.push_back(skin(0.3 * (1.0 - 2.0 * (j + 0.5) / side), 20.0 + 5.0 * u(rng)));
      ring.push_back(skin(-0.3 - 0.2 * u(rng), 0.0));
      for (int j = 0; j < side; ++j)
        ring.push_back(skin(-0.3 * (1.0 - 2.0 * (j + 0.5) / side), -20.0 - 5.0 * u(rng)));
      break;
    }
  }
  std::normal_distribution<double> nd;
  for (Vec3& r : ring) {
    const Vec3 dir = normalized(Vec3{nd(rng), nd(rng), nd(rng)});
    r += offset * norm(r) * dir;
  }
  const double scale = std::pow(10.0, 4.0 * u(rng) - 2.0);
  Vec3 q[3];
  random_rotation(rng, q);
  for (Vec3& r : ring) r = scale * rotate(r, q);
  return ring;
}

// The standard set of CAD-like fans: for each valence, offset (0, 1e-5 and 1e-3 of the
// edge length) and shape, `per_shape` fans drawn from rng in that order, each passed to
// visit(geometry, label) unless degenerate. The label names shape, valence, offset and
// draw.
template <class Visit>
void for_each_cad_fan(std::mt19937& rng, std::initializer_list<int> valences, int per_shape, Visit&& visit) {
  for (int valence : valences)
    for (double offset : {0.0, 1e-5, 1e-3})
      for (CadShape shape : kCadShapes)
        for (int t = 0; t < per_shape; ++t) {
          FanGeometry g = geometry(cad_like_fan(rng, shape, valence, offset));
          if (g.any_degenerate) continue;
          visit(std::move(g), std::string(cad_shape_name(shape)) + " k " + std::to_string(valence) + " offset " +
                                  std::to_string(offset) + " #" + std::to_string(t));
        }
}

}  // namespace testing_fans
}  // namespace blayer
