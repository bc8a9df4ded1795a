// The exact candidate families of the most-normal problem (docs/normals.md, Part 4), for
// any subset of the sites: 1-site critical points, 2-site bisector extrema, 3-site
// Voronoi vertices, the points of the visibility-constraint circles, and the
// visibility peaks along plateau circles. Each family hands its directions (unnormalised)
// to `emit`. The full enumeration passes every site; a local solver passes the few
// sites that can be nearest in a small region. Internal to blayer_normals.
#pragma once

#include <cmath>
#include <vector>

#include "blayer/core/vec3.h"
#include "fan_sites.h"
#include "sphere_solvers.h"

namespace blayer {
namespace detail {

// Smallest |x| of a candidate x = h x (w x f) discarded with its circle when the circle
// is screened off: its direction, after normalisation, is within 1e-16 / 1e-3 = 1e-13 of
// the circle, inside the level at which screens decide (kCircleLevel, most_normal.cpp).
constexpr double kCircleCandidateNorm = 1e-3;

// Indices of the points and arcs of a FanSites taking part.
struct SiteSubset {
  const int* points = nullptr;
  int n_points = 0;
  const int* arcs = nullptr;
  int n_arcs = 0;
};

// 1- and 2-site candidates: antipodes of points, poles of arcs, point-point and arc-arc
// bisector peaks, and the four extrema of each point-arc parabola.
template <class Emit>
void single_and_pair_candidates(const FanSites& s, const SiteSubset& sub, Emit&& emit) {
  const int np = sub.n_points, na = sub.n_arcs;
  for (int a = 0; a < np; ++a) emit(-s.points[sub.points[a]].w);
  for (int a = 0; a < na; ++a) emit(s.arcs[sub.arcs[a]].g);
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) emit(-(s.points[sub.points[a]].w + s.points[sub.points[b]].w));
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b) emit(s.arcs[sub.arcs[a]].g + s.arcs[sub.arcs[b]].g);
  // Point-arc parabola extrema: where it crosses the plane of w and f, at the angles
  // tf/2 +- pi/4 (and their antipodes) from w, tf = angle(w, f). For unit w and f,
  // p = w + f and q = f - w are orthogonal, at angles tf/2 and tf/2 + pi/2, so those
  // directions are p/|p| +- q/|q|, scaled here by |p| |q| (candidates are normalised
  // later): no angle round trip. Each of p, q is as well conditioned as the in-plane
  // axis f - (w.f) w, and both vanish only when f = +-w.
  for (int a = 0; a < np; ++a)
    for (int b = 0; b < na; ++b) {
      const Vec3& w = s.points[sub.points[a]].w;
      const Vec3& g = s.arcs[sub.arcs[b]].g;
      const Vec3 p = w + g, q = g - w;
      const double lp = norm(p), lq = norm(q);
      if (lp == 0.0 || lq == 0.0) continue;
      const Vec3 x = lq * p + lp * q, y = lq * p - lp * q;
      emit(x);
      emit(-x);
      emit(y);
      emit(-y);
    }
}

// 3-site candidates: Voronoi vertices of three points or three arcs (both signs), and
// of two points with an arc or two arcs with a point, on the great-circle bisector of
// the pair. skip_circle(h) may declare that no candidate on the bisector {n.h = 0} can
// matter; its candidates are then not built, except the short cross products, whose
// direction is too unreliable to be placed on the circle.
template <class SkipCircle, class Emit>
void triple_candidates(const FanSites& s, const SiteSubset& sub, SkipCircle&& skip_circle, Emit&& emit) {
  const int np = sub.n_points, na = sub.n_arcs;
  auto pw = [&](int a) -> const Vec3& { return s.points[sub.points[a]].w; };
  auto ag = [&](int a) -> const Vec3& { return s.arcs[sub.arcs[a]].g; };
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b)
      for (int c = b + 1; c < np; ++c) {
        const Vec3 h = cross(pw(a) - pw(b), pw(b) - pw(c));
        emit(h);
        emit(-h);
      }
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b)
      for (int c = b + 1; c < na; ++c) {
        const Vec3 h = cross(ag(a) - ag(b), ag(b) - ag(c));
        emit(h);
        emit(-h);
      }
  // Point-point bisector (great circle) against point-arc bisector (cone).
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) {
      const Vec3 h = normalized(pw(a) - pw(b));
      if (norm2(h) == 0.0) continue;
      const bool skipped = skip_circle(h);
      for (int c = 0; c < na; ++c) {
        const Vec3 x = cross(h, cross(pw(a), ag(c)));
        if (skipped && norm(x) >= kCircleCandidateNorm) continue;
        if (!skipped) circle_cone(h, 0.0, pw(a), ag(c), emit);
        emit(x);
        emit(-x);
      }
    }
  // Arc-arc bisector (great circle) against point-arc bisector (cone).
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b) {
      const Vec3 h = normalized(ag(a) - ag(b));
      if (norm2(h) == 0.0) continue;
      const bool skipped = skip_circle(h);
      for (int c = 0; c < np; ++c) {
        const Vec3 x = cross(h, cross(pw(c), ag(a)));
        if (skipped && norm(x) >= kCircleCandidateNorm) continue;
        if (!skipped) circle_cone(h, 0.0, pw(c), ag(a), emit);
        emit(x);
        emit(-x);
      }
    }
}

