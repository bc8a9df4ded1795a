// When a most-normal answer agrees with the enumeration's (the oracle), shared by the
// tests that compare the default solver with it (agreement_test_support.h) and by
// bench/normals/most_normal_agreement.
//
// Both solvers maximise D over the same region with the same rules ("maximise D, then V;
// maximisers within normality_tie; distinct when more than 1e-6 apart") and evaluate
// every candidate exactly, so they agree on D within the tie. The enumeration also offers
// candidates built from sites that are not nearest to them (not critical points of D).
// One can land inside the tie band below the optimum on a ridge or near-plateau: it then
// wins the tie-break by a larger V, or makes the status "non-unique" by being distinct.
// The default solver builds only candidates of sites that can be nearest, and plateau
// peaks from the lower envelope of V, so there it keeps the maximiser of D, or a higher V.
// Agreement therefore means:
//   1. D within normality_tie;
//   2. the same direction (kSameDirection), or V not lower (kSameDirection: at least as
//      good by the tie-break), or an oracle's answer that is not a genuine maximiser
//      (a point of the tie band; genuine_maximizer below);
//   3. the same status, or the status differs only because the oracle holds maximisers
//      that are not genuine: distinct from the other answer, yet neither a point where
//      three sites tie, nor a maximum along the bisector of two, nor a local maximum of D
//      (genuine_maximizer below), or that lie within kNearDegenerateSpread of the answer
//      (one near-degenerate optimum, placed by ill-conditioned intersections).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "blayer/core/tolerances.h"
#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/most_normal.h"
#include "most_normal_enumeration.h"

