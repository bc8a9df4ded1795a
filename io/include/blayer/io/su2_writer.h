// SU2's native mesh format (.su2, ASCII), read by SU2_CFD and meshio.
//
//   NDIME= 3
//   NELEM= #cells      one line per cell: VTK type id, its nodes (0-based), its index
//   NPOIN= #points     one line per point: x y z, its index
//   NMARK= #patches    per patch: MARKER_TAG= name, MARKER_ELEMS= #faces, then one
//                      line per face: 5 (triangle) or 9 (quad) and its nodes
// SU2 uses VTK's cell type ids and node orders, so cells are written as blayer holds
// them; boundary faces keep SolverMesh's outward orientation. The marker names are the
// patch names; their kinds (wall, farfield, symmetry) are set in SU2's configuration
// file (MARKER_HEATFLUX, MARKER_FAR, MARKER_SYM), not in the mesh. Indices are written
// in full 64-bit range (SU2 reads them as unsigned long).
#pragma once

#include <string>

#include "blayer/io/solver_mesh.h"

namespace blayer {

// Writes path (normally a staged temporary); target names the file in error messages.
void write_su2(const SolverMesh& mesh, const std::string& path, const std::string& target);

}  // namespace blayer
