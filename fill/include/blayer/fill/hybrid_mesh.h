// The hybrid mesh: the prism layers plus the tetrahedral fill of the region beyond
// them (tet_fill.h), and the boundary surface of the whole mesh with a marker per
// triangle, for solver converters.
//
// Contract
//   layers    the layer mesh (VolumeMesh in VTK order); its points 0..#W-1 are the wall
//             points, with the wall's indices, and envelope_point_ids[i] is the layer-
//             mesh point of envelope point i (the extruder's ExtrusionResult).
//   fill      fill_with_tets(envelope, ...): its first #E points are the envelope's,
//             bit-identical; its farfield triangles carry kFarfieldMarker.
// Preconditions (BLAYER_ASSERT, each O(#points)): envelope_point_ids has one valid
// layer-mesh point per envelope point and the fill's envelope points equal those
// layer-mesh points exactly; the wall's points equal the mesh's first points; the map
// returned by append_fill matches the fill.
#pragma once

#include <cstdint>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/symmetry_plane.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/fill/tet_fill.h"

namespace blayer {

// Marker of a boundary triangle of the hybrid mesh (cell array "marker" of the
// boundary file). The values are part of the file format: never renumber them.
enum class BoundaryMarker : int {
  kWall = 1,      // the wall surface the layers grow on
  kFarfield = 2,  // the farfield box or the user's farfield surface
  kSymmetry = 3,  // a half model's symmetry plane (the fill's plane facet, the layers' faces on it)
};

// Appends the fill's tets to the layer mesh: envelope point i of the fill becomes mesh
// point envelope_point_ids[i], every other fill point is appended, in the fill's order.
// Point arrays get 0 on the new points; cell arrays get 0 on the tets, except "layer",
// which gets -1; a new int cell array "region" is 0 on the layer cells and 1 on the
// tets and on the cells already marked "layer" -1 (fill_envelope's pyramid caps). Returns the mesh point of every fill point (size fill.tets.points.size()).
std::vector<std::int64_t> append_fill(const FillResult& fill, const std::vector<std::int64_t>& envelope_point_ids,
                                      VolumeMesh* mesh);

struct MarkedBoundary {
  TriSurface surface;       // points: all the mesh's points, same indices
  std::vector<int> marker;  // per triangle, a BoundaryMarker value
};

// The boundary of the hybrid mesh: the wall's triangles (kWall), then the fill's
// farfield triangles (kFarfield) and plane facet triangles (kSymmetry), then, given the
// half model's symmetry plane, the other cell faces on it (the layers'; kSymmetry; a
// quad as its two halves along its q0-q2 diagonal, as quads appear in every triangle
// list of blayer: io/mesh_faces.h), on the mesh's points, every triangle oriented outward: its
// right-hand normal points out of the meshed domain (into the body at the wall, away
// from the domain at the farfield), the convention of solver boundary faces. The
// triangles then close the domain, the plane included. A face is in the plane when its
// points are exactly on it: the fill takes coordinate planes only, on which the layers'
// points are exact. For region inside (internal flow) the boundary is the wall alone.
// fill_to_mesh is what append_fill returned.
MarkedBoundary hybrid_boundary(const VolumeMesh& mesh, const TriSurface& wall, const FillResult& fill,
                               const std::vector<std::int64_t>& fill_to_mesh, const SymmetryPlane* plane = nullptr);

}  // namespace blayer
