// CGNS: the mesh as one unstructured zone of a 3-D base, through the CGNS mid-level
// library (Debian's libcgns, HDF5 files), checked with cgnscheck.
//
// Layout
//   Base "blayer" (cell and physical dimension 3), Zone "fluid" (Unstructured).
//   GridCoordinates: CoordinateX/Y/Z in double precision, in the input surface's unit
//   (DataClass NormalizedByUnknownDimensional on the base: blayer has no unit).
//   Element sections, numbered from 1 in this order: one per volume cell type present
//   (Tetrahedra TETRA_4, Pyramids PYRA_5, Prisms PENTA_6, Hexahedra HEXA_8), so CGNS
//   element numbers follow the cell types, not blayer's cell order; then one section per
//   boundary patch, named after it (TRI_3 or QUAD_4), its faces' normals pointing out
//   of the domain; a patch of both has two, "<name>_tri" and "<name>_quad", with
//   consecutive element numbers (no MIXED section: that needs the ElementStartOffset
//   array, which readers built on CGNS before 3.4 do not know).
//   ZoneBC: one BC_t per patch, named after it, over its section's element range
//   (PointRange, GridLocation FaceCenter), with the BC type of its kind (wall BCWall,
//   farfield BCFarfield, symmetry BCSymmetryPlane, open BCGeneral) and FamilyName =
//   the patch name; one Family_t per patch in the base, with the same FamilyBC.
// Node order: CGNS's TETRA_4, PYRA_5 and HEXA_8 are VTK's; PENTA_6 has the base winding
// opposite to VTK_WEDGE's, so wedge (0,1,2,3,4,5) is written as (0,2,1,3,5,4).
// Limits: Debian's library has 32-bit cgsize_t; a mesh with more than 2^31-1 points,
// elements (cells plus boundary faces) or connectivity entries in one section is
// refused with an IoError saying so, before anything is written.
#pragma once

#include <string>

#include "blayer/io/solver_mesh.h"

namespace blayer {

// Writes path (normally a staged temporary); target names the file in error messages.
void write_cgns(const SolverMesh& mesh, const std::string& path, const std::string& target);

}  // namespace blayer
