// When a most-normal answer agrees with the enumeration's (the oracle), shared by the
// tests that compare the default solver with it and by bench/normals.
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
//      good by the tie-break), or the oracle's D below the other's by more than rounding
//      (the oracle's answer is a point of the tie band, not a maximiser of D);
//   3. the same status, or the status differs only because the oracle holds maximisers
//      that are not genuine: distinct from the other answer, yet neither a point where
//      three sites tie, nor a maximum along the bisector of two, nor a local maximum of D
//      (genuine_maximizer below).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

// Rounding of D at one direction computed along two paths.
constexpr double kSameNormality = 1e-12;

// A site seen from unit n: its distance and the gradient of the distance (tangent at n).
struct SiteView {
  double d;
  Vec3 gradient;
  bool operator<(const SiteView& o) const { return d < o.d; }
};

// The sites seen from unit n, computed here independently of the library: reflex link
// vertices (f_{j-1}.u_{j+1} < 0) as points, and the great circles of the arcs whose foot
// is inside, one per circle; nearest first.
inline std::vector<SiteView> independent_sites(const FanGeometry& g, const Vec3& n) {
  const int k = g.n_faces();
  std::vector<SiteView> out;
  for (int j = 0; j < k; ++j)
    if (dot(g.face_normals[(j + k - 1) % k], g.dirs[(j + 1) % k]) < -1e-12) {
      const Vec3& w = g.dirs[j];
      out.push_back({angle_between(n, w), -normalized(w - dot(w, n) * n)});
    }
  std::vector<Vec3> circles;
  for (int i = 0; i < k; ++i) {
    const Vec3& f = g.face_normals[i];
    const Vec3 m = n - dot(n, f) * f;
    if (dot(cross(g.arc_start(i), m), f) < 0.0 || dot(cross(m, g.arc_end(i)), f) < 0.0) continue;
    bool seen = false;
    for (const Vec3& c : circles) seen |= norm(c - f) < 1e-12;
    if (seen) continue;
    circles.push_back(f);
    const double s = dot(n, f) < 0.0 ? -1.0 : 1.0;
    out.push_back({std::atan2(std::fabs(dot(n, f)), norm(m)), s * normalized(f - dot(f, n) * n)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Whether unit x is a maximiser that any exact solver must find: a point where three
// sites tie (a Voronoi vertex), or where two tie and D is largest along their bisector,
// or a local maximum of D among all directions (1e-7 and 1e-6 away, more than rounding).
inline bool genuine_maximizer(const FanGeometry& g, const Vec3& x) {
  const double d = fan_normality(g, x);
  const std::vector<SiteView> sites = independent_sites(g, x);
  constexpr double kTied = 1e-11, kGain = 1e-14;
  if (sites.size() >= 3 && sites[2].d - sites[0].d <= kTied) return true;
  auto gains = [&](const Vec3& t) {
    for (double step : {1e-7, 1e-6})
      for (double sign : {1.0, -1.0})
        if (fan_normality(g, normalized(x + sign * step * t)) > d + kGain) return true;
    return false;
  };
  if (sites.size() >= 2 && sites[1].d - sites[0].d <= kTied) {
    const Vec3 t = normalized(cross(x, sites[0].gradient - sites[1].gradient));
    if (norm2(t) > 0.0) return !gains(t);
  }
  const Vec3 e1 = normalized(cross(x, std::fabs(x[0]) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
  const Vec3 e2 = cross(x, e1);
  for (int a = 0; a < 32; ++a) {
    const double t = M_PI * a / 32;
    if (gains(std::cos(t) * e1 + std::sin(t) * e2)) return false;
  }
  return true;
}

inline ::testing::AssertionResult same_optimum(const FanGeometry& g, bool constrained, const MostNormalResult& a,
                                               const MostNormalResult& oracle) {
  const double tie = default_tolerances().normality_tie;
  auto fail = [&](const std::string& what) {
    return ::testing::AssertionFailure()
           << what << ": " << normal_status_name(a.status) << " D " << a.normality << " V " << a.visibility
           << " vs oracle " << normal_status_name(oracle.status) << " D " << oracle.normality << " V "
           << oracle.visibility << ", angle " << angle_between(a.normal, oracle.normal);
  };
  if (std::fabs(a.normality - oracle.normality) > tie) return fail("D beyond the tie");
  const bool oracle_in_band = oracle.normality < a.normality - kSameNormality;
  if (angle_between(a.normal, oracle.normal) > kSameDirection && a.visibility < oracle.visibility - kSameDirection &&
      !oracle_in_band)
    return fail("direction, with lower V");
  if (a.status != oracle.status) {
    // Only an oracle that calls its optimum non-unique for maximisers that are not
    // genuine may differ from a unique answer.
    if (!(a.status == NormalStatus::kOk && oracle.status == NormalStatus::kNonUnique)) return fail("status");
    for (const detail::Maximizer& m :
         detail::most_normal_maximizers(g, default_tolerances(), constrained, /*by_default=*/false))
      if (angle_between(m.n, a.normal) > detail::kDistinctMaximizers && genuine_maximizer(g, m.n))
        return fail("status (a genuine distinct maximiser)");
  }
  return ::testing::AssertionSuccess();
}

}  // namespace testing_fans
}  // namespace blayer
