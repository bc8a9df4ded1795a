#include "blayer/normals/most_normal.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "blayer/normals/most_visible.h"
#include "blayer/normals/weighted_normal.h"
#include "candidate_pool.h"
#include "fan_sites.h"
#include "most_normal_enumeration.h"
#include "sphere_solvers.h"

namespace blayer {

namespace {

using detail::CandidatePool;
using detail::FanSites;

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

enum class Strategy { kEnumeration, kPrunedEnumeration };

// Winding number of the link around n (every triangle seen from n): one turn means a
// simple link with n inside its fluid region.
bool simple_link_around(const FanGeometry& g, const Vec3& n) {
  double turn = 0.0;
  for (int i = 0; i < g.n_faces(); ++i) {
    const Vec3& a = g.arc_start(i);
    const Vec3& b = g.arc_end(i);
    turn += std::atan2(dot(n, cross(a, b)), dot(a, b) - dot(n, a) * dot(n, b));
  }
  return std::lround(turn / (2.0 * M_PI)) == 1;
}

MostNormalResult fallback(const FanGeometry& g, const Vec3& n, double v, NormalStatus status) {
  MostNormalResult r;
  r.normal = n;
  r.visibility = v;
  r.normality = fan_normality(g, n);
  r.status = status;
  return r;
}

// The bound shortcut: every link vertex lies on the link, so D(n) <= min_j angle(n, u_j)
// for every n, and the right side is largest, at `target`, at the antipode of the
// smallest cap holding the link vertices. A fluid, feasible direction reaching the bound
// is optimal. This holds for any link; it is reached at convex solid corners (all
// junctions reflex) and whenever D* > pi/2, where the antipode sees every link vertex at
// more than 90 degrees, so no arc interior is nearer than its ends. Returns whether
// *out holds the answer.
bool cap_bound_shortcut(const FanGeometry& g, const FanSites& sites, const Tolerances& tol, CandidatePool* pool,
                        MostNormalResult* out) {
  const MostVisibleResult cap = most_visible_normal(g.dirs.data(), g.n_faces(), tol);
  if (!cap.feasible) return false;
  const double target =
      M_PI - std::atan2(std::sqrt(std::max(0.0, 1.0 - cap.visibility * cap.visibility)), cap.visibility);
  pool->consider(-cap.normal);
  // Beyond convex corners the bound is used only where D falls off steeply around the
  // optimum, so that no distinct direction comes within the tie band. Where it is flat
  // (two link vertices hold the cap: second order along their bisector) the other
  // candidates may hold distinct near-ties, to be broken by V.
  const bool sharp = sites.all_reflex || cap_falloff(g, cap) >= kSharpFalloff;
  const double tie = tol.normality_tie;
  if (!(sharp && pool->best_constrained() >= target - tie &&
        pool->best_unconstrained() <= pool->best_constrained() + tie && pool->has_maximizer()))
    return false;
  const detail::Maximizer& m = pool->last_maximizer();
  out->normal = m.n;
  out->normality = m.d;
  out->visibility = m.v;
  out->status = NormalStatus::kOk;
  out->n_candidates = pool->n_candidates();
  return true;
}

MostNormalResult solve(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility, Strategy strategy) {
  const int k = g.n_faces();
  const MostVisibleResult mv = most_visible_normal(g.face_normals.data(), k, tol);
  if (!mv.feasible) {
    MostNormalResult r = fallback(g, mv.normal, mv.visibility, NormalStatus::kNoVisibleDirection);
    return r;
  }
  if (!simple_link_around(g, mv.normal)) {
    const Vec3 n = weighted_average_normal(g, NormalMethod::kAngle);
    return fallback(g, n, fan_visibility(g, n), NormalStatus::kDegenerateFan);
  }
  CandidatePool pool(g, tol, constrain_visibility, 0.5 * mv.visibility);
  thread_local FanSites sites;
  detail::build_fan_sites(g, tol, &sites);
  pool.consider(mv.normal);
  const bool shortcuts = strategy != Strategy::kEnumeration;
  if (!sites.points.empty() && shortcuts) {
    MostNormalResult r;
    if (cap_bound_shortcut(g, sites, tol, &pool, &r)) return r;
  }
  if (!sites.points.empty()) detail::enumerate_unconstrained(sites, shortcuts, &pool);
  // Plateaus first: their feasible part may reach the unconstrained optimum.
  bool non_unique = pool.unconstrained_maxima_distinct() || pool.constrained_maxima_distinct();
  if (non_unique) detail::enumerate_plateau_peaks(sites, &pool);
  if (pool.limited()) detail::enumerate_constraint_circles(sites, &pool);
  non_unique = non_unique || pool.constrained_maxima_distinct();
  if (!pool.has_maximizer()) return fallback(g, mv.normal, mv.visibility, NormalStatus::kDegenerateFan);
  return pool.pick(non_unique);
}

}  // namespace

MostNormalResult most_normal_normal(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility) {
  return solve(g, tol, constrain_visibility, Strategy::kPrunedEnumeration);
}

MostNormalResult most_normal_by_enumeration(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility) {
  return solve(g, tol, constrain_visibility, Strategy::kEnumeration);
}

}  // namespace blayer
