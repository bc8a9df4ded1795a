#include "candidate_pool.h"

#include <algorithm>
#include <cmath>

#include "blayer/core/cyclic_index.h"

namespace blayer {
namespace detail {

namespace {

// Margin that keeps the sine/cosine pre-tests of a distance conservative (they reject
// only when the exact arctangent comparison would as well): a few ulps of values <= 1.
constexpr double kCheapTestMargin = 1e-15;

// Arcs whose rounded distance cosine is below the largest one by more than this are not
// compared exactly in evaluate(): the cosines are dot products and norms of unit vectors,
// off by a few ulps, and an angle gap is at least the cosine gap, so such an arc is
// farther than the nearest one by about 1e-12 radians, a thousand times what the exact
// comparison of the arctangent pairs can resolve.
constexpr double kNearestCosineMargin = 1e-12;

}  // namespace

VertexTangents vertex_tangents(const FanGeometry& g, int j, const Vec3& n) {
  const int k = g.n_faces();
  const Vec3& w = g.dirs[j];
  const Vec3& prev = g.dirs[cyclic_previous(j, k)];
  const Vec3& next = g.dirs[cyclic_next(j, k)];
  VertexTangents t;
  t.t_in = prev - dot(prev, w) * w;
  t.t_out = next - dot(next, w) * w;
  t.t_n = n - dot(n, w) * w;
  t.left = cross(w, t.t_out);
  return t;
}

bool fluid_side_at_vertex(const FanGeometry& g, int j, const Vec3& n) {
  const VertexTangents t = vertex_tangents(g, j, n);  // not a structured binding: the lambda captures it
  auto beta = [&](const Vec3& x) {
    const double b = std::atan2(dot(t.left, x), dot(t.t_out, x));
    return b < 0.0 ? b + 2.0 * M_PI : b;
  };
  return beta(t.t_n) < beta(t.t_in);
}

CandidatePool::CandidatePool(const FanGeometry& g, const Tolerances& tol, bool constrained, double v_min)
    : g_(g), tol_(tol), constrained_(constrained), v_min_(v_min) {
  arc_tests_.resize(g.n_faces());
}

bool CandidatePool::evaluate(const Vec3& n, double thr, double* d_out, bool* fluid) const {
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
      at.cosd = std::max(dot(n, u), dot(n, v));
      if (at.cosd > cos_thr_) {
        last_reject_ = i;
        return false;
      }
    }
  }
  // Pass 2: exact distances for the survivors of pass 1. Every arc's distance is an
  // angle atan2(y, x) with y >= 0, so the nearest arc is found by comparing the pairs
  // (sign of y1 x2 - x1 y2, exact to rounding for angles in [0, pi] except 0 against
  // pi, where it vanishes) and only its angle needs an arctangent; ties keep the first
  // arc, and an arc's start before its end. Only the arcs whose rounded cosine is within
  // kNearestCosineMargin of the largest can be the nearest: the others are left out of
  // the comparison (its cross products and square roots), which then picks the same arc.
  double cos_max = -2.0;
  for (int i = 0; i < k; ++i) {
    ArcTest& at = arc_tests_[i];
    if (at.kind == ArcTest::kPole) {
      at.cosd = 0.0;
    } else if (at.kind == ArcTest::kInterior) {
      at.cosd = std::sqrt(at.mm2);
    }
    cos_max = std::max(cos_max, at.cosd);
  }
  const double cos_near = cos_max - kNearestCosineMargin;
  auto nearer = [](double y1, double x1, double y2, double x2) {
    const double c = y1 * x2 - x1 * y2;
    return c < 0.0 || (c == 0.0 && y1 == 0.0 && y2 == 0.0 && x1 > x2);
  };
  double best_y = 0.0, best_x = 0.0;
  int feature_arc = -1;
  int feature_kind = 0;  // 0: arc interior or pole, 1: arc start, 2: arc end
  for (int i = 0; i < k; ++i) {
    const ArcTest& at = arc_tests_[i];
    if (at.cosd < cos_near) continue;
    double y, x;
    int kind = 0;
    if (at.kind == ArcTest::kPole) {
      y = 1.0;
      x = 0.0;
    } else if (at.kind == ArcTest::kInterior) {
      y = std::fabs(at.nf);
      x = at.cosd;
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
  *fluid = fluid_side_at_vertex(g_, feature_kind == 1 ? feature_arc : cyclic_next(feature_arc, k), n);
  return true;
}

void CandidatePool::add_maximizer(const Vec3& n, double d, double v) {
  if (d > best_c_) {
    best_c_ = d;
    maxima_.erase(std::remove_if(maxima_.begin(), maxima_.end(),
                                 [&](const Maximizer& m) { return m.d < best_c_ - tol_.normality_tie; }),
                  maxima_.end());
  }
  maxima_.push_back({n, d, v});
}

void CandidatePool::consider(Vec3 n) {
  const double len = norm(n);
  if (!(len > 0.0) || !std::isfinite(len)) return;
  n = n / len;
  ++n_candidates_;
  // The distance test runs first, against the lower of the two thresholds (best_c_ <=
  // best_u_), since it rejects most candidates; V is needed only for the survivors. A
  // candidate it passes has its exact D, then meets the threshold of its feasibility.
  // In the constrained pass an infeasible candidate is dropped whatever its D, so V
  // (one dot product per face) comes first there: most candidates on the constraint
  // circles of nearly parallel faces lie below another face's circle.
  auto feasible_at = [&](double v) { return !constrained_ || v >= v_min_ - kConstraintSlack; };
  double v = 0.0;
  if (constrained_pass_) {
    v = fan_visibility(g_, n);
    if (!feasible_at(v)) return;
  }
  double d;
  bool fluid;
  if (!evaluate(n, threshold(), &d, &fluid) || !fluid) return;
  if (!constrained_pass_) v = fan_visibility(g_, n);
  const bool feasible = feasible_at(v);
  if (!feasible && d < unconstrained_threshold()) return;
  if (d > best_u_) {
    best_u_ = d;
    maxima_u_.erase(std::remove_if(maxima_u_.begin(), maxima_u_.end(),
                                   [&](const Maximizer& m) { return m.d < best_u_ - tol_.normality_tie; }),
                    maxima_u_.end());
  }
  if (d >= best_u_ - tol_.normality_tie) maxima_u_.push_back({n, d, v});
  if (feasible) add_maximizer(n, d, v);
}

bool CandidatePool::distinct(const std::vector<Maximizer>& maxima) {
  // Against the first one: a pair farther than the limit settles it, and when all lie
  // within half of it (less the angles' rounding) no pair can exceed it. Symmetric fans
  // gather thousands of maximisers at one point, where the pairwise loop would not end.
  bool near_all = true;
  for (std::size_t b = 1; b < maxima.size(); ++b) {
    const double a0b = angle_between(maxima[0].n, maxima[b].n);
    if (a0b > kDistinctMaximizers) return true;
    near_all = near_all && a0b <= 0.5 * kDistinctMaximizers - kHalfLimitRounding;
  }
  if (near_all) return false;
  for (std::size_t a = 0; a < maxima.size(); ++a)
    for (std::size_t b = a + 1; b < maxima.size(); ++b)
      if (angle_between(maxima[a].n, maxima[b].n) > kDistinctMaximizers) return true;
  return false;
}

MostNormalResult CandidatePool::pick(bool non_unique) const {
  const Maximizer* best = &maxima_.front();
  for (const Maximizer& m : maxima_)
    if (m.d >= best_c_ - tol_.normality_tie && m.v > best->v) best = &m;
  MostNormalResult r;
  r.normal = best->n;
  r.normality = best->d;
  r.visibility = best->v;
  r.status = limited() ? NormalStatus::kVisibilityConstrained
                       : (non_unique ? NormalStatus::kNonUnique : NormalStatus::kOk);
  r.n_candidates = n_candidates_;
  return r;
}

}  // namespace detail
}  // namespace blayer
