#include "blayer/normals/most_normal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include "blayer/normals/most_visible.h"
#include "blayer/normals/weighted_normal.h"
#include "antipodal_plateau.h"
#include "candidate_families.h"
#include "candidate_pool.h"
#include "fan_sites.h"
#include "link_vertex_lens.h"
#include "most_normal_enumeration.h"
#include "site_subdivision.h"
#include "sphere_solvers.h"
#include "visibility_boundary.h"

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
// The vertices counted are those within `slack` (in cosine) of the cap.
double cap_falloff(const FanGeometry& g, const MostVisibleResult& cap, double slack = kCapSupportSlack) {
  const Vec3 n0 = -cap.normal;
  Vec3 e1, e2;
  detail::orthonormal_complement(n0, &e1, &e2);
  thread_local std::vector<double> az;
  az.clear();
  for (const Vec3& u : g.dirs)
    if (dot(cap.normal, u) <= cap.visibility + slack) az.push_back(std::atan2(dot(u, e2), dot(u, e1)));
  const int m = static_cast<int>(az.size());
  if (m < 3) return 0.0;
  std::sort(az.begin(), az.end());
  double widest = az[0] + 2.0 * M_PI - az[m - 1];
  for (int i = 1; i < m; ++i) widest = std::max(widest, az[i] - az[i - 1]);
  return widest >= M_PI ? 0.0 : std::cos(0.5 * widest);
}

// The link-vertex bound: pi minus the radius of the cap holding the link vertices, the
// largest D any direction can reach (reached only at the cap antipode).
double link_vertex_bound(const MostVisibleResult& cap) {
  return M_PI - std::atan2(std::sqrt(std::max(0.0, 1.0 - cap.visibility * cap.visibility)), cap.visibility);
}

// Beyond convex corners the bound is used only where D falls off steeply around the
// optimum, so that no distinct direction comes within the tie band. Where it is flat
// (two link vertices hold the cap: second order along their bisector) the other
// candidates may hold distinct near-ties, to be broken by V.
bool bound_is_sharp(const FanGeometry& g, const FanSites& sites, const MostVisibleResult& cap) {
  return sites.all_reflex || cap_falloff(g, cap) >= kSharpFalloff;
}

// The link-vertex bound region is used when the threshold exceeds pi/2 by this (its
// caps must be smaller than hemispheres to be convex), and when it fits in a cap of this
// radius (larger ones are covered as fast by the whole-sphere subdivision).
constexpr double kLensThresholdMargin = 1e-9;
constexpr double kMaxLensRadius = 0.5;

enum class Strategy { kEnumeration, kPrunedEnumeration, kSubdivision };

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
  const double target = link_vertex_bound(cap);
  pool->consider(-cap.normal);
  const bool sharp = bound_is_sharp(g, sites, cap);
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

// Fans with at most this many sites (reflex vertices plus merged arcs) whose optimum is
// not bounded by the link-vertex lens are solved by the screened enumeration, larger ones
// by the subdivision: the crossover measured on the public meshes' fans and fronts and
// on the CAD-like fans (subdivision 2-3x slower up to 10 sites, equal at 11-12, 1.5-20x
// faster from 13 on).
constexpr int kMaxEnumeratedSites = 12;

// A cap held by more link vertices than this is a symmetric configuration (a cone
// apex, the pole of a body of revolution): every triple of them builds the same
// antipode, so the generators' candidates number C(m, 3) for a single point (a
// valence-96 pole took minutes). Up to 8 (56 triples) the generators still build it,
// which keeps the answers of smaller symmetric caps bit for bit (structured grids hold
// caps of 4).
constexpr int kManySupports = 8;

// Link vertices within this (in cosine) of the cap count as nearly holding it: the ring
// of a pole whose coordinates carry noise of up to about 1e-9 of its radius. Such a cap
// is held exactly by two or three of them, but every triple of them builds a candidate
// within the tie of the optimum (a valence-96 pole took 250 ms).
constexpr double kNearSupportSlack = 1e-8;

