// The connectivity of the columns, computed once per run and shared by every marching
// stage: the fronts keep the same triangles, so every front has the same tables.
// Without fans the columns are the wall points and the front's triangles are the
// wall's; with fans (fan_layout.h) a wall point at a sharp convex edge has several
// columns, and the front's triangles are the wall triangles on their sector columns
// plus the fan strips and corner patches.
#pragma once

#include <vector>

#include <optional>

#include "blayer/core/surface.h"
#include "blayer/core/symmetry_plane.h"
#include "blayer/core/vertex_adjacency.h"
#include "blayer/core/vertex_fans.h"
#include "blayer/extruder/fan_layout.h"

namespace blayer {

using Csr = CsrTable;

struct WallTopology {
  VertexFans fans;                 // ordered one-rings (normals)
  Csr vertex_triangles;            // triangles incident to each point, ascending
  Csr vertex_neighbours;           // points sharing an edge with each point, ascending
  std::vector<char> used;          // point carries at least one triangle (has a column)
  std::vector<char> on_plane;      // boundary point on the symmetry plane (column in it)
  std::optional<SymmetryPlane> plane;
  std::vector<int> wall_point;     // per column: its wall point (the column itself without fans)
  Csr group_columns;               // per group: the columns of one fan point (they grow together)
  int n_points() const { return static_cast<int>(used.size()); }
  bool has_fans() const { return group_columns.n_rows() > 0; }
};

// Boundary points within this fraction of the bounding-box diagonal of the symmetry
// plane are on it: the input was snapped onto it (exactly for a coordinate plane, to
// rounding, ~1e-16 relative, otherwise).
constexpr double kOnSymmetryPlaneRelTol = 1e-12;

// O(#F) plus a sort of each point's neighbours (core/vertex_adjacency.h). One column
// per point of `wall`.
WallTopology build_wall_topology(const TriSurface& wall, const std::optional<SymmetryPlane>& plane = {});

// The tables of a column layout's front, with its columns' wall points and fan groups.
WallTopology build_column_topology(const ColumnLayout& layout, const std::optional<SymmetryPlane>& plane = {});

}  // namespace blayer