// Candidates on the constraint circles {n.f_i = v_min} of the faces `faces` (fan arc
// indices): with each other, with every bisector of the subset, and the single-site
// extrema along each circle (towards and away from each site's axis).
template <class Emit>
void constraint_candidates(const FanGeometry& g, const FanSites& s, const SiteSubset& sub, const int* faces,
                           int n_faces, double v_min, Emit&& emit) {
  const int np = sub.n_points, na = sub.n_arcs;
  auto pw = [&](int a) -> const Vec3& { return s.points[sub.points[a]].w; };
  auto ag = [&](int a) -> const Vec3& { return s.arcs[sub.arcs[a]].g; };
  const double c0 = v_min, sn = std::sqrt(std::max(0.0, 1.0 - c0 * c0));
  for (int ii = 0; ii < n_faces; ++ii) {
    const Vec3& fi = g.face_normals[faces[ii]];
    for (int jj = ii + 1; jj < n_faces; ++jj) plane_plane_sphere(fi, c0, g.face_normals[faces[jj]], c0, emit);
    for (int a = 0; a < np; ++a)
      for (int b = a + 1; b < np; ++b) plane_plane_sphere(fi, c0, pw(a) - pw(b), 0.0, emit);
    for (int a = 0; a < na; ++a)
      for (int b = a + 1; b < na; ++b) plane_plane_sphere(fi, c0, ag(a) - ag(b), 0.0, emit);
    for (int a = 0; a < np; ++a)
      for (int b = 0; b < na; ++b) circle_cone(fi, c0, pw(a), ag(b), emit);
    auto along = [&](const Vec3& axis) {
      const Vec3 t = normalized(axis - dot(axis, fi) * fi);
      if (norm2(t) == 0.0) return;
      emit(c0 * fi + sn * t);
      emit(c0 * fi - sn * t);
    };
    for (int a = 0; a < np; ++a) along(pw(a));
    for (int a = 0; a < na; ++a) along(ag(a));
  }
}

// A circle {n.h = c0} (h unit) along which two concentric sites keep D constant.
struct PlateauCircle {
  Vec3 h;
  double c0;
};

// Plateau circles of the concentric pairs of the subset: antipodal points (within
// `tie`), a point at an arc's pole, two arcs on one great circle (at D = d_best).
inline void plateau_circles(const FanSites& s, const SiteSubset& sub, double tie, double d_best,
                            std::vector<PlateauCircle>* out) {
  const int np = sub.n_points, na = sub.n_arcs;
  auto pw = [&](int a) -> const Vec3& { return s.points[sub.points[a]].w; };
  auto ag = [&](int a) -> const Vec3& { return s.arcs[sub.arcs[a]].g; };
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b)
      if (norm(pw(a) + pw(b)) <= tie) out->push_back({pw(a), 0.0});
  for (int a = 0; a < np; ++a)
    for (int b = 0; b < na; ++b)
      if (norm(pw(a) - ag(b)) <= tie || norm(pw(a) + ag(b)) <= tie) out->push_back({pw(a), std::sqrt(0.5)});
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b)
      if (norm(ag(a) - ag(b)) <= tie || norm(ag(a) + ag(b)) <= tie) {
        out->push_back({ag(a), std::sin(d_best)});
        out->push_back({ag(a), -std::sin(d_best)});
      }
}

// The points of a plateau circle where V = min over `faces` of n.f can peak: a single
// term's peak or the equality of two terms. ca, cb, cc are scratch of n_faces entries.
template <class Emit>
void plateau_peaks(const FanGeometry& g, const PlateauCircle& circ, const int* faces, int n_faces,
                   std::vector<double>* ca, std::vector<double>* cb, std::vector<double>* cc, Emit&& emit) {
  Vec3 e1, e2;
  orthonormal_complement(circ.h, &e1, &e2);
  const double s = std::sqrt(std::max(0.0, 1.0 - circ.c0 * circ.c0));
  ca->resize(n_faces);
  cb->resize(n_faces);
  cc->resize(n_faces);
  // V along the circle is min_i (a_i + b_i cos t + c_i sin t); it peaks at a single
  // term's peak or where two terms are equal.
  for (int i = 0; i < n_faces; ++i) {
    const Vec3& f = g.face_normals[faces[i]];
    (*ca)[i] = circ.c0 * dot(circ.h, f);
    (*cb)[i] = s * dot(e1, f);
    (*cc)[i] = s * dot(e2, f);
  }
  auto at = [&](double t) { emit(circ.c0 * circ.h + s * (std::cos(t) * e1 + std::sin(t) * e2)); };
  for (int i = 0; i < n_faces; ++i) {
    at(std::atan2((*cc)[i], (*cb)[i]));
    for (int j = i + 1; j < n_faces; ++j) {
      const double p = (*cb)[i] - (*cb)[j], q = (*cc)[i] - (*cc)[j], r = (*ca)[j] - (*ca)[i];
      const double amp = std::hypot(p, q);
      if (!(amp > 0.0) || std::fabs(r) > amp) continue;
      const double phi = std::atan2(q, p), da = std::acos(r / amp);
      at(phi + da);
      at(phi - da);
    }
  }
}

}  // namespace detail
}  // namespace blayer