// Whether the cap antipode n0, at D = d, is the optimum by the link-vertex bound
// (cap_bound_shortcut's test) on a cap held by more than kManySupports vertices; or, on
// a cap nearly held by as many, the one distinct maximiser: for the vertices u_j within
// kNearSupportSlack of the cap, each angle(n, u_j) is concave around n0 (all beyond
// pi/2), so D(n) <= min_j angle(n, u_j) <= g - s |n - n0| with g = max_j angle(n0, u_j)
// and s their fall-off (cap_falloff); a maximiser has D >= d - tie, so it lies within
// (g - d + tie) / s of n0, required to be a tenth of kDistinctMaximizers.
bool bound_reached_by_many(const FanGeometry& g, const FanSites& sites, const MostVisibleResult& cap, double d,
                           const Tolerances& tol) {
  if (d < link_vertex_bound(cap) - tol.normality_tie) return false;
  // Counted first: most caps are held by two or three vertices, and the fall-off sorts.
  int n_support = 0, n_near = 0;
  double cos_widest = 1.0;  // cosine of the largest angle from n0 to the near vertices
  for (const Vec3& u : g.dirs) {
    const double c = dot(cap.normal, u);
    n_support += c <= cap.visibility + kCapSupportSlack;
    if (c <= cap.visibility + kNearSupportSlack) {
      ++n_near;
      cos_widest = std::min(cos_widest, -c);
    }
  }
  if (n_support > kManySupports && bound_is_sharp(g, sites, cap)) return true;
  if (n_near <= kManySupports) return false;
  const double falloff = cap_falloff(g, cap, kNearSupportSlack);
  const double g_near = std::acos(std::max(-1.0, cos_widest));
  return falloff > 0.0 && g_near - d + tol.normality_tie <= 0.1 * detail::kDistinctMaximizers * falloff;
}

// Raises the pool's floor to D at the first direction where the way from n_MV towards
// `target` meets the constraint V = V_min, when that direction is fluid and feasible.
// Under a binding constraint the constrained optimum lies on that boundary, and where
// the unconstrained optimum is near `target` it lies near that point: on a cylinder's rim
// (a cap fanned from the vertex at a right angle to the side) the constrained optimum
// lies about 24 degrees from n_MV, and on 600 CAD-like rims of valence 20 to 60 the
// point was within 0.33 degrees of it, its D as close to D*. Any fluid, feasible
// direction's D is a floor, as the cap antipode's is: the subdivision drops the cells
// below it from the start (32 CAD-like rims of valence 20: 448 cells instead of 1,452;
// of valence 60: 532 instead of 1,432), and every candidate within the tie of the
// optimum still passes the threshold.
void raise_floor_on_constraint(const FanGeometry& g, const Vec3& mv_normal, const Vec3& target, CandidatePool* pool) {
  Vec3 n;
  if (!detail::first_direction_at_visibility(g.face_normals.data(), g.n_faces(), mv_normal, target, pool->v_min(), &n))
    return;
  double d;
  bool fluid;
  if (pool->evaluate(n, -std::numeric_limits<double>::infinity(), &d, &fluid) && fluid &&
      fan_visibility(g, n) >= pool->v_min() - detail::kConstraintSlack)
    pool->raise_floor(n, d);
}

