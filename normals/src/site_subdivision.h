// The most-normal candidates by an adaptive subdivision of the sphere that localises the
// generalized Voronoi diagram of the fan's sites (reflex link vertices as points, merged
// link arcs as great-circle arcs): instead of every 1-, 2- and 3-site candidate of all
// the sites (O(k^3)), only those of the few sites that can be nearest inside a small
// cell, in the cells where D can still reach the running threshold.
//
// Cells are the squares of gnomonic charts (the six cube faces, or one chart around a
// given direction), refined as quadtrees; each cell is held in the cap B(c, rho) around
// its centre c. D and V are 1-Lipschitz in the angle, so on the cell
//   D <= D(c) + rho,   V <= V(c) + rho,
// and a site s (distance d_s) can be the nearest one somewhere in the cell only if
// d_s(c) <= D(c) + 2 rho; a face can give V only if c.f <= V(c) + 2 rho. A cell is
// dropped when D(c) + rho is below the threshold (or, wholly invisible, below the
// unconstrained one), when a pair of link vertices bounds D below it on the cap
// (pair_cap_cosine), or when it lies off the fluid side (D(c) > rho, so the cap meets no
// arc, and c is not fluid). Otherwise it inherits the parent's surviving sites and
// faces and is split, until at most kLeafSites sites can be nearest in it, or they stop
// changing, or the cell is tiny. An arc counts only where its interior can be nearest
// (the cap meets its foot-inside lune) and can still reach the threshold, a reflex link
// vertex only where the cap meets its wedge: beyond the ends of both its arcs, the only
// directions to which it is nearer than they are.
//
// Exactness. Every local maximum of D (with or without the constraint V >= V_min) is a
// candidate of the subset of the sites nearest to it (docs/normals.md, "Why exact"): a
// point x with D(x) = d_s(x) for its generators s. If x lies in a leaf, each generator
// s has d_s(c) <= d_s(x) + rho = D(x) + rho <= D(c) + 2 rho, so it survives in the leaf,
// and the leaf's enumeration of its subsets builds x by the same formula as the full
// enumeration. A dropped cell holds no fluid point with D above the threshold of its
// kind, and thresholds only rise. A set-aside cell (below) that is never refined holds
// only directions that fail the constraint, and is left so only once the status no
// longer depends on them. Each subset is enumerated once, in the first leaf
// that holds it, and its candidates are offered wherever they lie. So every candidate of
// the full enumeration that is a critical point of D and can become a maximiser is
// offered; only candidates built from sites that are not nearest to them may be missing,
// and within the tie of the optimum those lie on ridges or near-plateaus whose genuine
// maximisers are offered. The leaves are kept for the plateau and constraint-circle
// passes, which therefore see only the faces and sites of each leaf.
//
// Cost: the cells near the superlevel set of the optimum, each O(sites of its parent),
// plus the candidates of the distinct subsets of the leaves' sites. Internal to
// blayer_normals.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "blayer/core/cyclic_index.h"
#include "candidate_pool.h"
#include "fan_sites.h"
#include "recycled_vector.h"
#include "sphere_solvers.h"

