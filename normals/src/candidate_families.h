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
// the circle, inside the level at which screens decide (kCircleLevel,
// most_normal_enumeration.cpp).
constexpr double kCircleCandidateNorm = 1e-3;

// What a caller may rule out before or after candidates are built (each "rule out"
// must be proved: no candidate so ruled out is needed):
//   circle(h)          no candidate on the bisector {n.h = 0} (h unit);
//   arc(h, g)          no candidate on that bisector with the arc of pole g among its
//                      generators;
//   arc_pair(g1, g2)   no candidate with both arcs among its generators;
//   point_ok(x, w), arc_ok(x, g)
//                      whether candidate x (any length) can have the point w, or the arc
//                      of pole g, among its generators.
struct NoScreen {
  bool circle(const Vec3&) const { return false; }
  bool arc(const Vec3&, const Vec3&) const { return false; }
  bool arc_pair(const Vec3&, const Vec3&) const { return false; }
  bool point_ok(const Vec3&, const Vec3&) const { return true; }
  bool arc_ok(const Vec3&, const Vec3&) const { return true; }
};

// Below this |a + b| (for unit a, b) a bisector peak is projected on the bisector's
// plane: the sum's direction carries ~1e-16 / |a + b| of rounding, up to 1e-12 rad here,
// three orders inside normality_tie; above it the sum is kept bit for bit.
constexpr double kOppositeSum = 1e-4;

// The peak of D along the bisector of two sites of one kind: a + b for the poles of two
// arcs, -(a + b) for two points (the caller's sign), in exact arithmetic, where the sum
// lies in the bisector's plane {x.(a - b) = 0}. The sum is ill-conditioned when a and b
// are nearly opposite: the spanwise neighbours on a straight sharp trailing edge are
// antipodal to 1e-8, and the sum's rounding (~1e-16 per component) then turns it off the
// bisector by ~1e-8 rad, where D falls by about as much (on the ONERA M6 571k it missed
// the peak, 3.9e-9 above 90 degrees, by 5.5e-9). There the sum is projected on that
// plane, whose normal a - b is then well conditioned: the candidate stays on the
// bisector, along which D is flat to second order at the peak. Elsewhere a - b may be
// the ill-conditioned one (nearly coplanar faces: projecting there moved a flat fan's
// answer off its peak by 5.4e-9).
inline Vec3 bisector_peak(const Vec3& a, const Vec3& b) {
  const Vec3 sum = a + b;
  if (!(norm2(sum) < kOppositeSum * kOppositeSum)) return sum;
  const Vec3 h = normalized(a - b);
  return sum - dot(sum, h) * h;
}

// The four extrema of the point-arc parabola of point site w and arc site g, those the
// screen keeps: where it crosses the plane of w and g, at the angles tg/2 +- pi/4 (and
// their antipodes) from w, tg = angle(w, g). For unit w and g, p = w + g and q = g - w
// are orthogonal, at angles tg/2 and tg/2 + pi/2, so those directions are p/|p| +-
// q/|q|, scaled here by |p| |q| (candidates are normalised later): no angle round trip.
// Each of p, q is as well conditioned as the in-plane axis g - (w.g) w, and both vanish
// only when g = +-w.
template <class Screen, class Emit>
void point_arc_extrema(const Vec3& w, const Vec3& g, const Screen& screen, Emit&& emit) {
  const Vec3 p = w + g, q = g - w;
  const double lp = norm(p), lq = norm(q);
  if (lp == 0.0 || lq == 0.0) return;
  const Vec3 x = lq * p + lp * q, y = lq * p - lp * q;
  for (const Vec3& c : {x, -x, y, -y})
    if (screen.point_ok(c, w) && screen.arc_ok(c, g)) emit(c);
}

// 1- and 2-site candidates: antipodes of points, poles of arcs, point-point and arc-arc
// bisector peaks, and the four extrema of each point-arc parabola.
template <class Screen, class Emit>
void single_and_pair_candidates(const FanSites& s, const SiteSubset& sub, const Screen& screen, Emit&& emit) {
  const int np = sub.n_points, na = sub.n_arcs;
  for (int a = 0; a < np; ++a) emit(-s.points[sub.points[a]].w);
  for (int a = 0; a < na; ++a)
    if (screen.arc_ok(s.arcs[sub.arcs[a]].g, s.arcs[sub.arcs[a]].g)) emit(s.arcs[sub.arcs[a]].g);
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) emit(-bisector_peak(s.points[sub.points[a]].w, s.points[sub.points[b]].w));
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b)
      if (!screen.arc_pair(s.arcs[sub.arcs[a]].g, s.arcs[sub.arcs[b]].g))
        emit(bisector_peak(s.arcs[sub.arcs[a]].g, s.arcs[sub.arcs[b]].g));
  for (int a = 0; a < np; ++a)
    for (int b = 0; b < na; ++b) point_arc_extrema(s.points[sub.points[a]].w, s.arcs[sub.arcs[b]].g, screen, emit);
}

