// Connected components of a triangle surface and the volume each one encloses.
//
// Two triangles are in one component when they share an edge used by exactly two
// triangles (either winding), so surfaces that only touch at a vertex, or meet along a
// non-manifold edge, are separate components. Components are numbered 0, 1, ... in
// the order of their first triangle.
//
// The signed volume of a component is (1/6) sum over its triangles of
// (a - r) . ((b - r) x (c - r)) (divergence theorem), with r the centroid of all the
// surface's points (differences near the data keep the digits that large coordinates
// would cancel). It is positive when a closed component's triangles face outward, and
// independent of r only for closed components; for open ones it is a number, not a
// volume.
#pragma once

#include <vector>

#include "blayer/core/edge_topology.h"
#include "blayer/core/surface.h"

namespace blayer {

struct SurfaceComponents {
  int count = 0;
  std::vector<int> of_triangle;  // #F labels in [0, count)
};

// edges must be build_edge_topology(s).
SurfaceComponents edge_connected_components(const TriSurface& s, const EdgeTopology& edges);

// One signed volume per component (size components.count).
std::vector<double> component_signed_volumes(const TriSurface& s, const SurfaceComponents& components);

}  // namespace blayer
