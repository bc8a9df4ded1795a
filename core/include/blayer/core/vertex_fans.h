// Ordered one-ring ("fan") of every vertex of an oriented triangle surface.
#pragma once

#include <vector>

#include "blayer/core/surface.h"

namespace blayer {

// The fan of vertex p: triangles (p, ring[j], ring[j+1]) in the surface's own winding,
// ordered so that consecutive triangles share the edge (p, ring[j+1]).
// closed: the ring wraps around (ring.size() == triangles.size());
// open (boundary vertex): ring.size() == triangles.size() + 1 and the first and last
// ring vertices lie on the boundary.
struct VertexFan {
  std::vector<int> ring;
  std::vector<int> triangles;
  bool closed = false;
};

struct VertexFans {
  std::vector<VertexFan> fans;       // one per point; empty for unused points
  std::vector<int> non_manifold;     // points whose triangles do not form a single fan
};

// O(#F) construction. A vertex whose incident triangles form several fans, or that
// has inconsistent winding around it, is listed in non_manifold and gets an empty fan.
VertexFans build_vertex_fans(const TriSurface& s);

}  // namespace blayer
