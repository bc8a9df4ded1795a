// Finding the symmetry plane of a half model: the plane its open boundary lies in.
//
// A surface whose every boundary edge lies in one plane is a half model cut by that
// plane (`--symmetry auto`, the default for open surfaces), or the plane is given
// (`--symmetry-plane`). Then:
//   - every boundary point must lie within kSymmetryPlaneRelTol x the bounding-box
//     diagonal of the plane, and is snapped onto it (exactly, for a coordinate plane);
//   - no triangle may lie in the plane (all three points within the tolerance): a face
//     in the plane would be both wall and symmetry;
//   - the surface must lie on one side of the plane; the plane's normal is turned
//     towards it.
// Boundary edges off the plane remain holes (an error unless open surfaces are allowed).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "blayer/core/edge_topology.h"
#include "blayer/core/surface.h"
#include "blayer/core/symmetry_plane.h"

namespace blayer {

// Boundary points within this fraction of the bounding-box diagonal of a plane lie in
// it. CAD exports and float STL files put a cut's points within ~1e-7 relative of the
// plane; a real hole's rim lies far farther from any plane through the rest.
constexpr double kSymmetryPlaneRelTol = 1e-6;

enum class SymmetryMode { kAuto, kNone, kPlane };

struct SymmetryRequest {
  SymmetryMode mode = SymmetryMode::kAuto;
  SymmetryPlane plane;  // kPlane: the plane (its side is decided from the surface)
};

struct SymmetryFinding {
  std::optional<SymmetryPlane> plane;  // none: no symmetry plane
  std::vector<int> plane_points;       // boundary points snapped onto it, ascending
  double max_snap = 0.0;               // largest distance a point was moved
  std::vector<std::string> problems;   // why the request cannot hold (empty: fine)
};

// Decides the plane for surface s with edge table edges (kNone or no boundary: no
// plane). Does not move points; snap_to_symmetry_plane does.
SymmetryFinding find_symmetry_plane(const TriSurface& s, const EdgeTopology& edges, const SymmetryRequest& request);

// Projects the finding's plane points onto the plane.
void snap_to_symmetry_plane(const SymmetryFinding& f, TriSurface* s);

}  // namespace blayer
