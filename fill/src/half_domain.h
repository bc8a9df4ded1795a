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

// How much larger than the fill's size field the plane facet's triangles are, and the
// size its new points carry to TetGen. In the full (mirrored) model no boundary lies on
// the plane and the tetrahedra crossing it have mean edges of 0.86 times the field (the
// pyHyp BWB, within 1 of the root); a facet refined to edges of at most the field has
// mean edges of 0.68 times it, and its points pin the tetrahedra on the plane to that:
// the half fill had 1.7 times the full's density next to the plane and 1.06 to 1.12
// times half its cells. With facet triangles of mean edge 0.96 times the field, the
// tetrahedra next to the plane have mean edges of 0.89 times it, as in the full model.
// Chosen on the BWB; bench/compare_half_full.sh on the M6, 717 and BWB halves measures
// the half fill at 0.45 to 0.49 of the full model's cells. Coarsening the facet alone
// changes nothing: its points' sizes still pin the tetrahedra.
inline constexpr double kPlaneFacetSizeFactor = 1.5;

// The half box (markers kFarfieldMarker) and the plane facet (kSymmetryMarker) between
// its face on the plane and the envelope's cut. *spacing: the box's grid spacing.
// outer.point_size holds the facet's new points' sizes (kPlaneFacetSizeFactor).
OuterBoundary half_domain_boundary(const TriSurface& envelope, const SymmetryPlane& plane, const Vec3& lo_env,
                                   const Vec3& hi_env, double scale, const SizeField& size, double* spacing);

// Hole points for the envelope's closed components (bodies away from the plane).
std::vector<Vec3> closed_body_hole_points(const TriSurface& envelope, double length_scale);

}  // namespace blayer::fill_detail