// The candidate passes of the default solver; *n_cells reports the subdivision's work.
bool default_passes(const FanGeometry& g, const FanSites& sites, const Tolerances& tol, const Vec3& mv_normal,
                    CandidatePool* pool, int* n_cells) {
  // Built on first use: the screened enumeration alone, which answers most wing-skin
  // fans, does not need its per-arc tables.
  std::optional<detail::SiteSubdivision> lazy;
  auto subdivision = [&]() -> detail::SiteSubdivision& {
    if (!lazy) lazy.emplace(sites, pool);
    return *lazy;
  };
  // The cap antipode maximises the link-vertex bound g >= D; above 90 degrees the region
  // g >= threshold, which holds every candidate that can still become a maximiser, is
  // convex around it and often tiny (link_vertex_lens.h).
  const Tolerances cap_tol = detail::lens_cap_tolerances(tol);
  MostVisibleResult cap;
  // Where Wolfe's iteration stays uncertified the supports on the hull of the link
  // vertices give the cap (the enumeration's answer in O(k^2)), which keeps the search in
  // the lens instead of the whole sphere (on one near-flat sliver fan, 189 cells against
  // 8162).
  const WolfeOutcome outcome = wolfe_min_norm_point(g.dirs.data(), g.n_faces(), cap_tol, &cap);
  bool capped = outcome == WolfeOutcome::kCertified && cap.feasible;
  if (outcome == WolfeOutcome::kUncertified) {
    cap = most_visible_on_hull(g.dirs.data(), g.n_faces(), cap_tol);
    capped = cap.feasible;
  }
  double radius = -1.0;
  // A fluid cap antipode that fails the visibility constraint (see below).
  double invisible_antipode_d = -std::numeric_limits<double>::infinity();
  if (capped) {
    // The antipode is a lower bound only: when it is the optimum its generators build it
    // exactly, and the rounding of the cap must not enter the tie-break. Except on a cap
    // held by many link vertices, where the bound certifies the antipode and building it
    // from its generators would take every triple of them.
    double d;
    bool fluid;
    if (pool->evaluate(-cap.normal, -std::numeric_limits<double>::infinity(), &d, &fluid) && fluid) {
      if (!pool->constrained() || fan_visibility(g, -cap.normal) >= pool->v_min() - detail::kConstraintSlack) {
        pool->raise_floor(-cap.normal, d);
        if (bound_reached_by_many(g, sites, cap, d, tol)) {
          pool->consider(-cap.normal);
          *n_cells = 0;
          return false;
        }
      } else {
        invisible_antipode_d = d;
        raise_floor_on_constraint(g, mv_normal, -cap.normal, pool);
      }
    }
    const double thr = pool->threshold();
    if (thr > 0.5 * M_PI + kLensThresholdMargin)
      radius = detail::link_vertex_lens_radius(g.dirs, -cap.normal, thr, kMaxLensRadius);
  }
  const int n_sites = static_cast<int>(sites.points.size() + sites.arcs.size());
  // An antipodal pair of link vertices bounds D by 90 degrees; where its plateau reaches
  // that, the maximisers lie along it (antipodal_plateau.h).
  if (radius <= 0.0 && n_sites > kMaxEnumeratedSites && detail::antipodal_plateau_settles(pool)) {
    *n_cells = 0;
    return pool->unconstrained_maxima_distinct() || pool->constrained_maxima_distinct();
  }
  bool subdivided = true;
  if (radius > 0.0) {
    subdivision().unconstrained_candidates_near(-cap.normal, radius);
  } else if (n_sites <= kMaxEnumeratedSites) {
    detail::enumerate_screened(sites, pool);
    subdivided = false;
  } else {
    subdivision().unconstrained_candidates();
  }
  // An invisible antipode above every candidate: the candidate formulas missed the
  // unconstrained optimum at a degenerate link (solve() catches a missed feasible one
  // with the floor), and with it that the constraint binds. It is offered, infeasible, so
  // that the constraint circles are searched: on a sliver wing's tip (a link arc of 2e-6
  // rad, two reflex link vertices 2.3e-7 from antipodal) the answer was otherwise the
  // 90-degree plateau, 1.1e-7 rad below the constrained optimum.
  if (invisible_antipode_d > pool->best_unconstrained() + tol.normality_tie) pool->consider(-cap.normal);
  bool non_unique;
  if (subdivided) {
    non_unique = subdivision().remaining_passes();
  } else {
    // Plateaus first: their feasible part may reach the unconstrained optimum.
    non_unique = pool->unconstrained_maxima_distinct() || pool->constrained_maxima_distinct();
    if (non_unique) {
      // One face per plane: on an exact CAD ridge 57 coplanar faces made the peaks'
      // O(k^2) candidates 1.2 ms at valence 60.
      std::vector<int> faces(g.n_faces()), first;
      std::iota(faces.begin(), faces.end(), 0);
      detail::same_plane_runs(g, &first);
      detail::drop_repeated_planes(first, &faces);
      detail::enumerate_plateau_peaks(sites, pool, faces);
    }
    if (pool->limited()) {
      // The constraint circles are searched leaf by leaf: a small fan gets its leaves now,
      // without their candidates, which the enumeration offered already (re-offering them
      // cost a quarter of a constrained valence-4 solve on the perforated block).
      subdivision().constraint_leaves();
      subdivision().constraint_circles();
    }
  }
  *n_cells = lazy ? lazy->stats().cells : 0;
  return non_unique;
}

// The passes of the enumeration, with the great-circle screen when `screen`.
bool enumeration_passes(const FanSites& sites, bool screen, CandidatePool* pool) {
  detail::enumerate_unconstrained(sites, screen, pool);
  const bool non_unique = pool->unconstrained_maxima_distinct() || pool->constrained_maxima_distinct();
  if (non_unique) detail::enumerate_plateau_peaks(sites, pool);
  if (pool->limited()) detail::enumerate_constraint_circles(sites, pool);
  return non_unique;
}

// Sites within this of the optimum's D (radians) count as its generators for the next
// front: genuine generators tie to rounding (~1e-15); near-ties up to 1e-10 only add
// rebuilt candidates.
constexpr double kGeneratorSlack = 1e-10;

// Faces whose visibility at a constrained optimum is within this of V_min hold it.
constexpr double kConstraintFaceSlack = 1e-10;

