// Downward smoothing of a per-column factor (height scale or step factor), so that a
// locally limited column ramps back to full height over a few rings instead of leaving
// a step in the layers.
#pragma once

#include <vector>

#include "blayer/extruder/extrusion_params.h"
#include "blayer/extruder/wall_topology.h"

namespace blayer {

// Lowers f so that it rises by at most 1/(rings+1) per ring away from a low spot: after
// `rings` Jacobi passes f[v] <= f[u] + d(u,v)/(rings+1) for every u within `rings`
// rings (d = ring distance), so a limited column ramps back to full height without a
// step. Only points with mask set take part. Never raises a value. The reason of the
// value that lowered a point travels with it; where neighbours lower it to the same
// value, the lowest StopReason of theirs does, so that the reasons do not depend on the
// order of the points (a neighbour that only ties the point's own value leaves its
// reason). rings <= 0: no change.
void smooth_downward(const Csr& neighbours, const std::vector<char>& mask, int rings, std::vector<double>* f,
                     std::vector<StopReason>* reason);

}  // namespace blayer