// The candidates of one site (its antipode or pole) or of one pair (bisector peak or
// point-arc extrema) alone: single_and_pair_candidates restricted to a subset of one or
// two sites, without repeating the single-site ones for a pair.
template <class Screen, class Emit>
void pair_candidates(const FanSites& s, const SiteSubset& sub, const Screen& screen, Emit&& emit) {
  if (sub.n_points + sub.n_arcs == 1) {
    single_and_pair_candidates(s, sub, screen, emit);
    return;
  }
  if (sub.n_points == 2) {
    emit(-bisector_peak(s.points[sub.points[0]].w, s.points[sub.points[1]].w));
  } else if (sub.n_arcs == 2) {
    if (!screen.arc_pair(s.arcs[sub.arcs[0]].g, s.arcs[sub.arcs[1]].g))
      emit(bisector_peak(s.arcs[sub.arcs[0]].g, s.arcs[sub.arcs[1]].g));
  } else {
    point_arc_extrema(s.points[sub.points[0]].w, s.arcs[sub.arcs[0]].g, screen, emit);
  }
}

// 3-site candidates: Voronoi vertices of three points or three arcs (both signs), and
// of two points with an arc or two arcs with a point, on the great-circle bisector of
// the pair. Candidates the screen rules out are not built, except the short cross
// products of a ruled-out circle or arc, whose direction is too unreliable to be placed
// on the circle.
template <class Screen, class Emit>
void triple_candidates(const FanSites& s, const SiteSubset& sub, const Screen& screen, Emit&& emit) {
  const int np = sub.n_points, na = sub.n_arcs;
  auto pw = [&](int a) -> const Vec3& { return s.points[sub.points[a]].w; };
  auto ag = [&](int a) -> const Vec3& { return s.arcs[sub.arcs[a]].g; };
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b)
      for (int c = b + 1; c < np; ++c) {
        const Vec3 h = cross(pw(a) - pw(b), pw(b) - pw(c));
        for (const Vec3& x : {h, -h})
          if (screen.point_ok(x, pw(a))) emit(x);
      }
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b) {
      if (screen.arc_pair(ag(a), ag(b))) continue;
      for (int c = b + 1; c < na; ++c) {
        if (screen.arc_pair(ag(a), ag(c)) || screen.arc_pair(ag(b), ag(c))) continue;
        const Vec3 h = cross(ag(a) - ag(b), ag(b) - ag(c));
        for (const Vec3& x : {h, -h})
          if (screen.arc_ok(x, ag(a))) emit(x);
      }
    }
  // Point-point bisector (great circle) against point-arc bisector (cone).
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) {
      const Vec3 h = normalized(pw(a) - pw(b));
      if (norm2(h) == 0.0) continue;
      // The circle screen is the costly one: asked only when an arc survives its own.
      int circle_state = -1;  // unknown
      for (int c = 0; c < na; ++c) {
        bool arc_skipped = screen.arc(h, ag(c));
        if (!arc_skipped) {
          if (circle_state < 0) circle_state = screen.circle(h) ? 1 : 0;
          arc_skipped = circle_state == 1;
        }
        const Vec3 x = cross(h, cross(pw(a), ag(c)));
        if (arc_skipped && norm(x) >= kCircleCandidateNorm) continue;
        auto filtered = [&](const Vec3& y) {
          if (screen.point_ok(y, pw(a)) && screen.arc_ok(y, ag(c))) emit(y);
        };
        if (!arc_skipped) circle_cone(h, 0.0, pw(a), ag(c), filtered);
        filtered(x);
        filtered(-x);
      }
    }
  // Arc-arc bisector (great circle) against point-arc bisector (cone).
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b) {
      const Vec3 h = normalized(ag(a) - ag(b));
      if (norm2(h) == 0.0) continue;
      const bool skipped = screen.arc_pair(ag(a), ag(b)) || (np > 0 && screen.circle(h));
      for (int c = 0; c < np; ++c) {
        const Vec3 x = cross(h, cross(pw(c), ag(a)));
        if (skipped && norm(x) >= kCircleCandidateNorm) continue;
        auto filtered = [&](const Vec3& y) {
          if (screen.point_ok(y, pw(c)) && screen.arc_ok(y, ag(a))) emit(y);
        };
        if (!skipped) circle_cone(h, 0.0, pw(c), ag(a), filtered);
        filtered(x);
        filtered(-x);
      }
    }
}

// Where a caller's candidates must lie, for the constraint circles' pass:
//   great_circle(h)       whether the great circle {n.h = 0} can hold one;
//   window(h, c0)         the arc of the circle {n.h = c0} (CircleWindow) that can.
// AnyRegion is the whole sphere.
struct AnyRegion {
  bool great_circle(const Vec3&) const { return true; }
  CircleWindow window(const Vec3&, double) const { return {}; }
};