// The lower bound the previous generators give on this fan, or -infinity: the best D of
// the fluid, feasible candidates rebuilt from them. *rebuilt receives its direction.
double rebuilt_bound(const FanGeometry& g, const FanSites& sites, const MostNormalWarmStart& warm,
                     const CandidatePool& pool, Vec3* rebuilt) {
  double best = -std::numeric_limits<double>::infinity();
  int points[3], arcs[3], faces[2];
  int np = 0, na = 0, nf = 0;
  const int k = g.n_faces();
  for (int t = 0; t < warm.n_points; ++t) {
    const int j = warm.points[t];
    if (j < 0 || j >= k || sites.point_of_vertex[j] < 0) return best;
    points[np++] = sites.point_of_vertex[j];
  }
  for (int t = 0; t < warm.n_arcs; ++t) {
    const int i = warm.arcs[t];
    if (i < 0 || i >= k) return best;
    const int m = sites.arc_of_face[i];
    bool repeated = false;
    for (int q = 0; q < na; ++q) repeated |= arcs[q] == m;
    if (!repeated) arcs[na++] = m;
  }
  for (int t = 0; t < warm.n_faces; ++t) {
    if (warm.faces[t] < 0 || warm.faces[t] >= k) return best;
    faces[nf++] = warm.faces[t];
  }
  auto offer = [&](const Vec3& x) {
    const double len = norm(x);
    if (!(len > 0.0) || !std::isfinite(len)) return;
    const Vec3 n = x / len;
    double d;
    bool fluid;
    if (!pool.evaluate(n, -std::numeric_limits<double>::infinity(), &d, &fluid) || !fluid || !(d > best)) return;
    if (pool.constrained() && fan_visibility(g, n) < pool.v_min() - detail::kConstraintSlack) return;
    best = d;
    *rebuilt = n;
  };
  // The generators' own candidates: those of the whole set, or of each of its triples
  // when ties give more than three (the smaller subsets built the previous optimum only
  // if it had fewer generators).
  const int size = std::min(3, np + na);
  for (int mask = 1; mask < (1 << (np + na)); ++mask) {
    int sp[3], sa[3], cp = 0, ca = 0;
    if (__builtin_popcount(static_cast<unsigned>(mask)) != size) continue;
    for (int b = 0; b < np + na; ++b)
      if (mask & (1 << b)) {
        if (b < np) {
          sp[cp++] = points[b];
        } else {
          sa[ca++] = arcs[b - np];
        }
      }
    const detail::SiteSubset sub{sp, cp, sa, ca};
    if (cp + ca <= 2) {
      detail::pair_candidates(sites, sub, detail::NoScreen{}, offer);
    } else {
      detail::triple_candidates(sites, sub, detail::NoScreen{}, offer);
    }
    if (nf > 0) detail::constraint_candidates(g, sites, sub, faces, nf, pool.v_min(), offer);
  }
  return best;
}

// The generators of the solution r for the next front (MostNormalWarmStart).
MostNormalWarmStart generators_of(const FanGeometry& g, const FanSites& sites, const MostNormalResult& r,
                                  double v_min) {
  MostNormalWarmStart w;
  if (r.status != NormalStatus::kOk && r.status != NormalStatus::kNonUnique &&
      r.status != NormalStatus::kVisibilityConstrained)
    return w;
  const Vec3& n = r.normal;
  const double reach = r.normality + kGeneratorSlack;
  thread_local std::vector<std::pair<double, int>> near_points, near_arcs;
  near_points.clear();
  near_arcs.clear();
  for (const detail::PointSite& p : sites.points) {
    const double d = angle_between(n, p.w);
    if (d <= reach) near_points.push_back({d, p.vertex});
  }
  for (const detail::ArcSite& a : sites.arcs) {
    // Only an arc whose foot is inside generates: there its distance is to its circle.
    if (dot(n, cross(a.g, a.u)) < 0.0 || dot(n, cross(a.v, a.g)) < 0.0) continue;
    const double nf = dot(n, a.g);
    const double d = std::atan2(std::fabs(nf), norm(n - nf * a.g));
    if (d <= reach) near_arcs.push_back({d, a.first_face});
  }
  // The three nearest of each kind, nearest first.
  std::sort(near_points.begin(), near_points.end());
  std::sort(near_arcs.begin(), near_arcs.end());
  w.n_points = static_cast<int>(std::min<std::size_t>(3, near_points.size()));
  w.n_arcs = static_cast<int>(std::min<std::size_t>(3, near_arcs.size()));
  for (int t = 0; t < w.n_points; ++t) w.points[t] = near_points[t].second;
  for (int t = 0; t < w.n_arcs; ++t) w.arcs[t] = near_arcs[t].second;
  if (r.status == NormalStatus::kVisibilityConstrained)
    for (int i = 0; i < g.n_faces() && w.n_faces < 2; ++i)
      if (dot(n, g.face_normals[i]) <= v_min + kConstraintFaceSlack) w.faces[w.n_faces++] = i;
  w.valid = w.n_points + w.n_arcs > 0;
  return w;
}

