// The exact candidate enumeration of the most-normal problem (docs/normals.md, Part 4,
// "Exact candidates"): every 1-, 2- and 3-site candidate of all the fan's sites, the
// constraint-circle candidates and the plateau peaks. Cost O(|A|^3 + |P|^2|A| +
// |P||A|^2) candidates: the reference (oracle) the faster solvers are tested against.
// Internal to blayer_normals.
#pragma once

#include <vector>

#include "candidate_pool.h"
#include "fan_sites.h"

namespace blayer {
namespace detail {

// Every unconstrained candidate. With `screen`, a bisector circle whose every point the
// link vertices prove worse than the running optimum has its candidate families skipped
// (they would all be rejected; see circle_screened_off in the .cpp).
void enumerate_unconstrained(const FanSites& s, bool screen, CandidatePool* pool);

// The same with, in addition, the arc-reach screen (ArcReachScreen in candidate_pool.h):
// candidates whose arc generators would lie nearer than the running threshold, or on
// the solid side of their arc, are not built. Only candidates that cannot be fluid
// maximisers are lost (solid-side ones, and those that are not critical points of D, their
// arc not being nearest), so every maximiser that is a critical point is still found.
void enumerate_screened(const FanSites& s, CandidatePool* pool);

// Every candidate on the constraint circles n.f_i = V_min (the pool is put in its
// constrained pass first).
void enumerate_constraint_circles(const FanSites& s, CandidatePool* pool);

// The visibility peaks along the plateau circles of every concentric pair of sites: of V
// over all the faces, or in the second form over `faces` (V's peaks are built from
// them; every candidate is still evaluated over all faces).
void enumerate_plateau_peaks(const FanSites& s, CandidatePool* pool);
void enumerate_plateau_peaks(const FanSites& s, CandidatePool* pool, const std::vector<int>& faces);

// Diagnostics for tests and benches: the maximisers (directions within the tie of the
// optimum, with their D and V) that most_normal_by_enumeration (or, with `by_default`,
// most_normal_normal) chooses its answer from; empty for the fallback statuses.
std::vector<Maximizer> most_normal_maximizers(const FanGeometry& g, const Tolerances& tol, bool constrain_visibility,
                                              bool by_default);

}  // namespace detail
}  // namespace blayer