namespace blayer {
namespace detail {

// min of n.x over the cap B(c, rho) (unit c; cos_rho, sin_rho of rho < 90 deg) when
// c.x >= 0: |x| cos(angle(c, x) + rho) = (c.x) cos rho - |c x x| sin rho, the angle sum
// then staying within 180 deg.
inline double cap_min_dot(const Vec3& c, double cos_rho, double sin_rho, const Vec3& x) {
  return dot(c, x) * cos_rho - norm(cross(c, x)) * sin_rho;
}

// A lower bound of max(n.u_a, n.u_b) over the cap B(c, rho): every n has
// max(n.u_a, n.u_b) >= n.q, q = (u_a + u_b) / 2, bounded by cap_min_dot when c.q >= 0;
// -2 (no bound) otherwise. So D <= arccos of it on the whole cap, u_a and u_b being link
// vertices.
inline double pair_cap_cosine(const Vec3& c, double cos_rho, double sin_rho, const Vec3& u_a, const Vec3& u_b) {
  const Vec3 q = 0.5 * (u_a + u_b);
  return dot(c, q) >= 0.0 ? cap_min_dot(c, cos_rho, sin_rho, q) : -2.0;
}

// Allowance of pair_cap_certainly_below: its squares of values below 2 carry rounding
// errors of a few 1e-16, and it answers true only where the bound lies kPairScreen / 3
// below the level, several times pair_cap_cosine's own rounding.
constexpr double kPairScreen = 1e-14;

// Whether pair_cap_cosine(c, cos_rho, sin_rho, u_a, u_b) is certainly at most `level`,
// decided without a root from x = c.q (q = (u_a + u_b) / 2; the mean of c.u_a and c.u_b
// will do): where c.q >= 0 the bound is level + l - s with l = x cos_rho - level and
// s = |c x q| sin_rho, |c x q|^2 = |q|^2 - x^2 and |q|^2 = (1 + u_a.u_b) / 2. As |l| < 2
// and s <= 1, l^2 < s^2 - kPairScreen gives s - |l| > kPairScreen / 3, so the bound lies
// that far below level (elsewhere it is -2). False says nothing.
inline bool pair_cap_certainly_below(double x, double cos_rho, double sin_rho, const Vec3& u_a, const Vec3& u_b,
                                     double level) {
  const double l = x * cos_rho - level;
  return l * l < (0.5 * (1.0 + dot(u_a, u_b)) - x * x) * sin_rho * sin_rho - kPairScreen;
}

// Whether no direction n of the cap B(c, rho) (c unit) has n.f_a + n.f_b >= level, so
// that none has both n.f_a and n.f_b at level / 2 or above: on the cap
// n.(f_a + f_b) <= c.(f_a + f_b) + rho |f_a + f_b| (the chord is at most the angle). The
// 1e-15 on rho and the 1e-12 cover the rounding of the sum and of its dot product (a few
// ulps of unit-length data) by three orders.
inline bool pair_sum_below_on_cap(const Vec3& c, double rho, const Vec3& f_a, const Vec3& f_b, double level) {
  const Vec3 sum = f_a + f_b;
  return dot(c, sum) + (rho + 1e-15) * norm(sum) + 1e-12 < level;
}

// Whether the great circle {n.h = 0} can hold a direction that a leaf with centre c
// admits (n.c >= cos_cap |n|, as SiteSubdivision::offer tests): such a direction is
// within the angle whose cosine is cos_cap of c, so |c.h| <= |h| times its sine. offer's
// comparison is rounded by about 1e-15 (its dot product and |n| near 1), which widens the
// admitted angle by much more than 1e-15 on small leaves (cos_cap is then within 1e-15 of
// 1): the sine is taken for the cosine cos_cap - 2e-15, 1 - (cos_cap - 2e-15)^2 <=
// 1 - cos_cap^2 + 4e-15, which also covers the rounding of 1 - cos_cap^2. 1e-12 covers
// that of n.h in the candidates built on the circle and of this test. Caps of a
// hemisphere or more meet every great circle.
inline bool great_circle_meets_cap(const Vec3& c, double cos_cap, const Vec3& h) {
  if (!(cos_cap > 0.0)) return true;
  const double sin_reach = std::sqrt(std::max(0.0, 1.0 - cos_cap * cos_cap) + 4e-15) + 1e-12;
  return std::fabs(dot(c, h)) <= sin_reach * norm(h);
}

// The arc of the circle {n.h = c0, |n| = 1} (h unit, its CircleWindow frame) where
// n.x >= level (x unit): n(t).x = c0 (h.x) + s R cos(t - t0) with R cos t0 = e1.x,
// R sin t0 = e2.x, widened by 1e-9 in half width for the rounding of the arccosine. The
// whole circle where the circle is a point or nearly centred on x (s R <= 1e-6), an
// empty window (half width -1) where no point of it reaches the level.
inline CircleWindow circle_arc_above(const Vec3& h, double c0, const Vec3& x, double level) {
  Vec3 e1, e2;
  orthonormal_complement(h, &e1, &e2);
  const double s = std::sqrt(std::max(0.0, 1.0 - c0 * c0));
  const double a = dot(x, e1), b = dot(x, e2);
  const double sr = s * std::hypot(a, b);
  if (!(sr > 1e-6)) return {};
  const double kappa = (level - c0 * dot(x, h)) / sr;
  if (kappa <= -1.0) return {};
  if (kappa > 1.0) return {0.0, -1.0};
  return {std::atan2(b, a), std::acos(kappa) + 1e-9};
}

// The arc of the circle {n.h = c0} that can hold a direction a leaf with centre c
// admits (n.c >= cos_cap |n|, as SiteSubdivision::offer tests): the level is lowered by
// 1e-12 for the rounding of the built points (about 1e-15) and of offer's test. The
// whole circle for caps of a hemisphere or more.
inline CircleWindow circle_window_in_cap(const Vec3& c, double cos_cap, const Vec3& h, double c0) {
  if (!(cos_cap > 0.0)) return {};
  return circle_arc_above(h, c0, c, cos_cap - 1e-12);
}

// The part of the circle {n.h = c0} where face normal f keeps the visibility that
// CandidatePool::consider requires of a constrained candidate, n.f >= v_min -
// kConstraintSlack, lowered by 1e-13 for the rounding of the built points and of the
// pool's dot products.
inline CircleWindow circle_window_feasible(const Vec3& f, double v_min, const Vec3& h, double c0) {
  return circle_arc_above(h, c0, f, v_min - kConstraintSlack - 1e-13);
}

// The smallest window holding the common part of two windows of one circle (their
// intersection, or the hull of its two pieces where it has two).
inline CircleWindow intersect_windows(const CircleWindow& a, const CircleWindow& b) {
  if (a.half_width < 0.0 || b.whole()) return a;
  if (b.half_width < 0.0 || a.whole()) return b;
  const double delta = std::remainder(b.centre - a.centre, 2.0 * M_PI);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int turn = -1; turn <= 1; ++turn) {
    const double piece_lo = std::max(-a.half_width, delta + 2.0 * M_PI * turn - b.half_width);
    const double piece_hi = std::min(a.half_width, delta + 2.0 * M_PI * turn + b.half_width);
    if (piece_lo <= piece_hi) {
      lo = std::min(lo, piece_lo);
      hi = std::max(hi, piece_hi);
    }
  }
  if (!(lo <= hi)) return {0.0, -1.0};
  return {a.centre + 0.5 * (lo + hi), 0.5 * (hi - lo)};
}

// The foot-inside lune of fan arc i, as two half-spaces: n's foot on the arc's great
// circle lies inside the arc iff n.arc_start_lune(g, i) >= 0 (not before its start)
// and n.arc_end_lune(g, i) >= 0 (not past its end). With m = n - (n.f) f: (u x m).f >= 0
// is n.(f x u) >= 0, and (m x v).f >= 0 is n.(v x f) >= 0.
inline Vec3 arc_start_lune(const FanGeometry& g, int i) { return normalized(cross(g.face_normals[i], g.arc_start(i))); }
inline Vec3 arc_end_lune(const FanGeometry& g, int i) { return normalized(cross(g.arc_end(i), g.face_normals[i])); }

struct SubdivisionStats {
  int cells = 0;
  int leaves = 0;
  int max_depth = 0;
  int set_aside = 0;          // cells set aside (each time)
  int set_aside_refined = 0;  // set-aside cells taken up again
  int floors_raised = 0;      // cell centres that raised the pool's floor
  int floors_raised_unlimited = 0;  // of them, while no direction beat the constrained optimum
  int closed = 0;             // cells left unrefined once all their site subsets were enumerated
  int dropped_by_hint = 0;    // cells dropped by their parent's nearest arc alone (refine)
};

class SiteSubdivision {
 public:
  SiteSubdivision(const FanSites& sites, CandidatePool* pool);