MostNormalResult solve(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility, Strategy strategy,
                       MostNormalWarmStart* warm = nullptr, bool* hit = nullptr,
                       std::vector<detail::Maximizer>* maximizers = nullptr) {
  if (hit) *hit = false;
  const MostNormalWarmStart previous = warm ? *warm : MostNormalWarmStart{};
  if (warm) *warm = MostNormalWarmStart{};
  const int k = g.n_faces();
  const MostVisibleResult mv = most_visible_normal(g.face_normals.data(), k, tol);
  if (!mv.feasible) return fallback(g, mv.normal, mv.visibility, NormalStatus::kNoVisibleDirection);
  if (!simple_link_around(g, mv.normal)) {
    const Vec3 n = weighted_average_normal(g, NormalMethod::kAngle);
    return fallback(g, n, fan_visibility(g, n), NormalStatus::kDegenerateFan);
  }
  CandidatePool pool(g, tol, constrain_visibility, 0.5 * mv.visibility);
  thread_local FanSites sites;
  detail::build_fan_sites(g, tol, &sites);
  pool.consider(mv.normal);
  Vec3 rebuilt{0.0, 0.0, 0.0};
  double rebuilt_d = -std::numeric_limits<double>::infinity();
  if (previous.valid && !sites.points.empty()) {
    rebuilt_d = rebuilt_bound(g, sites, previous, pool, &rebuilt);
    pool.raise_floor(rebuilt, rebuilt_d);
  }
  bool non_unique = false;
  int n_cells = 0;
  // Without reflex vertices MN = MV (docs/normals.md, Part 4, "Sites").
  if (!sites.points.empty()) {
    if (strategy == Strategy::kSubdivision) {
      non_unique = default_passes(g, sites, tol, mv.normal, &pool, &n_cells);
    } else {
      if (strategy == Strategy::kPrunedEnumeration) {
        MostNormalResult r;
        if (cap_bound_shortcut(g, sites, tol, &pool, &r)) return r;
      }
      non_unique = enumeration_passes(sites, strategy == Strategy::kPrunedEnumeration, &pool);
    }
  }
  if (pool.best_constrained() < pool.floor() - tol.normality_tie) {
    // No candidate reached the floor: the formulas missed an optimum at a degenerate
    // configuration. A warm start then yields to the cold solve; the cap antipode, the
    // best point known, becomes a candidate.
    if (previous.valid) return solve(g, tol, constrain_visibility, strategy, warm, nullptr, maximizers);
    pool.settle_floor();
  }
  non_unique = non_unique || pool.constrained_maxima_distinct();
  if (!pool.has_maximizer()) return fallback(g, mv.normal, mv.visibility, NormalStatus::kDegenerateFan);
  MostNormalResult r = pool.pick(non_unique);
  r.n_cells = n_cells;
  if (maximizers) *maximizers = pool.maximizers();
  if (hit)
    *hit = rebuilt_d > -std::numeric_limits<double>::infinity() &&
           angle_between(r.normal, rebuilt) <= detail::kDistinctMaximizers &&
           std::fabs(r.normality - rebuilt_d) <= tol.normality_tie;
  if (warm && !sites.points.empty()) *warm = generators_of(g, sites, r, pool.v_min());
  return r;
}

}  // namespace

MostNormalResult most_normal_normal(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility) {
  return solve(g, tol, constrain_visibility, Strategy::kSubdivision);
}

MostNormalResult most_normal_normal(const FanGeometry& g, MostNormalWarmStart* warm, bool* hit, const Tolerances& tol,
                                    bool constrain_visibility) {
  return solve(g, tol, constrain_visibility, Strategy::kSubdivision, warm, hit);
}

MostNormalResult most_normal_by_pruned_enumeration(const FanGeometry& g, const Tolerances& tol,
                                                   bool constrain_visibility) {
  return solve(g, tol, constrain_visibility, Strategy::kPrunedEnumeration);
}

namespace detail {

std::vector<Maximizer> most_normal_maximizers(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility,
                                              bool by_default) {
  std::vector<Maximizer> out;
  solve(g, tol, constrain_visibility, by_default ? Strategy::kSubdivision : Strategy::kEnumeration, nullptr, nullptr,
        &out);
  return out;
}

}  // namespace detail

MostNormalResult most_normal_by_enumeration(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility) {
  return solve(g, tol, constrain_visibility, Strategy::kEnumeration);
}

}  // namespace blayer
