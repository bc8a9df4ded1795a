// Most-normal normal (docs/normals.md, Part 2; Aubry & Loehner 2008, Aubry et al. 2015):
// n_MN = argmax_{n in R} D(n), where R is the fluid region of the sphere bounded by the
// vertex link (left of every arc u_i -> v_i) and D(n) the angle from n to the nearest
// direction inside an incident triangle: the centre of the largest empty circle among
// the link arcs.
//
// The problem (steps common to every solver here):
//   1. Most-visible normal and V* (most_visible.h). V* < tol.min_visibility: no
//      visible direction, return the best-margin direction (kNoVisibleDirection).
//   2. Fold test: the winding number of the link around n_MV must be 1, otherwise the
//      link overlaps itself, has no fluid side, and the angle average is returned
//      (kDegenerateFan).
//   3. Sites: link arcs merged along common great circles (|f_i.v_{i+1}| <=
//      tol.coplanar_arc, merged length < pi) and reflex link vertices (f_i.v_{i+1} < 0).
//      No reflex vertex: MN = MV.
//   4. Candidates: 1-, 2- and 3-site critical points of the generalized Voronoi diagram
//      of the sites (poles, antipodes, bisector peaks, point-arc parabola extrema,
//      Voronoi vertices), each evaluated exactly (true D, nearest-feature side test).
//   5. Constraint (constrain_visibility, the default): maximise D over R with
//      V >= V_min = V*/2. When the unconstrained optimum violates it, candidates on the
//      circles n.f_i = V_min (with each other, with the bisectors, and single-site
//      extrema along them) are added and the status is kVisibilityConstrained; MV is
//      always a feasible fallback.
//   6. Ties: all candidates with D >= D* - tol.normality_tie are maximisers; when they
//      differ the plateau circles of concentric sites (antipodal reflex vertices, a
//      reflex vertex at an arc's pole, arcs on one circle) are searched for the largest V
//      on the plateau, and the status is kNonUnique.
//
// most_normal_normal (the default) offers only the candidates that can still become
// maximisers, localising the Voronoi diagram instead of enumerating all site triples:
//   a. Link-vertex lens: D(n) <= g(n) = min_j angle(n, u_j). Above 90 degrees the set
//      g >= threshold is an intersection of caps smaller than hemispheres, convex around
//      the antipode of the smallest cap holding the link vertices; a circle-cover test
//      bounds it by a cap (link_vertex_lens.h), and only that cap is searched. The
//      antipode's own D is a lower bound (it never competes in the tie-break); where the
//      antipode fails the constraint, the first direction at V_min on the way to it from
//      n_MV gives the bound instead (visibility_boundary.h).
//   b. Otherwise, fans of at most 12 sites run the enumeration with exact screens:
//      a generator of a candidate that can still win is at D >= threshold from it, so an
//      arc generator's pole lies within 90 deg - threshold of it (on the fluid side), a
//      point generator at least the threshold away (candidate_pool.h, ArcReachScreen).
//   c. Larger fans: a cube-map quadtree of cells, each keeping the sites and faces that
//      can be nearest or lowest in it (D and V are 1-Lipschitz), dropped when its bound
//      D(c) + rho, or the bound of a pair of link vertices, is below the running
//      threshold, or when it lies off the fluid side; each leaf
//      enumerates the subsets of its few sites once (site_subdivision.h, with the proof
//      that every maximiser that is a critical point is built).
//   d. Plateau peaks from the lower envelope of V along the circle; the constraint
//      circles searched leaf by leaf.
//   e. Before c, an antipodal pair of link vertices bounds D by 90 degrees; where its
//      plateau (an arc of the circle between them) reaches that, the maximisers lie
//      along it and its V peaks answer; where it fails the visibility constraint, it
//      settles the unconstrained optimum and c drops the cells that fail the constraint
//      all over (antipodal_plateau.h).
// The enumeration also offers candidates built from sites that are not nearest to them
// (not critical points of D); within the tie of a near-plateau they could decide the
// tie-break or a non-unique status there, and the default solver never builds them
// (tests/normals/agreement.h states the agreement this gives).
// Cost (measured, bench/normals): a few us per wing-skin vertex; linear-ish in the
// sites near the optimum instead of O(|A|^3 + |P|^2|A| + |P||A|^2) candidates.
// Preconditions: closed fan without degenerate triangles (compute_vertex_normal handles
// the others).
#pragma once

