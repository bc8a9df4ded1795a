// The outer boundary of an external-flow fill (tet_fill.h, "Farfield"): a generated box
// or the user's surface, in both cases wound with normals into the domain.
#pragma once

#include "blayer/core/surface.h"
#include <utility>
#include <vector>

#include "blayer/core/surface_components.h"
#include "blayer/core/symmetry_plane.h"
#include "size_field.h"

namespace blayer::fill_detail {

// Box centred on [lo, hi] (the envelope's bounding box) with side scale times
// max(extent_k, extent_max / 2) along axis k; its faces are structured triangle grids
// with spacing close to the smallest target size on the box, returned in *spacing.
TriSurface farfield_box(const Vec3& lo, const Vec3& hi, double scale, const SizeField& size, double* spacing);

// A half model's farfield: the box of farfield_box for the mirrored model (the
// envelope's bounding box and its mirror image), cut by the symmetry plane (a
// coordinate plane) on the model's side. Five of its faces are triangle grids wound into
// the domain; the face on the plane is left open, its boundary lattice points are listed
// (plane_boundary) with the lattice segments between them (plane_boundary_edges, as
// pairs of indices into surface.points), for the plane facet to close it.
struct HalfBox {
  TriSurface surface;
  std::vector<int> plane_boundary;
  std::vector<std::pair<int, int>> plane_boundary_edges;
  Vec3 lo, hi;  // the half box
};
HalfBox half_farfield_box(const Vec3& lo_env, const Vec3& hi_env, const SymmetryPlane& plane, double scale,
                          const SizeField& size, double* spacing);

// The user's farfield: checked closed, wound into the domain (flipped when its signed
// volume is positive), and required to enclose a point of every envelope component.
// *size_on_farfield: the largest target size at its points. Throws InputError.
TriSurface user_farfield(const TriSurface& farfield, const TriSurface& envelope,
                         const SurfaceComponents& envelope_components, const SizeField& size,
                         double* size_on_farfield);

}  // namespace blayer::fill_detail
