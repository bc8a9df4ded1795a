// Test-only reference routines written independently of the library: link distance D,
// visibility V, fluid membership by crossing parity, and a brute-force maximiser of D
// (Fibonacci sphere sampling + randomized pattern search), docs/normals.md Part 5.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer {
namespace oracle {
// Internal linkage: each test source keeps its own copy, compiled with its own flags.
// Shared inline functions would be merged at link time, and a copy from a source built
// at -O0 could then serve the sources that keep the build's flags for speed.
namespace {

struct Link {
  std::vector<Vec3> u;  // link vertices (unit), closed
  std::vector<Vec3> g;  // arc plane normals (unit), arc i from u[i] to u[i+1]
};

inline Link make_link(const std::vector<Vec3>& ring) {
  Link l;
  const int k = static_cast<int>(ring.size());
  for (const Vec3& r : ring) l.u.push_back(r / norm(r));
  for (int i = 0; i < k; ++i) l.g.push_back(normalized(cross(ring[i], ring[(i + 1) % k])));
  return l;
}

// Distance to arc i through its angular parametrisation phi in [0, alpha].
inline double arc_distance(const Link& l, int i, const Vec3& n) {
  const int k = static_cast<int>(l.u.size());
  const Vec3& a = l.u[i];
  const Vec3& b = l.u[(i + 1) % k];
  const Vec3 e2 = cross(l.g[i], a);
  const double alpha = std::atan2(dot(b, e2), dot(b, a));
  const double x = dot(n, a), y = dot(n, e2), z = dot(n, l.g[i]);
  const double phi = std::atan2(y, x);
  if (phi >= 0.0 && phi <= alpha) return std::atan2(std::fabs(z), std::hypot(x, y));
  return std::min(std::atan2(norm(cross(n, a)), dot(n, a)), std::atan2(norm(cross(n, b)), dot(n, b)));
}

inline double normality(const Link& l, const Vec3& n) {
  double d = 1e300;
  for (int i = 0; i < static_cast<int>(l.u.size()); ++i) d = std::min(d, arc_distance(l, i, n));
  return d;
}

inline double visibility(const Link& l, const Vec3& n) {
  double v = 1e300;
  for (const Vec3& g : l.g) v = std::min(v, dot(n, g));
  return v;
}

// Number of arcs crossed by the geodesic from a to b (a, b not antipodal).
inline int crossings(const Link& l, const Vec3& a, const Vec3& b) {
  const int k = static_cast<int>(l.u.size());
  const Vec3 h = cross(a, b);
  int c = 0;
  for (int i = 0; i < k; ++i) {
    const Vec3& p = l.u[i];
    const Vec3& q = l.u[(i + 1) % k];
    const double sp = dot(h, p), sq = dot(h, q);
    if ((sp > 0) == (sq > 0)) continue;
    const double sa = dot(l.g[i], a), sb = dot(l.g[i], b);
    if ((sa > 0) == (sb > 0)) continue;
    // Both great circles cross; check the crossing lies on the short sides.
    Vec3 x = normalized(cross(h, l.g[i]));
    if (dot(x, a + b) < 0) x = -x;
    if (dot(x, p + q) <= 0) continue;
    ++c;
  }
  return c;
}

// Fluid reference point: just off arc 0's midpoint on its fluid side.
inline Vec3 reference_point(const Link& l, int i) {
  const int k = static_cast<int>(l.u.size());
  const Vec3 mid = normalized(l.u[i] + l.u[(i + 1) % k]);
  return normalized(mid + 1e-4 * l.g[i]);
}

// Fluid by crossing parity against reference points through two intermediate hops
// (avoids antipodal pairs); returns -1 when the references disagree.
inline int fluid(const Link& l, const Vec3& n) {
  int verdict = -2;
  for (int i = 0; i < std::min<int>(3, static_cast<int>(l.u.size())); ++i) {
    const Vec3 r = reference_point(l, i);
    Vec3 m = normalized(n + r);
    if (norm2(m) == 0.0) m = normalized(cross(n, Vec3{0.3, 0.5, 0.7}));
    const int parity = (crossings(l, r, m) + crossings(l, m, n)) % 2;
    const int v = parity == 0 ? 1 : 0;
    if (verdict == -2) verdict = v;
    else if (verdict != v) return -1;
  }
  return verdict;
}

struct Best {
  Vec3 n{0, 0, 1};
  double d = -1.0;
};

// Brute-force max of D over the fluid region with V >= v_min.
inline Best maximise(const Link& l, double v_min, int n_samples, unsigned seed, std::size_t n_seeds = 6) {
  std::vector<std::pair<double, Vec3>> samples;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n_samples; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n_samples;
    const double r = std::sqrt(1.0 - z * z);
    const Vec3 n{r * std::cos(golden * i), r * std::sin(golden * i), z};
    if (visibility(l, n) < v_min) continue;
    if (fluid(l, n) != 1) continue;
    samples.push_back({normality(l, n), n});
  }
  std::sort(samples.begin(), samples.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Vec3> seeds;
  for (const auto& s : samples) {
    bool far = true;
    for (const Vec3& q : seeds) far &= std::atan2(norm(cross(q, s.second)), dot(q, s.second)) > 0.05;
    if (far) seeds.push_back(s.second);
    if (seeds.size() >= n_seeds) break;
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 2.0 * M_PI);
  Best best;
  auto score = [&](const Vec3& n) {
    if (visibility(l, n) < v_min || fluid(l, n) != 1) return -1.0;
    return normality(l, n);
  };
  for (Vec3 n : seeds) {
    double d = score(n);
    double step = 0.02;
    while (step > 1e-14) {
      Vec3 e1 = normalized(cross(n, Vec3{0.31, -0.72, 0.55}));
      Vec3 e2 = cross(n, e1);
      const double rot = uni(rng);
      bool improved = false;
      for (int j = 0; j < 48 && !improved; ++j) {
        const double a = rot + j * (2.0 * M_PI / 48.0);
        const Vec3 c = normalized(n + step * (std::cos(a) * e1 + std::sin(a) * e2));
        const double dc = score(c);
        if (dc > d) {
          d = dc;
          n = c;
          improved = true;
        }
      }
      step *= improved ? 1.5 : 0.5;
    }
    if (d > best.d) {
      best.d = d;
      best.n = n;
    }
  }
  return best;
}

}  // namespace
}  // namespace oracle
}  // namespace blayer
