// The layers' envelope as the tetrahedral fill needs it: a closed triangle surface on
// the layer mesh's own points, every face of which is a face of a layer cell.
//
// The extruder's envelope has one point per column and the front's triangles
// (extruder/extrude_layers.h). With fans of columns two things differ from what the
// fill can take: the columns of a fan that did not grow share one mesh point (their
// strip triangles then name a point twice), and the top of a fan strip is a quad face
// of a hexahedron or wedge, which two fill tetrahedra could only meet non-conformingly.
//
// Contract
//   in   envelope, envelope_point_ids (one mesh point per envelope point) and the layer
//        mesh (valid and conforming, VTK order, cells positively oriented).
//   out  the surface on the distinct mesh points of the envelope, without the
//        triangles that name a mesh point twice; every quad face of a layer cell that
//        lies on the envelope (both of its halves are envelope triangles) is capped by
//        a pyramid whose apex is appended to the mesh and whose four side triangles
//        replace the two halves. The pyramids are appended to the mesh as cells (point
//        arrays 0 on the apexes; cell arrays 0, "layer" -1 on the pyramids).
//   Without fans the surface is the envelope itself (same triangles, same points) and
//   nothing is appended.
// Apex: quality/quad_cap.h's, on the quad's outward (Newell) normal through its centre.
// The extruder accepts a fan strip's cell only if that quad can be capped, so a quad for
// which no apex passes is an internal failure: std::runtime_error naming its nodes.
// Cost: O(#cells) for the layer mesh's faces (io/mesh_faces.h). (Every layer mesh has
// quad faces, its wedges' sides, so no cheaper test tells a fanned envelope apart.)
#pragma once

#include <cstdint>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

struct FillEnvelope {
  TriSurface surface;
  std::vector<std::int64_t> point_ids;  // surface point i = mesh point point_ids[i]
  std::int64_t n_caps = 0;              // pyramids appended to the mesh
};

FillEnvelope fill_envelope(const TriSurface& envelope, const std::vector<std::int64_t>& envelope_point_ids,
                           VolumeMesh* layers);

}  // namespace blayer
