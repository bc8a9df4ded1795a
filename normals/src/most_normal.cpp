#include "blayer/normals/most_normal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "blayer/normals/most_visible.h"
#include "blayer/normals/weighted_normal.h"
#include "sphere_solvers.h"

namespace blayer {

namespace {

// Maximisers farther apart than this (radians) are distinct optima, i.e. a plateau or
// a discrete tie. Candidates for one point computed from different site triples agree
// to ~1e-12; an off-plateau optimum moves by O(eps) under an eps perturbation, so 1e-6
// separates real ties from rounding with a wide margin on both sides.
constexpr double kDistinctMaximizers = 1e-6;

// Slack on V >= V_min for candidates constructed on a constraint circle n.f_i = V_min:
// their computed V carries ~1e-16 rounding, 1e-12 accepts them without admitting any
// meaningfully invisible direction.
constexpr double kConstraintSlack = 1e-12;

// Margin that keeps the sine/cosine pre-tests of a distance conservative (they reject
// only when the exact arctangent comparison would as well): a few ulps of values <= 1.
constexpr double kCheapTestMargin = 1e-15;

// Level above the rejection bound at which the great-circle screen
// (Solver::circle_rejected) requires a link vertex, and the rounding allowance of its
// computed boundary points: the candidates it discards lie within ~1e-15 of the circle,
// so each is still beyond the bound by ~1e-12, and a boundary point it computes is
// within 1e-15 of the exact one, well inside 1e-14.
constexpr double kCircleLevel = 1e-12;
constexpr double kCircleRounding = 1e-14;

// Smallest |x| of a candidate x = h x (w x f) discarded with its circle: its direction,
// after normalisation, is within 1e-16 / 1e-3 = 1e-13 of the circle, inside kCircleLevel.
constexpr double kCircleCandidateNorm = 1e-3;

// Slowest fall-off rate (radians of D per radian of motion) of the link-vertex bound
// around its maximiser for which the bound shortcut is taken beyond convex corners:
// directions within normality_tie of the optimum then lie within 1e-9 / 1e-2 = 1e-7 rad
// of it, an order inside kDistinctMaximizers, so the enumeration could not find a
// distinct near-tie there either.
constexpr double kSharpFalloff = 1e-2;

// Link vertices whose angle to the cap antipode is within this of the bound count as
// holding the cap; including extra ones only lowers the bound, which stays valid.
constexpr double kCapSupportSlack = 1e-10;

// Slowest rate at which g(n) = min_j angle(n, u_j) falls off around n0 = -cap.normal,
// its maximiser. Near n0 g is the minimum of the concave angles to the vertices u_j at
// the bound (all beyond pi/2), so it lies below its tangent cone, whose slowest slope is
// cos(phi/2) for the widest angular gap phi between the projected u_j at n0 (0 when a
// gap reaches pi: flat to first order).
double cap_falloff(const FanGeometry& g, const MostVisibleResult& cap) {
  const Vec3 n0 = -cap.normal;
  Vec3 e1, e2;
  detail::orthonormal_complement(n0, &e1, &e2);
  constexpr int kMaxSupport = 16;
  double az[kMaxSupport];
  int m = 0;
  for (const Vec3& u : g.dirs)
    if (dot(cap.normal, u) <= cap.visibility + kCapSupportSlack) {
      if (m == kMaxSupport) return 0.0;
      az[m++] = std::atan2(dot(u, e2), dot(u, e1));
    }
  if (m < 3) return 0.0;
  std::sort(az, az + m);
  double widest = az[0] + 2.0 * M_PI - az[m - 1];
  for (int i = 1; i < m; ++i) widest = std::max(widest, az[i] - az[i - 1]);
  return widest >= M_PI ? 0.0 : std::cos(0.5 * widest);
}

struct Arc {
  Vec3 u, v, g;
};

// Per-arc result of the cheap pass of Solver::evaluate, reused by its exact pass.
struct ArcTest {
  enum Kind : char { kPole, kInterior, kEnds };
  double nf;  // n.f
  double mm2;  // |n - (n.f) f|^2
  Kind kind;
};

struct Maximizer {
  Vec3 n;
  double d;
  double v;
};

class Solver {
 public:
  Solver(const FanGeometry& g, const Tolerances& tol, bool shortcuts) : g_(g), tol_(tol), shortcuts_(shortcuts) {}

