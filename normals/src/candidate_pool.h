// The candidate bookkeeping every most-normal solver shares: the exact evaluation of D
// and of the fluid side at a direction, the running optima with and without the
// visibility constraint, the sets of maximisers within the tie tolerance, and the final
// tie-break (docs/normals.md, Part 4). Solvers differ only in which candidates they
// offer. Internal to blayer_normals.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "blayer/core/tolerances.h"
#include "blayer/core/vec3.h"
#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/most_normal.h"
#include "recycled_vector.h"

namespace blayer {
namespace detail {

// Maximisers farther apart than this (radians) are distinct optima, i.e. a plateau or
// a discrete tie. Candidates for one point computed from different site triples agree
// to ~1e-12; an off-plateau optimum moves by O(eps) under an eps perturbation, so 1e-6
// separates real ties from rounding with a wide margin on both sides.
constexpr double kDistinctMaximizers = 1e-6;

// Rounding allowance of the angles compared by the distinctness test's triangle
// inequality (angle_between is accurate to a few ulps of pi).
constexpr double kHalfLimitRounding = 1e-14;

// Slack on V >= V_min for candidates constructed on a constraint circle n.f_i = V_min:
// their computed V carries ~1e-16 rounding, 1e-12 accepts them without admitting any
// meaningfully invisible direction.
constexpr double kConstraintSlack = 1e-12;

// Whether unit n, whose nearest link feature is link vertex j (joining arc j-1, incoming,
// and arc j, outgoing), lies on the fluid side: the tangent towards n at u_j must fall
// in the fluid wedge, left of the turn from the outgoing arc to the incoming one.
bool fluid_side_at_vertex(const FanGeometry& g, int j, const Vec3& n);

// The tangents at link vertex u_j (= g.dirs[j]) that the fluid-side tests compare: the
// incoming arc's (towards u_j-1), the outgoing arc's (towards u_j+1), n's, and `left`,
// the outgoing tangent turned a quarter counter-clockwise about u_j.
struct VertexTangents {
  Vec3 t_in, t_out, t_n, left;
};
VertexTangents vertex_tangents(const FanGeometry& g, int j, const Vec3& n);

struct Maximizer {
  Vec3 n;
  double d;
  double v;
};

class CandidatePool {
 public:
  // The visibility constraint V >= v_min applies when `constrained`.
  CandidatePool(const FanGeometry& g, const Tolerances& tol, bool constrained, double v_min);

  // Offers direction n (any length; zero and non-finite vectors are ignored). A fluid
  // candidate within the tie tolerance of a running optimum is recorded as a maximiser.
  void consider(Vec3 n);

  // From now on only candidates meeting the visibility constraint count (the pass over
  // the constraint circles).
  void begin_constrained_pass() { constrained_pass_ = true; }
  // Back to the unconstrained pass: infeasible candidates count again towards the
  // unconstrained optimum (cells set aside before the constraint circles were searched,
  // site_subdivision.h).
  void end_constrained_pass() { constrained_pass_ = false; }

  // Exact D at unit n (radians) unless some arc is closer than thr (then false), and
  // whether n is on the fluid side of its nearest link feature.
  bool evaluate(const Vec3& n, double thr, double* d, bool* fluid) const;

  double best_constrained() const { return best_c_; }
  double best_unconstrained() const { return best_u_; }
  // Candidates below this cannot become maximisers any more (with or without the
  // constraint).
  double threshold() const { return std::max(best_c_, floor_) - tol_.normality_tie; }
  // Infinite once the unconstrained optimum is settled.
  double unconstrained_threshold() const {
    return unconstrained_settled_ ? std::numeric_limits<double>::infinity()
                                  : std::max(best_u_, floor_) - tol_.normality_tie;
  }
  // Declares the unconstrained optimum reached: a bound proved that no direction beats
  // best_unconstrained() by more than the tie. From then on candidates and cells that
  // fail the visibility constraint count for nothing (they could only add unconstrained
  // maximisers, which decide no status once the constraint limits the optimum).
  void settle_unconstrained() { unconstrained_settled_ = true; }
  // Declares that the fluid, feasible direction n reaches D = d (the cap antipode, a warm
  // start's rebuilt candidate): the optimum does too, so candidates more than the tie
  // below d are dropped as they come, without n entering the maximisers or the
  // tie-break.
  void raise_floor(const Vec3& n, double d) {
    if (d > floor_) {
      floor_ = d;
      floor_direction_ = n;
    }
  }
  double floor() const { return floor_; }
  // When no candidate reached the floor (the candidate formulas missed an optimum that
  // rounding or a degenerate configuration hides), the direction that set it is the
  // best point known: it becomes a candidate, evaluated like any other.
  void settle_floor() {
    if (floor_ > -std::numeric_limits<double>::infinity() && best_c_ < floor_ - tol_.normality_tie)
      consider(floor_direction_);
  }
  const Tolerances& tolerances() const { return tol_; }
  bool constrained() const { return constrained_; }
  double v_min() const { return v_min_; }
  const FanGeometry& geometry() const { return g_; }

