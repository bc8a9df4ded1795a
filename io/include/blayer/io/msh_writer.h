// Gmsh's MSH 4.1 format (ASCII), read by gmsh, gmshToFoam (OpenFOAM) and meshio.
//
// Layout
//   $PhysicalNames  one 2-D physical group per boundary patch, tags 1..P in patch
//                   order, named after the patch; one 3-D group "fluid", tag P+1.
//   $Entities       one surface entity per patch (tag = its physical tag, with its
//                   bounding box) and one volume entity (tag 1, group "fluid") bounded
//                   by them.
//   $Nodes          one block, on the volume entity: tags 1..#points in SolverMesh order.
//   $Elements       volume cells grouped by type on the volume entity (tags from 1, in
//                   type order tet, pyramid, prism, hex), then each patch's triangles and
//                   quads on its surface entity (normals out of the domain).
// Node order: gmsh's tetrahedron, pyramid and hexahedron are VTK's; gmsh's prism has
// its base winding opposite to VTK_WEDGE's, so wedge (0,1,2,3,4,5) is written as
// (0,2,1,3,5,4). Tags are size_t in MSH 4.1: no limit below 2^64.
#pragma once

#include <string>

#include "blayer/io/solver_mesh.h"

namespace blayer {

// Writes path (normally a staged temporary); target names the file in error messages.
void write_msh(const SolverMesh& mesh, const std::string& path, const std::string& target);

}  // namespace blayer
