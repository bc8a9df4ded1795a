// The plateau of an antipodal pair of link vertices (docs/normals.md, Part 4,
// "Tie-break"), solved along its circle instead of by the subdivision, which has to cover
// the whole plateau with small cells to prove its ties (thousands of cells on a sliver
// fan exactly as drawn, where the spanwise neighbours on both sides line up).
//
// Bound. For link vertices u_a, u_b with q = (u_a + u_b) / 2, every direction has
// max(n.u_a, n.u_b) >= n.q >= -|q|, so D(n) <= pi/2 + asin|q| everywhere (a link vertex
// lies on the link).
// Plateau. D(n) >= pi/2 exactly where n.u_j <= 0 for every link vertex: each arc, shorter
// than pi with both ends in the closed hemisphere {x : n.x <= 0}, then lies in it. For an
// antipodal pair these directions lie on the great circle C = {n.h = 0},
// h = unit(u_a - u_b), and the other link vertices' half-circle conditions leave one
// arc I of it: the directions opposite the widest gap between their projections, empty
// when that gap is below pi (or two single directions, when the projections lie on one
// line).
// Tie-break. A maximiser (D >= D* - tie) sees every link vertex at pi/2 - tie or more, so
// it lies within about the tie of I, and the largest V among them is, to that order, the
// largest V along I: the peaks of V's lower envelope along I (envelope_peaks_between),
// offered with the ends of I, which make the status non-unique when I is longer than
// kDistinctMaximizers. Internal to blayer_normals.
#pragma once

#include "candidate_pool.h"

namespace blayer {
namespace detail {

// Offers the candidates of the plateau of the most nearly antipodal pair of link vertices
// (within kAntipodal) to *pool. Returns true when they settle the solve: a fluid one that
// meets the visibility constraint reached the pair's bound within the tie. Otherwise the
// candidates offered stay (each was evaluated exactly) and the caller goes on.
bool antipodal_plateau_settles(CandidatePool* pool);

}  // namespace detail
}  // namespace blayer
