#include "blayer/normals/fan_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace blayer {

void build_fan_geometry(const Vec3& p, const std::vector<Vec3>& ring, bool closed, const Tolerances& tol,
                        FanGeometry* out) {
  FanGeometry& g = *out;
  g.closed = closed;
  g.any_degenerate = false;
  const int n_ring = static_cast<int>(ring.size());
  const int k = closed ? n_ring : n_ring - 1;
  // Per-thread scratch: callers build one fan per vertex, and the allocations would
  // otherwise cost as much as the geometry.
  thread_local std::vector<Vec3> edge;
  thread_local std::vector<double> len;
  edge.resize(n_ring);
  len.resize(n_ring);
  g.dirs.resize(n_ring);
  for (int j = 0; j < n_ring; ++j) {
    edge[j] = ring[j] - p;
    len[j] = norm(edge[j]);
    g.dirs[j] = len[j] > 0.0 ? edge[j] / len[j] : Vec3{0.0, 0.0, 0.0};
  }
  g.face_normals.resize(k);
  g.angles.resize(k);
  g.areas.resize(k);
  g.max_weights.resize(k);
  g.degenerate.assign(k, 0);
  for (int i = 0; i < k; ++i) {
    const int j = (i + 1) % n_ring;
    const Vec3 c = cross(edge[i], edge[j]);
    const double twice_area = norm(c);
    const double opposite = norm(edge[j] - edge[i]);
    const double longest = std::max({len[i], len[j], opposite});
    const bool degenerate = !(twice_area > tol.degenerate_relative_height * longest * longest);
    g.degenerate[i] = degenerate ? 1 : 0;
    g.any_degenerate |= degenerate;
    g.face_normals[i] = twice_area > 0.0 ? c / twice_area : Vec3{0.0, 0.0, 0.0};
    g.angles[i] = std::atan2(twice_area, dot(edge[i], edge[j]));
    g.areas[i] = 0.5 * twice_area;
    const double ll = len[i] * len[j];
    g.max_weights[i] = ll > 0.0 ? twice_area / (ll * ll) : 0.0;
  }
}

FanGeometry build_fan_geometry(const Vec3& p, const std::vector<Vec3>& ring, bool closed,
                               const Tolerances& tol) {
  FanGeometry g;
  build_fan_geometry(p, ring, closed, tol, &g);
  return g;
}

double fan_visibility(const FanGeometry& g, const Vec3& n) {
  double v = std::numeric_limits<double>::infinity();
  for (int i = 0; i < g.n_faces(); ++i)
    if (!g.degenerate[i]) v = std::min(v, dot(n, g.face_normals[i]));
  return v;
}

double distance_to_arc(const Vec3& n, const Vec3& u, const Vec3& v, const Vec3& f) {
  const double nf = dot(n, f);
  const Vec3 m = n - nf * f;
  const double mm = norm(m);
  // At the pole of the arc's circle every point of the arc is 90 degrees away.
  if (mm == 0.0) return 0.5 * M_PI;
  if (dot(cross(u, m), f) >= 0.0 && dot(cross(m, v), f) >= 0.0) return std::atan2(std::fabs(nf), mm);
  return std::min(angle_between(n, u), angle_between(n, v));
}

namespace {

// Proxies are cosines of the arc distances up to rounding (~1e-16 times |n|); arcs
// whose proxy is this far below the largest are certainly farther than the nearest one.
constexpr double kProxyMargin = 1e-12;

// |n| times the cosine of distance_to_arc(n, u, v, f), without arctangents.
double arc_proxy(const Vec3& n, const Vec3& u, const Vec3& v, const Vec3& f) {
  const Vec3 m = n - dot(n, f) * f;
  const double mm = norm(m);
  if (mm == 0.0) return 0.0;
  if (dot(cross(u, m), f) >= 0.0 && dot(cross(m, v), f) >= 0.0) return mm;
  return std::max(dot(n, u), dot(n, v));
}

}  // namespace

double fan_normality(const FanGeometry& g, const Vec3& n) {
  // The nearest arc is found by cosine first; the arctangents are evaluated only for the
  // arcs that may be nearest, so the minimum is the same value as over all arcs.
  const int k = g.n_faces();
  double best = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < k; ++i) best = std::max(best, arc_proxy(n, g.arc_start(i), g.arc_end(i), g.face_normals[i]));
  const double cut = best - kProxyMargin * std::max(1.0, norm(n));
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < k; ++i)
    if (arc_proxy(n, g.arc_start(i), g.arc_end(i), g.face_normals[i]) >= cut)
      d = std::min(d, distance_to_arc(n, g.arc_start(i), g.arc_end(i), g.face_normals[i]));
  return d;
}

}  // namespace blayer