  // Refines the whole sphere (six cube faces) and offers every leaf's 1-, 2- and 3-site
  // candidates. Under the visibility constraint, cells invisible below V_min all over
  // that could still hold the unconstrained optimum are set aside (see "Set-aside
  // cells" below).
  void unconstrained_candidates();
  // The leaves the constraint-circle pass needs, without offering their candidates, for
  // a fan whose candidates an enumeration of all its sites has offered already: the
  // same refinement, but cells that are infeasible all over are dropped at once.
  void constraint_leaves();
  // The same within the cap B(centre, radius) alone (radius < pi/2), for callers that
  // have proved that every candidate that can still become a maximiser lies there.
  void unconstrained_candidates_near(const Vec3& centre, double radius);
  // Visibility peaks along the plateau circles of the concentric pairs of each leaf.
  void plateau_peaks();
  // Candidates on the constraint circles n.f_i = V_min crossing each leaf (puts the
  // pool in its constrained pass).
  void constraint_circles();

  // Set-aside cells. A cell invisible below V_min all over (face by face, or by a pair
  // of nearly opposite faces: pair_infeasible) holds no candidate of the constrained
  // problem: its candidates can only raise the unconstrained optimum, which
  // decides no answer, only whether the constraint limits it (the status, and whether
  // the constraint circles are searched at all). On sliver fans that optimum sits on a
  // near-plateau of near-antipodal link vertices, and pinning its value took thousands
  // of such cells, while any direction beyond the tie of the constrained optimum settles
  // the status. So the refinement sets those cells aside, and the caller refines them
  // (refine_set_aside) only while no such direction is known; a set-aside cell is
  // dropped like any other once it cannot reach the unconstrained threshold.
  //
  // Closed cells. Every maximiser in a cell is a candidate of a subset of the cell's
  // sites (the exactness argument above, for the cell's own cap), so once every subset
  // of at most three of them is enumerated, refining the cell offers nothing new to the
  // unconstrained search. Along a ridge of near-ties on a nearly flat fan the leaves
  // repeat the same handful of sites by the hundred (a valence-40 sliver fan: 10 of its
  // 857 leaves enumerated a subset no leaf had before), so a small cell there enumerates
  // its few missing subsets itself and is closed: left unrefined. Its leaves would serve
  // the later passes only, and they find nothing there: a closed cell is above V_min all
  // over (no constraint circle crosses it) and holds no concentric pair of sites (no
  // plateau circle). The extra subsets offer candidates its leaves would not have built,
  // exact points of the fan like every other candidate (docs/normals.md, "Closed cells").
  //
  // The passes after unconstrained_candidates[_near]: the plateau peaks where the
  // maximisers found are distinct, then, where the constraint limits the optimum, the
  // constraint circles, refining set-aside cells only while the status is open. Returns
  // whether the maximisers were distinct when the plateau pass was decided.
  bool remaining_passes();