  MostNormalResult run(bool constrain_visibility);

 private:
  // Distance to the link with early exit below thr; sets *fluid from the nearest feature.
  bool evaluate(const Vec3& n, double thr, double* d_out, bool* fluid) const;
  void consider(Vec3 n);
  bool circle_rejected(const Vec3& h) const;
  bool build_sites();
  void enumerate_unconstrained();
  void enumerate_constrained();
  void search_plateaus();
  void add_maximizer(const Vec3& n, double d, double v);
  static bool distinct(const std::vector<Maximizer>& maxima);

  const FanGeometry& g_;
  const Tolerances& tol_;
  const bool shortcuts_;
  std::vector<Arc> arcs_;
  std::vector<Vec3> pts_;
  double v_min_ = 0.0;
  bool constrained_ = false;
  bool constrained_pass_ = false;
  double best_c_ = -std::numeric_limits<double>::infinity();
  double best_u_ = -std::numeric_limits<double>::infinity();
  std::vector<Maximizer> maxima_;    // D >= best_c_ - tie among V >= V_min
  std::vector<Maximizer> maxima_u_;  // D >= best_u_ - tie, any V
  int n_candidates_ = 0;
  // Scratch of evaluate(): per-arc tests, the cached pre-test bounds of the last
  // threshold, and the arc that rejected the last candidate.
  mutable std::vector<ArcTest> arc_tests_;
  mutable double thr_key_ = std::numeric_limits<double>::quiet_NaN();
  mutable double cos_thr_ = 2.0;
  mutable double sin_thr_ = -1.0;
  mutable int last_reject_ = 0;
};

bool Solver::evaluate(const Vec3& n, double thr, double* d_out, bool* fluid) const {
  const int k = g_.n_faces();
  if (thr != thr_key_) {
    // The pre-test bounds change only with the running best, far less often than
    // candidates arrive: recomputing them per call cost two libm calls per candidate.
    thr_key_ = thr;
    cos_thr_ = thr > 0.0 ? std::cos(thr) + kCheapTestMargin : 2.0;
    sin_thr_ = thr > 0.0 ? std::sin(std::min(thr, 0.5 * M_PI)) - kCheapTestMargin : -1.0;
  }
  // Pass 1: the feature class of every arc and the cheap sine/cosine rejections, with no
  // arctangent. Starting at the arc that rejected the previous candidate finds a
  // rejecting arc at once for most of them (consecutive candidates are near each other).
  // The outcome does not depend on the order: a candidate is rejected iff some arc is
  // closer than thr, and otherwise pass 2 computes D exactly, in arc order.
  for (int c = 0; c < k; ++c) {
    int i = last_reject_ + c;
    if (i >= k) i -= k;
    const Vec3& f = g_.face_normals[i];
    const Vec3& u = g_.arc_start(i);
    const Vec3& v = g_.arc_end(i);
    ArcTest& at = arc_tests_[i];
    at.nf = dot(n, f);
    const Vec3 m = n - at.nf * f;
    // |m| only in pass 2: its square root waits until an arctangent needs it.
    at.mm2 = norm2(m);
    if (at.mm2 == 0.0) {
      at.kind = ArcTest::kPole;
    } else if (dot(cross(u, m), f) >= 0.0 && dot(cross(m, v), f) >= 0.0) {
      // Foot inside the arc: d = atan2(|n.f|, |m|) <= pi/2, increasing in |n.f|.
      at.kind = ArcTest::kInterior;
      if (thr > 0.5 * M_PI || std::fabs(at.nf) < sin_thr_) {
        last_reject_ = i;
        return false;
      }
    } else {
      // Nearest point an end: d = min angle to u, v, decreasing in the cosines.
      at.kind = ArcTest::kEnds;
      if (std::max(dot(n, u), dot(n, v)) > cos_thr_) {
        last_reject_ = i;
        return false;
      }
    }
  }
  // Pass 2: exact distances for the survivors of pass 1. Every arc's distance is an
  // angle atan2(y, x) with y >= 0, so the nearest arc is found by comparing the pairs
  // (sign of y1 x2 - x1 y2, exact to rounding for angles in [0, pi] except 0 against
  // pi, where it vanishes) and only its angle needs an arctangent; ties keep the first
  // arc, and an arc's start before its end.
  auto nearer = [](double y1, double x1, double y2, double x2) {
    const double c = y1 * x2 - x1 * y2;
    return c < 0.0 || (c == 0.0 && y1 == 0.0 && y2 == 0.0 && x1 > x2);
  };
  double best_y = 0.0, best_x = 0.0;
  int feature_arc = -1;
  int feature_kind = 0;  // 0: arc interior or pole, 1: arc start, 2: arc end
  for (int i = 0; i < k; ++i) {
    const ArcTest& at = arc_tests_[i];
    double y, x;
    int kind = 0;
    if (at.kind == ArcTest::kPole) {
      y = 1.0;
      x = 0.0;
    } else if (at.kind == ArcTest::kInterior) {
      y = std::fabs(at.nf);
      x = std::sqrt(at.mm2);
    } else {
      const Vec3& u = g_.arc_start(i);
      const Vec3& v = g_.arc_end(i);
      const double yu = norm(cross(n, u)), xu = dot(n, u);
      const double yv = norm(cross(n, v)), xv = dot(n, v);
      if (nearer(yv, xv, yu, xu)) {
        y = yv;
        x = xv;
        kind = 2;
      } else {
        y = yu;
        x = xu;
        kind = 1;
      }
    }
    if (feature_arc < 0 || nearer(y, x, best_y, best_x)) {
      best_y = y;
      best_x = x;
      feature_arc = i;
      feature_kind = kind;
    }
  }
  // A pole's pair (1, 0) gives atan2 = pi/2 as rounded, the same as 0.5 * M_PI.
  const double best = std::atan2(best_y, best_x);
  if (best < thr) {
    last_reject_ = feature_arc;
    return false;
  }
  *d_out = best;
  if (feature_kind == 0) {
    *fluid = dot(n, g_.face_normals[feature_arc]) > 0.0;
    return true;
  }
  // Link vertex j joins arc j-1 (incoming) and arc j (outgoing).
  const int j = feature_kind == 1 ? feature_arc : (feature_arc + 1) % k;
  const Vec3& w = g_.dirs[j];
  const Vec3& prev = g_.dirs[(j + k - 1) % k];
  const Vec3& next = g_.dirs[(j + 1) % k];
  const Vec3 t_in = prev - dot(prev, w) * w;
  const Vec3 t_out = next - dot(next, w) * w;
  const Vec3 t_n = n - dot(n, w) * w;
  const Vec3 left = cross(w, t_out);
  auto beta = [&](const Vec3& x) {
    const double b = std::atan2(dot(left, x), dot(t_out, x));
    return b < 0.0 ? b + 2.0 * M_PI : b;
  };
  *fluid = beta(t_n) < beta(t_in);
  return true;
}

// Whether every candidate on the great circle {n.h = 0} (h unit) would be rejected by
// consider() at the current threshold thr, so that a whole family of candidates on that
// bisector need not be built. Proof: u_j is a link point, so D(n) <= angle(n, u_j), and
// n.u_j > cos(thr) + kCheapTestMargin makes the computed D(n) < thr (the arc ending at
// u_j is at most angle(n, u_j) away; the margin covers rounding; see evaluate()). The
// threshold only rises during the enumeration, so a candidate rejected now is rejected
// when its turn comes. The sets G_j = {n on the circle : n.u_j > lambda}, lambda =
// cos(thr) + kCheapTestMargin + kCircleLevel, are open arcs; if they do not cover the
// circle, some component of the uncovered part has a boundary point p on the boundary of
// one G_j with p.u_i <= lambda for all i, which is found below (its computed image is
// within rounding of p, so the test at lambda + kCircleRounding sees it uncovered). When
// no such point is found, every n on the circle has n.u_j > lambda for some j, and every
// candidate within 1e-13 of the circle has n.u_j > cos(thr) + kCheapTestMargin.
bool Solver::circle_rejected(const Vec3& h) const {
  const double thr = best_c_ - tol_.normality_tie;
  if (!(thr > 0.0)) return false;
  const double lambda = std::cos(thr) + kCheapTestMargin + kCircleLevel;
  Vec3 e1, e2;
  detail::orthonormal_complement(h, &e1, &e2);
  const int k = static_cast<int>(g_.dirs.size());
  constexpr int kMaxVertices = 64;
  if (k > kMaxVertices) return false;
  double a[kMaxVertices], b[kMaxVertices];
  for (int j = 0; j < k; ++j) {
    a[j] = dot(g_.dirs[j], e1);
    b[j] = dot(g_.dirs[j], e2);
  }
  bool any_arc = false;
  for (int j = 0; j < k; ++j) {
    const double r2 = a[j] * a[j] + b[j] * b[j];
    // G_j empty (r <= lambda) or the whole circle (r < -lambda, lambda < 0).
    if (lambda >= 0.0 && r2 <= lambda * lambda) continue;
    if (lambda < 0.0 && r2 < lambda * lambda) return true;
    any_arc = true;
    // Boundary points: (x, y) with a x + b y = lambda on the unit circle.
    const double q = std::sqrt(std::max(0.0, r2 - lambda * lambda));
    for (double sign : {1.0, -1.0}) {
      const double x = (lambda * a[j] - sign * q * b[j]) / r2;
      const double y = (lambda * b[j] + sign * q * a[j]) / r2;
      bool covered = false;
      for (int i = 0; i < k && !covered; ++i) covered = a[i] * x + b[i] * y > lambda + kCircleRounding;
      if (!covered) return false;
    }
  }
  return any_arc;
}

void Solver::add_maximizer(const Vec3& n, double d, double v) {
  if (d > best_c_) {
    best_c_ = d;
    maxima_.erase(std::remove_if(maxima_.begin(), maxima_.end(),
                                 [&](const Maximizer& m) { return m.d < best_c_ - tol_.normality_tie; }),
                  maxima_.end());
  }
  maxima_.push_back({n, d, v});
}

void Solver::consider(Vec3 n) {
  const double len = norm(n);
  if (!(len > 0.0) || !std::isfinite(len)) return;
  n = n / len;
  ++n_candidates_;
  // The distance test runs first, against the lower of the two thresholds (best_c_ <=
  // best_u_), since it rejects most candidates; V is needed only for the survivors. A
  // candidate it passes has its exact D, then meets the threshold of its feasibility.
  double d;
  bool fluid;
  if (!evaluate(n, best_c_ - tol_.normality_tie, &d, &fluid) || !fluid) return;
  const double v = fan_visibility(g_, n);
  const bool feasible = !constrained_ || v >= v_min_ - kConstraintSlack;
  if (constrained_pass_ && !feasible) return;
  if (!feasible && d < best_u_ - tol_.normality_tie) return;
  if (d > best_u_) {
    best_u_ = d;
    maxima_u_.erase(std::remove_if(maxima_u_.begin(), maxima_u_.end(),
                                   [&](const Maximizer& m) { return m.d < best_u_ - tol_.normality_tie; }),
                    maxima_u_.end());
  }
  if (d >= best_u_ - tol_.normality_tie) maxima_u_.push_back({n, d, v});
  if (feasible) add_maximizer(n, d, v);
}

bool Solver::build_sites() {
  const int k = g_.n_faces();
  // Junction j: between arc j-1 and arc j at dirs[j].
  std::vector<char> straight(k), reflex(k);
  for (int j = 0; j < k; ++j) {
    const int a = (j + k - 1) % k;
    const double side = dot(g_.face_normals[a], g_.dirs[(j + 1) % k]);
    straight[j] = std::fabs(side) <= tol_.coplanar_arc && dot(g_.face_normals[a], g_.face_normals[j]) > 0.0;
    reflex[j] = !straight[j] && side < 0.0;
    if (reflex[j]) pts_.push_back(g_.dirs[j]);
  }
  int start = 0;
  while (start < k && straight[start]) ++start;
  if (start == k) start = 0;
  for (int c = 0; c < k;) {
    const int i0 = (start + c) % k;
    double length = g_.angles[i0];
    int len = 1;
    while (c + len < k) {
      const int j = (start + c + len) % k;
      if (!straight[j] || length + g_.angles[j] >= M_PI) break;
      length += g_.angles[j];
      ++len;
    }
    arcs_.push_back({g_.dirs[i0], g_.dirs[(i0 + len) % k], g_.face_normals[i0]});
    c += len;
  }
  bool all_reflex = true;
  for (int j = 0; j < k; ++j) all_reflex &= straight[j] || reflex[j];
  return all_reflex;
}

void Solver::enumerate_unconstrained() {
  const int np = static_cast<int>(pts_.size()), na = static_cast<int>(arcs_.size());
  for (const Vec3& w : pts_) consider(-w);
  for (const Arc& a : arcs_) consider(a.g);
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) consider(-(pts_[a] + pts_[b]));
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b) consider(arcs_[a].g + arcs_[b].g);
  // Point-arc parabola extrema: where it crosses the plane of w and f, at the angles
  // tf/2 +- pi/4 (and their antipodes) from w, tf = angle(w, f). For unit w and f,
  // p = w + f and q = f - w are orthogonal, at angles tf/2 and tf/2 + pi/2, so those
  // directions are p/|p| +- q/|q|, scaled here by |p| |q| (consider() normalises):
  // no angle round trip. Each of p, q is as well conditioned as the in-plane axis
  // f - (w.f) w, and both vanish only when f = +-w.
  for (const Vec3& w : pts_)
    for (const Arc& arc : arcs_) {
      const Vec3 p = w + arc.g, q = arc.g - w;
      const double lp = norm(p), lq = norm(q);
      if (lp == 0.0 || lq == 0.0) continue;
      const Vec3 a = lq * p + lp * q, b = lq * p - lp * q;
      consider(a);
      consider(-a);
      consider(b);
      consider(-b);
    }
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b)
      for (int c = b + 1; c < np; ++c) {
        const Vec3 h = cross(pts_[a] - pts_[b], pts_[b] - pts_[c]);
        consider(h);
        consider(-h);
      }
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b)
      for (int c = b + 1; c < na; ++c) {
        const Vec3 h = cross(arcs_[a].g - arcs_[b].g, arcs_[b].g - arcs_[c].g);
        consider(h);
        consider(-h);
      }
  auto emit = [this](const Vec3& n) { consider(n); };
  // Point-point bisector (great circle) against point-arc bisector (cone). Both families
  // below lie on one bisector circle per pair; a circle the link vertices screen off
  // entirely (circle_rejected) is skipped, except candidates x too short to have a
  // reliable direction, which are evaluated as before.
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b) {
      const Vec3 h = normalized(pts_[a] - pts_[b]);
      if (norm2(h) == 0.0) continue;
      const bool rejected = shortcuts_ && circle_rejected(h);
      for (const Arc& arc : arcs_) {
        const Vec3 x = cross(h, cross(pts_[a], arc.g));
        if (rejected && norm(x) >= kCircleCandidateNorm) continue;
        if (!rejected) detail::circle_cone(h, 0.0, pts_[a], arc.g, emit);
        consider(x);
        consider(-x);
      }
    }
  // Arc-arc bisector (great circle) against point-arc bisector (cone).
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b) {
      const Vec3 h = normalized(arcs_[a].g - arcs_[b].g);
      if (norm2(h) == 0.0) continue;
      const bool rejected = shortcuts_ && circle_rejected(h);
      for (const Vec3& w : pts_) {
        const Vec3 x = cross(h, cross(w, arcs_[a].g));
        if (rejected && norm(x) >= kCircleCandidateNorm) continue;
        if (!rejected) detail::circle_cone(h, 0.0, w, arcs_[a].g, emit);
        consider(x);
        consider(-x);
      }
    }
}

