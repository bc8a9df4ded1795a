// The candidate bookkeeping every most-normal solver shares: the exact evaluation of D
// and of the fluid side at a direction, the running optima with and without the
// visibility constraint, the sets of maximisers within the tie tolerance, and the final
// tie-break (docs/normals.md, Part 4). Solvers differ only in which candidates they
// offer. Internal to blayer_normals.
#pragma once

#include <limits>
#include <vector>

#include "blayer/core/tolerances.h"
#include "blayer/core/vec3.h"
#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/most_normal.h"

namespace blayer {
namespace detail {

// Maximisers farther apart than this (radians) are distinct optima, i.e. a plateau or
// a discrete tie. Candidates for one point computed from different site triples agree
// to ~1e-12; an off-plateau optimum moves by O(eps) under an eps perturbation, so 1e-6
// separates real ties from rounding with a wide margin on both sides.
constexpr double kDistinctMaximizers = 1e-6;

// Slack on V >= V_min for candidates constructed on a constraint circle n.f_i = V_min:
// their computed V carries ~1e-16 rounding, 1e-12 accepts them without admitting any
// meaningfully invisible direction.
constexpr double kConstraintSlack = 1e-12;

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

  // Exact D at unit n (radians) unless some arc is closer than thr (then false), and
  // whether n is on the fluid side of its nearest link feature.
  bool evaluate(const Vec3& n, double thr, double* d, bool* fluid) const;

  double best_constrained() const { return best_c_; }
  double best_unconstrained() const { return best_u_; }
  // Candidates below this cannot become maximisers any more.
  double threshold() const { return best_c_ - tol_.normality_tie; }
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
  double best_c_ = -std::numeric_limits<double>::infinity();
  double best_u_ = -std::numeric_limits<double>::infinity();
  std::vector<Maximizer> maxima_;    // D >= best_c_ - tie among V >= V_min
  std::vector<Maximizer> maxima_u_;  // D >= best_u_ - tie, any V
  int n_candidates_ = 0;
  // Scratch of evaluate(): per-arc tests, the cached pre-test bounds of the last
  // threshold, and the arc that rejected the last candidate.
  struct ArcTest {
    enum Kind : char { kPole, kInterior, kEnds };
    double nf;   // n.f
    double mm2;  // |n - (n.f) f|^2
    Kind kind;
  };
  mutable std::vector<ArcTest> arc_tests_;
  mutable double thr_key_ = std::numeric_limits<double>::quiet_NaN();
  mutable double cos_thr_ = 2.0;
  mutable double sin_thr_ = -1.0;
  mutable int last_reject_ = 0;
};

}  // namespace detail
}  // namespace blayer
