// The symmetry plane's facet of a half model's fill: the part of the half box's face on
// the plane outside the layers' cut, triangulated so that TetGen (which may not split
// it, switch Y) gets well-shaped triangles: a constrained Delaunay triangulation of the
// face's boundary lattice points and the envelope's cut edges, refined to angles of at
// least 20.7 degrees and edges of at most the local target size (half_domain.h),
// with CGAL's 2D mesher, without splitting any constrained edge (they are shared with
// the box faces and the layers). A triangle whose refinement would split a constrained
// edge stays as it is, so next to a small angle of the cut (a trailing edge) angles
// below 20.7 degrees remain: 11 of 2,046 triangles, down to 2.7 degrees, on the pyHyp
// BWB half.
#pragma once

#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "blayer/core/symmetry_plane.h"
#include "blayer/core/vec3.h"

namespace blayer::fill_detail {

struct PlaneFacetInput {
  std::vector<Vec3> points;                  // on the plane: the face's boundary, the cut's points
  std::vector<std::pair<int, int>> edges;    // constraints: the face's boundary, the cut's edges
  Vec3 inside_point;                         // a point of the facet (between boundary and cut)
};

struct PlaneFacet {
  std::vector<Vec3> new_points;  // points the refinement added (index points.size() + j)
  std::vector<std::array<int, 3>> triangles;  // over input points, then new points
};

// Triangles wound with their normals along plane.normal (into the model's half space,
// the domain). plane must be a coordinate plane. Throws InputError when the facet's
// region cannot be found (the inside point lies in no triangle).
PlaneFacet triangulate_plane_facet(const PlaneFacetInput& in, const SymmetryPlane& plane,
                                   const std::function<double(const Vec3&)>& size);

}  // namespace blayer::fill_detail
