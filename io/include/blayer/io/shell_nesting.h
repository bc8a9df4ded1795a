// How the closed components of a wall surface lie inside each other, and from that
// which side of each one is fluid.
//
// Nesting depth of a closed component c: the number of other closed components that
// enclose it. Space is split by the components into regions; the region just outside
// c has depth(c) enclosing shells and the region just inside has depth(c) + 1. Solid
// and fluid alternate from region to region:
//   external flow (--side outward): the unbounded region (0 shells) is fluid, so a
//     region with an even number of enclosing shells is fluid. A component of even
//     depth is a body's outer skin (fluid outside); one of odd depth bounds a cavity
//     in a body (fluid inside: its layers grow into the cavity, not into the solid).
//   internal flow (--side inward): the region inside the outermost wall is fluid, so
//     regions with an odd number of shells are fluid. A component of even depth is a
//     duct's wall (fluid inside); one of odd depth is a body in the duct (fluid outside).
// So the fluid lies outside c exactly when depth(c) is even for outward and odd for
// inward flow.
//
// Containment is decided by ray parity (blayer/core/point_in_surface.h) from one point
// of c, the centroid of its first triangle, against each component d whose bounding box
// contains c's. Precondition: no two closed components cross or touch (the check of
// surface_intersections.h), so every point of c lies on one side of d and one point
// decides for all of c. Open components (with boundary edges) enclose nothing and are
// neither tested nor counted.
#pragma once

#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/surface_components.h"

namespace blayer {

struct ShellNesting {
  std::vector<int> depth;      // per component; 0 for open ones
  std::vector<int> enclosing;  // per component: the innermost closed component enclosing it, or -1
  // Components for which ray parity could not decide containment in some component
  // (every ray grazed an edge within its margin); their depth is unknown.
  std::vector<int> undecided;
};

// closed[c] != 0 for closed components; components must be edge_connected_components(s, ...).
ShellNesting nest_closed_components(const TriSurface& s, const SurfaceComponents& components,
                                    const std::vector<char>& closed);

// Does the fluid lie outside component c (its normals should point away from its
// enclosed volume)? inward_flow: --side inward.
inline bool fluid_is_outside(int depth, bool inward_flow) { return (depth % 2 == 0) != inward_flow; }

}  // namespace blayer