  const SubdivisionStats& stats() const { return stats_; }

 private:
  // Link vertices around the closed fan, i < k_.
  int next_vertex(int i) const { return cyclic_next(i, k_); }
  int previous_vertex(int i) const { return cyclic_previous(i, k_); }
  // A gnomonic chart: the direction of (x, y) is e0 + x e1 + y e2.
  struct Chart {
    Vec3 e0, e1, e2;
  };
  struct Cell {
    int chart;
    double x0, y0, size;
    Vec3 c;
    double rho;
  };
  struct Leaf {
    Vec3 c;
    double rho;
    double d;  // D(c)
    double v;  // V(c)
    int points_begin, arcs_begin, faces_begin;  // into leaf_ids_
    int n_points, n_arcs, n_faces;
    // Directions n in the leaf's cap have n.c >= cos_cap |n|: computed once per leaf,
    // since the constraint-circle pass offers hundreds of candidates to some leaves.
    double cos_cap;
  };

  // A cell set aside with what its refinement needs: its parent's kept arcs and faces
  // (ids_begin .. + n_arcs, then n_faces, in set_aside_ids_).
  struct SetAside {
    Cell cell;
    int ids_begin, n_arcs, n_faces;
    int depth, parent_sites, stable_levels;
    double d_high;
  };

