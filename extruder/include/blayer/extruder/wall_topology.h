// The wall's connectivity, computed once per run and shared by every marching stage:
// the fronts keep the wall's triangles, so every front has the same tables.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/vertex_fans.h"

namespace blayer {

// Compressed adjacency lists: the items of v are items[start[v] .. start[v+1]).
struct Csr {
  std::vector<int> start;
  std::vector<int> items;
  const int* begin(int v) const { return items.data() + start[v]; }
  const int* end(int v) const { return items.data() + start[v + 1]; }
  int size(int v) const { return start[v + 1] - start[v]; }
};

struct WallTopology {
  VertexFans fans;                 // ordered one-rings (normals)
  Csr vertex_triangles;            // triangles incident to each point, ascending
  Csr vertex_neighbours;           // points sharing an edge with each point, ascending
  std::vector<char> used;          // point carries at least one triangle (has a column)
  int n_points() const { return static_cast<int>(used.size()); }
};

// O(#F log) construction; the neighbour lists are built in parallel.
WallTopology build_wall_topology(const TriSurface& wall);

}  // namespace blayer