namespace blayer {
namespace testing_fans {

// Directions of one optimum computed from different site subsets agree to ~1e-12; a
// unique optimum with a fall-off slope of at least 1e-2 keeps every direction within
// the tie of it inside 1e-9 / 1e-2.
constexpr double kSameDirection = 1e-7;

// Where four or more sites nearly tie, the candidate formulas meet tangentially and
// place one optimum at points up to a few 1e-6 apart, across the 1e-6 that makes
// maximisers distinct: a status that differs only by maximisers within this of the
// other answer is that spread, not a second optimum.
constexpr double kNearDegenerateSpread = 1e-5;

// A site seen from unit n: its distance and the gradient of the distance (tangent at n).
struct SiteView {
  double d;
  Vec3 gradient;
  Vec3 axis;   // the point, or the arc's pole on n's side
  bool point;
  bool operator<(const SiteView& o) const { return d < o.d; }
};

// The sites seen from unit n, computed here independently of the library: reflex link
// vertices (f_{j-1}.u_{j+1} < 0) as points, and the great circles of the arcs whose foot
// is strictly inside, one per circle; nearest first.
inline std::vector<SiteView> independent_sites(const FanGeometry& g, const Vec3& n) {
  const int k = g.n_faces();
  std::vector<SiteView> out;
  for (int j = 0; j < k; ++j)
    if (dot(g.face_normals[(j + k - 1) % k], g.dirs[(j + 1) % k]) < -1e-12) {
      const Vec3& w = g.dirs[j];
      out.push_back({angle_between(n, w), -normalized(w - dot(w, n) * n), w, true});
    }
  std::vector<Vec3> circles;
  for (int i = 0; i < k; ++i) {
    const Vec3& f = g.face_normals[i];
    const Vec3 m = n - dot(n, f) * f;
    // Strictly inside: a foot on an end is that link vertex, already seen as a point.
    const double margin = 1e-9 * norm(m);
    if (dot(cross(g.arc_start(i), m), f) <= margin || dot(cross(m, g.arc_end(i)), f) <= margin) continue;
    bool seen = false;
    for (const Vec3& c : circles) seen |= norm(c - f) < 1e-12;
    if (seen) continue;
    circles.push_back(f);
    const double s = dot(n, f) < 0.0 ? -1.0 : 1.0;
    out.push_back({std::atan2(std::fabs(dot(n, f)), norm(m)), s * normalized(f - dot(f, n) * n), s * f, false});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Whether unit x is a maximiser that any exact solver must find: a point where three
// sites tie (a Voronoi vertex), or a local maximum of D among all directions (1e-7 and
// 1e-6 away, more than rounding) that, where the two nearest sites nearly tie, also
// gains nothing along their bisector.
inline bool genuine_maximizer(const FanGeometry& g, const Vec3& x) {
  const double d = fan_normality(g, x);
  const std::vector<SiteView> sites = independent_sites(g, x);
  constexpr double kTied = 1e-11, kNearlyTied = 1e-8, kGain = 1e-14;
  if (sites.size() >= 3 && sites[2].d - sites[0].d <= kTied) return true;
  // D gained along tangent t: by steps along the great circle through x and t (exactly on
  // a point-point or arc-arc bisector when t is its tangent) up to max_step.
  auto gains = [&](const Vec3& t, double max_step) {
    for (double step = 1e-7; step <= max_step * 1.0001; step *= (step < 1e-2 ? 10.0 : 3.0))
      for (double sign : {1.0, -1.0})
        if (fan_normality(g, normalized(std::cos(step) * x + sign * std::sin(step) * t)) > d + kGain) return true;
    return false;
  };
  if (sites.size() >= 2 && sites[1].d - sites[0].d <= kNearlyTied) {
    // Along the bisector of the two nearest: a great circle {n.(a - b) = 0} for two points
    // or two arcs (walked up to 0.03 rad: a near-plateau, two points antipodal to 1e-7,
    // rises by ~1e-11 over that), a cone otherwise.
    const SiteView& a = sites[0];
    const SiteView& b = sites[1];
    const bool circle = a.point == b.point;
    const Vec3 t = circle ? normalized(cross(x, a.axis - b.axis)) : normalized(cross(x, a.gradient - b.gradient));
    if (norm2(t) > 0.0 && gains(t, circle ? 3e-2 : 1e-6)) return false;
    // No gain along it is not enough: a point where two other sites tie exactly and the
    // nearest lies 1.5e-9 below them (a pair candidate placed beside a three-site vertex)
    // gains nothing along the first two's bisector, yet D rises towards that vertex.
    // It must also be a local maximum.
  }
  const Vec3 e1 = normalized(cross(x, std::fabs(x[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
  const Vec3 e2 = cross(x, e1);
  for (int a = 0; a < 32; ++a) {
    const double t = M_PI * a / 32;
    if (gains(std::cos(t) * e1 + std::sin(t) * e2, 1e-6)) return false;
  }
  return true;
}

// The verdict of the rule: agreed, and if not, why.
struct Agreement {
  bool ok = true;
  std::string why;  // empty when ok
  // Whether it agreed only through the tie band (rules 2 and 3, not the exact match).
  bool through_tie_band = false;
  // Whether the statuses differ only by the spread of one near-degenerate optimum.
  bool near_degenerate = false;
};

inline Agreement compare_optimum(const FanGeometry& g, bool constrained, const MostNormalResult& a,
                                 const MostNormalResult& oracle) {
  const double tie = default_tolerances().normality_tie;
  Agreement r;
  auto fail = [&](const std::string& what) {
    char line[300];
    std::snprintf(line, sizeof line, ": %s D %.13f V %.10f vs oracle %s D %.13f V %.10f, angle %.3g",
                  normal_status_name(a.status), a.normality, a.visibility, normal_status_name(oracle.status),
                  oracle.normality, oracle.visibility, angle_between(a.normal, oracle.normal));
    r.ok = false;
    r.why = what + line;
    return r;
  };
  if (a.normality > oracle.normality + tie) return fail("D beyond the tie, above the oracle");
  if (a.normality < oracle.normality - tie) return fail("D beyond the tie, below the oracle");
  const bool same_direction = angle_between(a.normal, oracle.normal) <= kSameDirection;
  const bool v_not_lower = a.visibility >= oracle.visibility - kSameDirection;
  // A different answer of higher V must not be a genuine maximiser: the other solver
  // would then have had to pick it.
  if (!same_direction && !v_not_lower) {
    if (genuine_maximizer(g, oracle.normal)) return fail("a genuine maximiser of higher V");
    r.through_tie_band = true;
  }
  if (a.status != oracle.status) {
    // Only an oracle that calls its optimum non-unique for maximisers that are not
    // genuine may differ from a unique answer.
    if (!(a.status == NormalStatus::kOk && oracle.status == NormalStatus::kNonUnique)) return fail("status");
    for (const detail::Maximizer& m :
         detail::most_normal_maximizers(g, default_tolerances(), constrained, /*by_default=*/false)) {
      const double apart = angle_between(m.n, a.normal);
      if (apart <= detail::kDistinctMaximizers) continue;
      if (apart <= kNearDegenerateSpread) {
        r.near_degenerate = true;
      } else if (genuine_maximizer(g, m.n)) {
        return fail("status (a genuine distinct maximiser)");
      }
    }
    r.through_tie_band = !r.near_degenerate;
  }
  return r;
}

}  // namespace testing_fans
}  // namespace blayer