  Cell make_cell(int chart, double x0, double y0, double size) const;
  void refine_roots();
  // `invisible`: the cell lies in a set-aside one, so it is invisible below V_min all
  // over whatever its own bound says.
  // `hint`: an arc near the cell (the parent's nearest one), or -1. D is at most the
  // distance to any arc, so the cell is dropped at once when that arc is nearer than the
  // threshold allows, before the distances to all the kept arcs are taken.
  void refine(const Cell& cell, int arcs_begin, int arcs_end, int faces_begin, int faces_end, int depth,
              int parent_sites, int stable_levels, bool invisible = false, int hint = -1);
  // Cosine of the distance from c to arc i: to its great circle where the foot of c
  // lies in the arc (c in both of its lunes), to its nearer end elsewhere. Defined here
  // to be inlined into refine's scan (out of line, the calls cost 7 % of a ridge fan).
  double arc_cosine(const Vec3& c, int i) const {
    if (dot(c, lune1_[i]) >= 0.0 && dot(c, lune2_[i]) >= 0.0) {
      const double cf = dot(c, g_.face_normals[i]);
      return std::sqrt(std::max(0.0, 1.0 - cf * cf));
    }
    return std::max(dot(c, g_.arc_start(i)), dot(c, g_.arc_end(i)));
  }
  // Refines the set-aside cells, the one that may reach the highest D first, until the
  // pool is limited (its remaining cells are set aside again) or none is left. Their
  // leaves count as invisible all over: none is searched for constraint circles.
  void refine_set_aside();
  // Raises the pool's floor to D at centre c when c is fluid and feasible. Where the
  // constraint binds, the constrained optimum lies on a constraint circle, built only by
  // the pass after the refinement; until then the threshold is the best feasible
  // candidate of the leaves, often far below, and every feasible cell above it is refined
  // (a valence-30 sliver fan: 10,106 cells and 4.6 ms, with the probes 3,710 and 1.0 ms).
  // The same holds, before any direction beats the constrained optimum, in cells that
  // reach below V_min: the leaves' candidates there are infeasible, and a band of cells
  // along the constraint was refined below the optimum (a valence-40 sliver fan: 21,378
  // cells and 7.6 ms, with the probes 306 and 0.15 ms).
  // The floor is a point's exact D, so the optimum reaches it, and it never enters the
  // maximisers (CandidatePool::raise_floor).
  void probe_centre(const Vec3& c);
  // Whether a pair of the kept faces arena_[faces_begin, faces_end) puts the whole cap
  // B(c, rho) below V_min: feasible points have n.f_a + n.f_b >= 2 (V_min - slack), so a
  // pair whose sum stays below that on the cap proves it. The bound V(c) + rho, face by
  // face, cannot: it keeps every cell along the constraint of two nearly opposite faces
  // (a knife-edge fan: on valence-30 and -40 sliver fans 3,000 to 4,800 cells, all but a
  // few hundred of them refined there). Any pair gives a valid proof; as a matter of cost
  // the two lowest faces at c are paired with the others.
  bool pair_infeasible(const Vec3& c, double rho, int faces_begin, int faces_end);
  // Closes the cell being classified if it may be: at most kCloseMissing subsets of at
  // most three of its sites (leaf_points_, leaf_arcs_) not enumerated yet, and no
  // concentric pair among them (plateau_circles). Then enumerates those subsets and
  // returns true.
  bool close_cell();
  // A set of site ids below 128 as bits; false (and no set) when an id is larger.
  using SiteSet = std::array<std::uint64_t, 2>;
  static bool site_set(const std::vector<int>& ids, SiteSet* set);
  // Whether the set lies within that of one of the last leaves or closed cells, all of
  // whose subsets were enumerated.
  bool within_enumerated_set(const SiteSet& set) const;
  // Appends the subsets of the ids not enumerated yet to *missing; false once there are
  // more than kCloseMissing.
  bool missing_subsets(const std::vector<int>& ids, std::vector<std::array<int, 3>>* missing) const;
  // The ids of the cell's sites (points, then n_points_ + merged arc), as subsets use them.
  void cell_site_ids(std::vector<int>* ids) const;
  // Offers the candidates of the subset of m sites (ids as cell_site_ids gives them).
  void offer_subset(const int* sel, int m);
  // Whether the subset of this key was enumerated (first_time, without inserting it).
  bool enumerated(std::uint64_t key) const;
  void set_aside(const Cell& cell, int arcs_begin, int arcs_end, int faces_begin, int faces_end, int depth,
                 int parent_sites, int stable_levels, double d_high);
  // Fills leaf_points_, leaf_arcs_ and near_ for the cell B(c, rho) from its kept arcs
  // arena_[arcs_begin, arcs_end), the ends within cos_reach (c.u >= cos_reach).
  void gather_sites(const Vec3& c, double rho, double cos_reach, int arcs_begin, int arcs_end);
  // Whether the pair bound (pair_cap_cosine) puts D below the threshold on the whole cap
  // B(c, rho) for some pair of link vertices. For a nearly antipodal pair q is short and
  // the bound nearly flat, where D(c) + rho is not: it drops the cells along the ridges
  // of near-ties (straight ridges, sliver fans) that the Lipschitz bound keeps down to
  // the size of the offsets between the sites. Any pair gives a valid bound; as a matter
  // of cost, pairs are taken among the cell's vertices within reach (near_, which it
  // reorders and trims).
  bool pair_bound_below(const Vec3& c, double rho);
  // Removes from *crossing the faces whose circles lie where another face of the leaf
  // is infeasible.
  void drop_circles_below_another(const Leaf& leaf, std::vector<int>* crossing);
  // drop_repeated_planes on the faces of a face-by-face pass.
  void one_face_per_plane(std::vector<int>* faces);
  // Whether some face repeats the plane of the face before it (same_plane_runs), made on
  // first use with same_plane_.
  bool planes_repeat();
  void record_leaf(const Cell& cell, double d, double v, int faces_begin, int faces_end, bool invisible);
  void offer(const Leaf& leaf, const Vec3& n);
  void offer_anywhere(const Vec3& n);
  static std::uint64_t subset_key(int a, int b, int c);
  static std::size_t subset_hash(std::uint64_t key);
  bool first_time(int a, int b, int c);
  bool insert_subset(std::uint64_t key);
  void enumerate_new_subsets();
  SiteSubset subset(const Leaf& leaf) const;
  bool leaf_alive(const Leaf& leaf, bool feasible_only) const;