// Candidates on the constraint circles {n.f_i = v_min} of the faces `faces` (fan arc
// indices): with each other, with every bisector of the subset, and the single-site
// extrema along each circle (towards and away from each site's axis). The intersections
// with a great circle (of two faces' circles, or a bisector) are built only where
// `region` says that circle can reach it, those with a point-arc cone only in its window
// of the constraint circle.
template <class Emit, class Region>
void constraint_candidates(const FanGeometry& g, const FanSites& s, const SiteSubset& sub, const int* faces,
                           int n_faces, double v_min, Emit&& emit, const Region& region) {
  const int np = sub.n_points, na = sub.n_arcs;
  auto pw = [&](int a) -> const Vec3& { return s.points[sub.points[a]].w; };
  auto ag = [&](int a) -> const Vec3& { return s.arcs[sub.arcs[a]].g; };
  const double c0 = v_min, sn = std::sqrt(std::max(0.0, 1.0 - c0 * c0));
  for (int ii = 0; ii < n_faces; ++ii) {
    const Vec3& fi = g.face_normals[faces[ii]];
    // Two faces' circles meet on the great circle {n.(f_i - f_j) = 0}.
    for (int jj = ii + 1; jj < n_faces; ++jj) {
      const Vec3& fj = g.face_normals[faces[jj]];
      if (region.great_circle(fi - fj)) plane_plane_sphere(fi, c0, fj, c0, emit);
    }
    for (int a = 0; a < np; ++a)
      for (int b = a + 1; b < np; ++b) {
        const Vec3 h = pw(a) - pw(b);
        if (region.great_circle(h)) plane_plane_sphere(fi, c0, h, 0.0, emit);
      }
    for (int a = 0; a < na; ++a)
      for (int b = a + 1; b < na; ++b) {
        const Vec3 h = ag(a) - ag(b);
        if (region.great_circle(h)) plane_plane_sphere(fi, c0, h, 0.0, emit);
      }
    if (np > 0 && na > 0) {
      const CircleWindow window = region.window(fi, c0);
      for (int a = 0; a < np; ++a)
        for (int b = 0; b < na; ++b) circle_cone(fi, c0, pw(a), ag(b), emit, window);
    }
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

template <class Emit>
void constraint_candidates(const FanGeometry& g, const FanSites& s, const SiteSubset& sub, const int* faces,
                           int n_faces, double v_min, Emit&& emit) {
  constraint_candidates(g, s, sub, faces, n_faces, v_min, emit, AnyRegion{});
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

// The terms a_i + b_i cos t + c_i sin t of n(t).f_i on the plateau circle
// n(t) = c0 h + s (cos t e1 + sin t e2), for the given faces.
inline void circle_terms(const FanGeometry& g, const PlateauCircle& circ, const int* faces, int n_faces,
                         const Vec3& e1, const Vec3& e2, double s, std::vector<double>* ca, std::vector<double>* cb,
                         std::vector<double>* cc) {
  ca->resize(n_faces);
  cb->resize(n_faces);
  cc->resize(n_faces);
  for (int i = 0; i < n_faces; ++i) {
    const Vec3& f = g.face_normals[faces[i]];
    (*ca)[i] = circ.c0 * dot(circ.h, f);
    (*cb)[i] = s * dot(e1, f);
    (*cc)[i] = s * dot(e2, f);
  }
}

// The parametrisation n(t) = c0 h + s (cos t e1 + sin t e2) of a plateau circle, e1 and
// e2 from orthonormal_complement(h); false when the circle is a point (s = 0).
struct CircleFrame {
  Vec3 e1, e2;
  double s;
};
inline bool circle_frame(const PlateauCircle& circ, CircleFrame* f) {
  orthonormal_complement(circ.h, &f->e1, &f->e2);
  f->s = std::sqrt(std::max(0.0, 1.0 - circ.c0 * circ.c0));
  return f->s > 0.0;
}

// The points of a plateau circle where V = min over `faces` of n.f can peak: a single
// term's peak or the equality of two terms. ca, cb, cc are scratch of n_faces entries.
template <class Emit>
void plateau_peaks(const FanGeometry& g, const PlateauCircle& circ, const int* faces, int n_faces,
                   std::vector<double>* ca, std::vector<double>* cb, std::vector<double>* cc, Emit&& emit) {
  CircleFrame frame;
  circle_frame(circ, &frame);  // a point circle (s = 0) gives its one point
  const Vec3 &e1 = frame.e1, &e2 = frame.e2;
  const double s = frame.s;
  // V along the circle is min_i (a_i + b_i cos t + c_i sin t); it peaks at a single
  // term's peak or where two terms are equal.
  circle_terms(g, circ, faces, n_faces, e1, e2, s, ca, cb, cc);
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

// The local maxima of V = min over `faces` of n.f along a plateau circle between the
// parameters t0 <= t1: on n(t) = c0 h + s (cos t e1 + sin t e2), e1 and e2 from
// orthonormal_complement(h), each term is a_i + b_i cos t + c_i sin t, and V, their
// lower envelope, peaks at a peak of the term it follows or where it switches terms. The
// envelope is swept from t0, switching to the first term that crosses below; O(n_faces)
// per switch instead of all O(n_faces^2) pairwise equalities. Both ends are offered.
template <class Emit>
void envelope_peaks_between(const FanGeometry& g, const PlateauCircle& circ, const int* faces, int n_faces,
                            double t0, double t1, std::vector<double>* ca, std::vector<double>* cb,
                            std::vector<double>* cc, Emit&& emit) {
  CircleFrame frame;
  if (n_faces == 0 || !circle_frame(circ, &frame)) return;
  const Vec3 &e1 = frame.e1, &e2 = frame.e2;
  const double s = frame.s;
  circle_terms(g, circ, faces, n_faces, e1, e2, s, ca, cb, cc);
  const double* a = ca->data();
  const double* b = cb->data();
  const double* c = cc->data();
  auto term = [&](int i, double t) { return a[i] + b[i] * std::cos(t) + c[i] * std::sin(t); };
  auto slope = [&](int i, double t) { return -b[i] * std::sin(t) + c[i] * std::cos(t); };
  auto at = [&](double t) { emit(circ.c0 * circ.h + s * (std::cos(t) * e1 + std::sin(t) * e2)); };
  // The term that is lowest at t0 (and lowest just after it on ties).
  int cur = 0;
  for (int i = 1; i < n_faces; ++i) {
    const double d = term(i, t0) - term(cur, t0);
    if (d < 0.0 || (d == 0.0 && slope(i, t0) < slope(cur, t0))) cur = i;
  }
  double t = t0;
  at(t);
  for (int guard = 0; guard < 4 * n_faces + 8; ++guard) {
    // First crossing after t at which another term goes below the current one.
    double next = t1;
    int who = -1;
    for (int j = 0; j < n_faces; ++j) {
      if (j == cur) continue;
      const double A = a[j] - a[cur], B = b[j] - b[cur], C = c[j] - c[cur];
      const double amp = std::hypot(B, C);
      if (!(amp > 0.0) || std::fabs(A) > amp) continue;
      const double phi = std::atan2(C, B), da = std::acos(-A / amp);
      for (double root : {phi + da, phi - da}) {
        // The difference A + amp cos(t - phi) falls through zero where its slope
        // -amp sin(t - phi) < 0.
        if (!(-std::sin(root - phi) < 0.0)) continue;
        double tr = root;
        while (tr <= t) tr += 2.0 * M_PI;
        while (tr - 2.0 * M_PI > t) tr -= 2.0 * M_PI;
        if (tr < next) {
          next = tr;
          who = j;
        }
      }
    }
    // The current term's own peak, if inside the stretch it leads.
    double peak = std::atan2(c[cur], b[cur]);
    while (peak < t) peak += 2.0 * M_PI;
    while (peak - 2.0 * M_PI >= t) peak -= 2.0 * M_PI;
    if (peak <= next) at(peak);
    if (who < 0) break;
    at(next);
    t = next;
    cur = who;
  }
  at(t1);
}

// The same along the part of the circle inside the cap B(centre, cos_radius = cos of its
// radius).
template <class Emit>
void plateau_envelope_peaks(const FanGeometry& g, const PlateauCircle& circ, const int* faces, int n_faces,
                            const Vec3& centre, double cos_radius, std::vector<double>* ca, std::vector<double>* cb,
                            std::vector<double>* cc, Emit&& emit) {
  CircleFrame frame;
  if (n_faces == 0 || !circle_frame(circ, &frame)) return;
  // Window: n(t).centre >= cos_radius, i.e. r cos(t - tc) >= mu.
  const double hc = dot(circ.h, centre), xc = dot(frame.e1, centre), yc = dot(frame.e2, centre);
  const double r = frame.s * std::hypot(xc, yc);
  const double mu = cos_radius - circ.c0 * hc;
  double t0, t1;
  if (!(r > 0.0) || mu <= -r) {
    t0 = 0.0;
    t1 = 2.0 * M_PI;
  } else if (mu > r) {
    return;
  } else {
    const double tc = std::atan2(yc, xc), half = std::acos(mu / r);
    t0 = tc - half;
    t1 = tc + half;
  }
  envelope_peaks_between(g, circ, faces, n_faces, t0, t1, ca, cb, cc, emit);
}

}  // namespace detail
}  // namespace blayer