void Solver::enumerate_constrained() {
  constrained_pass_ = true;
  const int k = g_.n_faces();
  const int np = static_cast<int>(pts_.size()), na = static_cast<int>(arcs_.size());
  const double c0 = v_min_, s = std::sqrt(std::max(0.0, 1.0 - c0 * c0));
  auto emit = [this](const Vec3& n) { consider(n); };
  for (int i = 0; i < k; ++i) {
    const Vec3& fi = g_.face_normals[i];
    for (int j = i + 1; j < k; ++j) detail::plane_plane_sphere(fi, c0, g_.face_normals[j], c0, emit);
    for (int a = 0; a < np; ++a)
      for (int b = a + 1; b < np; ++b) detail::plane_plane_sphere(fi, c0, pts_[a] - pts_[b], 0.0, emit);
    for (int a = 0; a < na; ++a)
      for (int b = a + 1; b < na; ++b)
        detail::plane_plane_sphere(fi, c0, arcs_[a].g - arcs_[b].g, 0.0, emit);
    for (const Vec3& w : pts_)
      for (const Arc& arc : arcs_) detail::circle_cone(fi, c0, w, arc.g, emit);
    // Single-site extrema along the circle: towards and away from each site's axis.
    auto along = [&](const Vec3& axis) {
      const Vec3 t = normalized(axis - dot(axis, fi) * fi);
      if (norm2(t) == 0.0) return;
      consider(c0 * fi + s * t);
      consider(c0 * fi - s * t);
    };
    for (const Vec3& w : pts_) along(w);
    for (const Arc& arc : arcs_) along(arc.g);
  }
}

