// The wall's connectivity, computed once per run and shared by every marching stage:
// the fronts keep the wall's triangles, so every front has the same tables.
#pragma once

#include <vector>

#include <optional>

#include "blayer/core/surface.h"
#include "blayer/core/symmetry_plane.h"
#include "blayer/core/vertex_adjacency.h"
#include "blayer/core/vertex_fans.h"

namespace blayer {

using Csr = CsrTable;

struct WallTopology {
  VertexFans fans;                 // ordered one-rings (normals)
  Csr vertex_triangles;            // triangles incident to each point, ascending
  Csr vertex_neighbours;           // points sharing an edge with each point, ascending
  std::vector<char> used;          // point carries at least one triangle (has a column)
  std::vector<char> on_plane;      // boundary point on the symmetry plane (column in it)
  std::optional<SymmetryPlane> plane;
  int n_points() const { return static_cast<int>(used.size()); }
};

// Boundary points within this fraction of the bounding-box diagonal of the symmetry
// plane are on it: the input was snapped onto it (exactly for a coordinate plane, to
// rounding, ~1e-16 relative, otherwise).
constexpr double kOnSymmetryPlaneRelTol = 1e-12;

// O(#F) plus a sort of each point's neighbours (core/vertex_adjacency.h).
WallTopology build_wall_topology(const TriSurface& wall, const std::optional<SymmetryPlane>& plane = {});

}  // namespace blayer