  // The unconstrained optimum beats the constrained one by more than the tie.
  bool limited() const { return constrained_ && best_u_ > best_c_ + tol_.normality_tie; }
  // Some set of maximisers holds two distinct directions.
  bool unconstrained_maxima_distinct() const { return distinct(maxima_u_); }
  bool constrained_maxima_distinct() const { return distinct(maxima_); }
  bool has_maximizer() const { return !maxima_.empty(); }
  const Maximizer& last_maximizer() const { return maxima_.back(); }
  // The maximisers within the tie of the constrained optimum (diagnostics).
  const std::vector<Maximizer>& maximizers() const { return maxima_; }
  int n_candidates() const { return n_candidates_; }

  // The maximiser of largest V among those within the tie of the optimum, with the
  // status the flags give. Precondition: has_maximizer().
  MostNormalResult pick(bool non_unique) const;

 private:
  void add_maximizer(const Vec3& n, double d, double v);
  static bool distinct(const std::vector<Maximizer>& maxima);

  const FanGeometry& g_;
  const Tolerances& tol_;
  const bool constrained_;
  const double v_min_;
  bool constrained_pass_ = false;
  bool unconstrained_settled_ = false;
  double best_c_ = -std::numeric_limits<double>::infinity();
  double best_u_ = -std::numeric_limits<double>::infinity();
  double floor_ = -std::numeric_limits<double>::infinity();
  Vec3 floor_direction_{0.0, 0.0, 0.0};
  RecycledVector<Maximizer> maxima_;    // D >= best_c_ - tie among V >= V_min
  RecycledVector<Maximizer> maxima_u_;  // D >= best_u_ - tie, any V
  int n_candidates_ = 0;
  // Scratch of evaluate(): per-arc tests, the cached pre-test bounds of the last
  // threshold, and the arc that rejected the last candidate.
  struct ArcTest {
    enum Kind : char { kPole, kInterior, kEnds };
    double nf;    // n.f
    double mm2;   // |n - (n.f) f|^2
    double cosd;  // cosine of the distance, as rounded: |m|, max(n.u, n.v), 0 at the pole
    Kind kind;
  };
  mutable RecycledVector<ArcTest> arc_tests_;
  mutable double thr_key_ = std::numeric_limits<double>::quiet_NaN();
  mutable double cos_thr_ = 2.0;
  mutable double sin_thr_ = -1.0;
  mutable int last_reject_ = 0;
};

// Generators that cannot give a maximiser any more. A critical point x of D is built
// from sites nearest to it: a point site w there has angle(x, w) = D(x), an arc site c
// has its foot inside and arcsin|x.g_c| = D(x). A maximiser is fluid, and a fluid
// direction whose nearest feature is an arc's interior lies on the side of its normal,
// x.g_c > 0 (docs/normals.md, "Which side is fluid"). A candidate that can still become a
// maximiser has D(x) >= thr (the pool's threshold, which only rises), so
//   x.w <= cos(thr) |x|  and  x.g_c >= sin(thr) |x|:
// x lies within 90 deg - thr of the pole g_c (not of its antipode, which holds only
// solid-side candidates), a bisector {n.h = 0} carrying it passes that near,
// |h.g_c| <= cos thr, and two arc generators have poles at most 2 (90 deg - thr) apart;
// above 90 degrees no arc generates a maximiser at all.
// Candidates so ruled out that are not critical points (built from a site that is not
// nearest to them) are lost; those are not needed (site_subdivision.h, "Exactness").
class ArcReachScreen {
 public:
  explicit ArcReachScreen(const CandidatePool& pool) : pool_(pool) {}
  bool circle(const Vec3&) const { return false; }
  bool arc(const Vec3& h, const Vec3& g) const {
    update();
    if (!active_) return false;
    return no_arcs_ || std::fabs(dot(h, g)) > cos_thr_ + kMargin;
  }
  bool arc_pair(const Vec3& a, const Vec3& b) const {
    update();
    if (!active_) return false;
    // Both within 90 deg - thr of x: a.b >= cos(2 (90 deg - thr)) = -cos(2 thr).
    return no_arcs_ || dot(a, b) < cos_pair_ - kMargin;
  }
  bool point_ok(const Vec3& x, const Vec3& w) const {
    update();
    return !active_ || dot(x, w) <= (cos_thr_ + kMargin) * norm(x);
  }
  bool arc_ok(const Vec3& x, const Vec3& g) const {
    update();
    if (!active_) return true;
    return !no_arcs_ && dot(x, g) >= (sin_thr_ - kMargin) * norm(x);
  }

 private:
  // Rounding allowance of the dot products and of the threshold.
  static constexpr double kMargin = 1e-12;
  void update() const {
    const double thr = pool_.threshold() - kMargin;
    if (thr == thr_) return;
    thr_ = thr;
    active_ = thr > 0.0;
    no_arcs_ = thr >= 0.5 * M_PI;
    cos_thr_ = std::cos(thr);
    sin_thr_ = std::sin(thr);
    cos_pair_ = -std::cos(2.0 * thr);
  }
  const CandidatePool& pool_;
  mutable double thr_ = std::numeric_limits<double>::quiet_NaN();
  mutable bool active_ = false, no_arcs_ = false;
  mutable double cos_thr_ = 1.0, sin_thr_ = 0.0, cos_pair_ = -1.0;
};

}  // namespace detail
}  // namespace blayer