void Solver::search_plateaus() {
  struct Circle {
    Vec3 h;
    double c0;
  };
  std::vector<Circle> circles;
  const double tie = tol_.normality_tie;
  const int np = static_cast<int>(pts_.size()), na = static_cast<int>(arcs_.size());
  // Concentric sites: within the tie tolerance the distance along their common circle is
  // constant to within the tie band, so every point found there is a genuine maximiser.
  for (int a = 0; a < np; ++a)
    for (int b = a + 1; b < np; ++b)
      if (norm(pts_[a] + pts_[b]) <= tie) circles.push_back({pts_[a], 0.0});
  for (const Vec3& w : pts_)
    for (const Arc& arc : arcs_)
      if (norm(w - arc.g) <= tie || norm(w + arc.g) <= tie) circles.push_back({w, std::sqrt(0.5)});
  for (int a = 0; a < na; ++a)
    for (int b = a + 1; b < na; ++b)
      if (norm(arcs_[a].g - arcs_[b].g) <= tie || norm(arcs_[a].g + arcs_[b].g) <= tie) {
        circles.push_back({arcs_[a].g, std::sin(best_c_)});
        circles.push_back({arcs_[a].g, -std::sin(best_c_)});
      }
  const int k = g_.n_faces();
  std::vector<double> ca(k), cb(k), cc(k);
  for (const Circle& circ : circles) {
    Vec3 e1, e2;
    detail::orthonormal_complement(circ.h, &e1, &e2);
    const double s = std::sqrt(std::max(0.0, 1.0 - circ.c0 * circ.c0));
    // V along the circle is min_i (a_i + b_i cos t + c_i sin t); it peaks at a single
    // term's peak or where two terms are equal.
    for (int i = 0; i < k; ++i) {
      const Vec3& f = g_.face_normals[i];
      ca[i] = circ.c0 * dot(circ.h, f);
      cb[i] = s * dot(e1, f);
      cc[i] = s * dot(e2, f);
    }
    auto at = [&](double t) { consider(circ.c0 * circ.h + s * (std::cos(t) * e1 + std::sin(t) * e2)); };
    for (int i = 0; i < k; ++i) {
      at(std::atan2(cc[i], cb[i]));
      for (int j = i + 1; j < k; ++j) {
        const double p = cb[i] - cb[j], q = cc[i] - cc[j], r = ca[j] - ca[i];
        const double amp = std::hypot(p, q);
        if (!(amp > 0.0) || std::fabs(r) > amp) continue;
        const double phi = std::atan2(q, p), da = std::acos(r / amp);
        at(phi + da);
        at(phi - da);
      }
    }
  }
}

