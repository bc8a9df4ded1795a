// The wall's connectivity, computed once per run and shared by every marching stage:
// the fronts keep the wall's triangles, so every front has the same tables.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/vertex_adjacency.h"
#include "blayer/core/vertex_fans.h"

namespace blayer {

using Csr = CsrTable;

struct WallTopology {
  VertexFans fans;                 // ordered one-rings (normals)
  Csr vertex_triangles;            // triangles incident to each point, ascending
  Csr vertex_neighbours;           // points sharing an edge with each point, ascending
  std::vector<char> used;          // point carries at least one triangle (has a column)
  int n_points() const { return static_cast<int>(used.size()); }
};

// O(#F) plus a sort of each point's neighbours (core/vertex_adjacency.h).
WallTopology build_wall_topology(const TriSurface& wall);

}  // namespace blayer
