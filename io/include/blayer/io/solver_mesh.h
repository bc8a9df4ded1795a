// The mesh as solver formats store it: only the points that cells use, the cells in
// VTK node order, every face once (mesh_faces.h) and the boundary faces grouped into
// named patches. Every solver writer (CGNS, OpenFOAM, SU2, Gmsh) takes this one type,
// so all of them carry the same cells and the same patches.
//
// Patches
//   A boundary face is a face used by exactly one cell. It is assigned by where it lies:
//   a boundary triangle whose nodes are those of a triangle listed for a patch belongs to
//   that patch (the first listing wins); every other boundary face (quads included)
//   belongs to the `rest` patch. So every boundary face belongs to exactly one patch.
//   Patches that receive no face are dropped; the others keep the order given, `rest`
//   last.
//
// Kinds and what each format calls them:
//   kind        OpenFOAM        CGNS              SU2 / Gmsh
//   wall        wall            BCWall            marker / physical group of that name
//   farfield    patch           BCFarfield
//   symmetry    symmetryPlane   BCSymmetryPlane
//   open        patch           BCGeneral         (the layers' outer envelope, open sides)
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/symmetry_plane.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/io/mesh_faces.h"

namespace blayer {

enum class PatchKind { kWall, kFarfield, kSymmetry, kOpen };

struct BoundaryPatch {
  std::string name;
  PatchKind kind = PatchKind::kWall;
  std::size_t start = 0;  // absolute face index of the patch's first face in SolverMesh::faces
  std::size_t size = 0;
};

// Triangles, on the volume mesh's point ids, that lie on one patch. A quad boundary face
// belongs to the patch that lists both of its halves (along either diagonal).
struct PatchTriangles {
  std::string name;
  PatchKind kind = PatchKind::kWall;
  std::vector<std::array<std::int64_t, 3>> triangles;
};

struct SolverMesh {
  VolumeMesh cells;        // points and cells only (no arrays); every point is used by a cell
  MeshFaces faces;         // boundary faces [n_internal, n) ordered patch by patch
  std::vector<BoundaryPatch> patches;
  std::vector<std::int64_t> point_of_input;  // per input point: its index here, or -1 if unused

  std::size_t n_cells_of(CellType t) const;
  std::size_t n_boundary_faces() const { return faces.n_boundary(); }
};

// A boundary face whose nodes all lie within this fraction of the bounding-box diagonal
// of the symmetry plane lies in it: the mesh's points on the plane are on it exactly
// (coordinate planes) or to rounding.
constexpr double kOnPlaneRelTol = 1e-12;

// Builds the solver mesh. With a symmetry plane, boundary faces that no listed patch
// claims and that lie in the plane (the layers' side faces over a half model's cut)
// join the listed symmetry patch, or a new one named "symmetry". Throws InputError when
// two listed patches share a name or the mesh has a face shared by three or more cells.
SolverMesh make_solver_mesh(const VolumeMesh& mesh, const std::vector<PatchTriangles>& listed,
                            const std::string& rest_name, const SymmetryPlane* symmetry = nullptr);

// The wall's patches: one per edge-connected component of the wall (core's
// surface_components), named "wall" when there is one component and "wall_1",
// "wall_2", ... in component order otherwise. wall.points must be the mesh's first
// points (the extruder's contract).
std::vector<PatchTriangles> wall_patches(const TriSurface& wall);

// Triangles of a surface as PatchTriangles, mapping its points through point_ids
// (empty: the identity).
PatchTriangles patch_triangles(const std::string& name, PatchKind kind, const TriSurface& s,
                               const std::vector<std::int64_t>& point_ids = {});

}  // namespace blayer