#include <array>

#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/point_normals.h"

namespace blayer {

struct MostNormalResult {
  Vec3 normal{0.0, 0.0, 0.0};
  double normality = 0.0;   // D(normal), radians
  double visibility = 0.0;  // V(normal)
  NormalStatus status = NormalStatus::kOk;
  int n_candidates = 0;     // candidates evaluated (diagnostics and benchmarks)
  int n_cells = 0;          // cells of the subdivision visited (diagnostics and benchmarks)
};

MostNormalResult most_normal_normal(const FanGeometry& g, const Tolerances& tol = default_tolerances(),
                                    bool constrain_visibility = true);

// A most-normal solution carried from one front to the next: the sites nearest to the
// normal, which generated it, named by the fan's own indices so that they survive the
// motion of the points (plain data, one per vertex; the fan's ring must keep its order).
//   points  link-vertex indices j (ring positions) of reflex vertices,
//   arcs    fan-arc indices i (arc i runs from ring j = i to i + 1) of arcs whose interior
//           is nearest; a merged arc is named by any fan arc in it;
//   faces   fan-arc (face) indices whose constraint circle n.f = V*/2 holds a visibility-
//           constrained optimum.
// valid is false before the first solve, after a fallback status, and when the fan has
// no reflex vertex (MN = MV, nothing to carry).
struct MostNormalWarmStart {
  std::array<int, 3> points{{-1, -1, -1}};
  std::array<int, 3> arcs{{-1, -1, -1}};
  std::array<int, 2> faces{{-1, -1}};
  int n_points = 0;
  int n_arcs = 0;
  int n_faces = 0;
  bool valid = false;
};

// The same optimum as most_normal_normal, warm-started. Contract:
//   in:  *warm from the previous front at this vertex (or default: no warm start);
//   out: *warm describes this solution, ready for the next front;
//        *hit (optional) is true when the certificate held: the candidate rebuilt from
//        the previous generators on this fan is the answer (within kDistinctMaximizers
//        and the tie tolerance).
// Certificate: the best candidate rebuilt from the previous generators (every 1-, 2- and
// 3-site candidate of them, and of their constraint faces) is evaluated exactly; its D,
// reached by a fluid, feasible direction, is a lower bound of the optimum, and becomes
// the threshold of every screen, cell and evaluation from the start. The passes then
// prove that nothing beats it by more than the tie tolerance (hit), or find what does;
// either way the status and D are those of the cold solve (D within the tie): the bound
// prunes only candidates that could not be maximisers, and the rebuilt candidate itself
// enters neither the maximisers nor the tie-break. The direction is the cold one too
// except inside the tie band, where a tighter bound can change which leaves are built
// and so which candidates of the band compete (measured over ten fronts: 36 of 2.8
// million vertex solves on the ONERA M6 571k, 6 and 2 of 240 and 259 thousand on the 717
// wing and the BWB). If the passes ever found nothing up to the bound, the vertex is
// solved again cold.
MostNormalResult most_normal_normal(const FanGeometry& g, MostNormalWarmStart* warm, bool* hit = nullptr,
                                    const Tolerances& tol = default_tolerances(), bool constrain_visibility = true);

// The same optimum by the full candidate enumeration of step 4 (every subset of at most
// three sites): the test oracle of the default solver.
MostNormalResult most_normal_by_enumeration(const FanGeometry& g, const Tolerances& tol = default_tolerances(),
                                            bool constrain_visibility = true);

// The enumeration with the previous default's shortcut (the cap antipode answers when
// it reaches the link-vertex bound and D falls off steeply around it) and its
// great-circle screen (a bisector whose points the link vertices all prove worse is
// skipped): the speed baseline of the benchmarks.
MostNormalResult most_normal_by_pruned_enumeration(const FanGeometry& g,
                                                   const Tolerances& tol = default_tolerances(),
                                                   bool constrain_visibility = true);

}  // namespace blayer