  const FanSites& s_;
  CandidatePool& pool_;
  const FanGeometry& g_;
  const int k_;
  RecycledVector<Chart> charts_;
  // Per fan arc: the normals of its foot-inside lune {n.a1 >= 0, n.a2 >= 0}; per merged
  // arc, the same for the merged arc.
  RecycledVector<Vec3> lune1_, lune2_, merged_lune1_, merged_lune2_;
  RecycledVector<int> arena_;  // active fan arcs and faces of the cells on the current path
  RecycledVector<double> arc_cos_;  // scratch: cosine of each fan arc's distance at the cell centre
  RecycledVector<double> face_cos_;  // scratch of pair_infeasible: c.f_i of the kept faces
  RecycledVector<int> arc_stamp_, vertex_stamp_;
  // Scratch of the cell being classified: (c.u_j, j) of the link vertices within reach.
  RecycledVector<std::pair<double, int>> near_;
  // Scratch of the constraint-circle pass: (c.f_i, i) of a leaf's faces.
  RecycledVector<std::pair<double, int>> by_visibility_;
  // same_plane_runs of the fan, made by the first face-by-face pass that needs it
  // (planes_repeat), and whether any run holds more than one face.
  std::vector<int> same_plane_;
  bool planes_repeat_ = false;
  int pair_tries_ = 0, pair_drops_ = 0, pair_skips_ = 0;
  int stamp_ = 0;
  RecycledVector<int> leaf_points_, leaf_arcs_;  // scratch of the cell being classified
  RecycledVector<Leaf> leaves_;
  RecycledVector<int> leaf_ids_;
  // Sorted site triples (ids + 1, 0 for an absent one) already enumerated, open
  // addressing.
  RecycledVector<std::uint64_t> subset_table_;
  // Site sets of the leaves and closed cells (site_set), whose subsets were all enumerated.
  RecycledVector<SiteSet> enumerated_sets_;
  std::size_t subset_count_ = 0;
  int n_points_ = 0;
  bool offer_subsets_ = true;
  bool refining_set_aside_ = false;
  RecycledVector<SetAside> set_aside_, set_aside_batch_;
  RecycledVector<int> set_aside_ids_, set_aside_batch_ids_;
  SubdivisionStats stats_;
};

}  // namespace detail
}  // namespace blayer
