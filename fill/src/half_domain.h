// The fill of a half model: the domain between the layers' envelope (open along the
// symmetry plane), the half farfield box and the plane facet that closes it
// (tet_fill.h, "Symmetry plane"). Together they bound the half domain, so the bodies
// cut by the plane need no hole point: the region inside them is outside that closed
// boundary. Only envelope components that do not touch the plane (whole bodies) do.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/symmetry_plane.h"
#include "size_field.h"
#include "tet_plc.h"

namespace blayer::fill_detail {

// The envelope must be edge-manifold and consistently oriented, with every boundary
// edge exactly on the plane (a coordinate plane; the extruder keeps the cut's columns
// in it). Throws InputError naming the first offending edge.
void check_half_envelope(const TriSurface& envelope, const SymmetryPlane& plane);

// The half box (markers kFarfieldMarker) and the plane facet (kSymmetryMarker) between
// its face on the plane and the envelope's cut. *spacing: the box's grid spacing.
OuterBoundary half_domain_boundary(const TriSurface& envelope, const SymmetryPlane& plane, const Vec3& lo_env,
                                   const Vec3& hi_env, double scale, const SizeField& size, double* spacing);

// Hole points for the envelope's closed components (bodies away from the plane).
std::vector<Vec3> closed_body_hole_points(const TriSurface& envelope, double length_scale);

}  // namespace blayer::fill_detail