bool Solver::distinct(const std::vector<Maximizer>& maxima) {
  for (std::size_t a = 0; a < maxima.size(); ++a)
    for (std::size_t b = a + 1; b < maxima.size(); ++b)
      if (angle_between(maxima[a].n, maxima[b].n) > kDistinctMaximizers) return true;
  return false;
}

MostNormalResult Solver::run(bool constrain_visibility) {
  MostNormalResult r;
  const int k = g_.n_faces();
  const MostVisibleResult mv = most_visible_normal(g_.face_normals.data(), k, tol_);
  if (!mv.feasible) {
    r.normal = mv.normal;
    r.visibility = mv.visibility;
    r.normality = fan_normality(g_, mv.normal);
    r.status = NormalStatus::kNoVisibleDirection;
    return r;
  }
  // Winding number of the link around n_MV: every triangle is seen from n_MV, so the
  // projected link turns monotonically; one turn means a simple link.
  double turn = 0.0;
  for (int i = 0; i < k; ++i) {
    const Vec3& a = g_.arc_start(i);
    const Vec3& b = g_.arc_end(i);
    turn += std::atan2(dot(mv.normal, cross(a, b)), dot(a, b) - dot(mv.normal, a) * dot(mv.normal, b));
  }
  if (std::lround(turn / (2.0 * M_PI)) != 1) {
    r.normal = weighted_average_normal(g_, NormalMethod::kAngle);
    r.visibility = fan_visibility(g_, r.normal);
    r.normality = fan_normality(g_, r.normal);
    r.status = NormalStatus::kDegenerateFan;
    return r;
  }
  constrained_ = constrain_visibility;
  v_min_ = 0.5 * mv.visibility;
  arc_tests_.resize(k);
  const bool all_reflex = build_sites();
  consider(mv.normal);
  if (!pts_.empty() && shortcuts_) {
    // Every link vertex lies on the link, so D(n) <= min_j angle(n, u_j) for every n,
    // and the right side is largest, at `target`, at the antipode of the smallest cap
    // holding the link vertices. A fluid, feasible direction reaching the bound is
    // optimal. This holds for any link; it is reached at convex solid corners (all
    // junctions reflex) and whenever D* > pi/2, where the antipode sees every link
    // vertex at more than 90 degrees, so no arc interior is nearer than its ends.
    const MostVisibleResult cap = most_visible_normal(g_.dirs.data(), k, tol_);
    if (cap.feasible) {
      const double target = M_PI - std::atan2(std::sqrt(std::max(0.0, 1.0 - cap.visibility * cap.visibility)),
                                              cap.visibility);
      consider(-cap.normal);
      // Beyond convex corners the bound is used only where D falls off steeply around
      // the optimum, so that no distinct direction comes within the tie band. Where it
      // is flat (two link vertices hold the cap: second order along their bisector) the
      // enumeration may find distinct near-ties and break them by V.
      const bool sharp = all_reflex || cap_falloff(g_, cap) >= kSharpFalloff;
      if (sharp && best_c_ >= target - tol_.normality_tie && best_u_ <= best_c_ + tol_.normality_tie &&
          !maxima_.empty()) {
        const Maximizer& m = maxima_.back();
        r.normal = m.n;
        r.normality = m.d;
        r.visibility = m.v;
        r.status = NormalStatus::kOk;
        r.n_candidates = n_candidates_;
        return r;
      }
    }
  }
  if (!pts_.empty()) enumerate_unconstrained();
  // Plateaus first: their feasible part may reach the unconstrained optimum.
  bool non_unique = distinct(maxima_u_) || distinct(maxima_);
  if (non_unique) search_plateaus();
  if (constrained_ && best_u_ > best_c_ + tol_.normality_tie) enumerate_constrained();
  const bool limited = constrained_ && best_u_ > best_c_ + tol_.normality_tie;
  non_unique = non_unique || distinct(maxima_);
  if (maxima_.empty()) {
    r.normal = mv.normal;
    r.visibility = mv.visibility;
    r.normality = fan_normality(g_, mv.normal);
    r.status = NormalStatus::kDegenerateFan;
    return r;
  }
  const Maximizer* pick = &maxima_.front();
  for (const Maximizer& m : maxima_)
    if (m.d >= best_c_ - tol_.normality_tie && m.v > pick->v) pick = &m;
  r.normal = pick->n;
  r.normality = pick->d;
  r.visibility = pick->v;
  r.status = limited ? NormalStatus::kVisibilityConstrained
                     : (non_unique ? NormalStatus::kNonUnique : NormalStatus::kOk);
  r.n_candidates = n_candidates_;
  return r;
}

}  // namespace

MostNormalResult most_normal_normal(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility) {
  Solver solver(g, tol, true);
  return solver.run(constrain_visibility);
}

MostNormalResult most_normal_by_enumeration(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility) {
  Solver solver(g, tol, false);
  return solver.run(constrain_visibility);
}

}  // namespace blayer
