// Floating-point shape metrics of one linear cell in VTK node order (see
// cell_validity.h for the orders). They are reported, never used to decide validity:
// validity is decided by exact orient3d in cell_validity().
//
// "Caps" and "column edges": a wedge has caps (0,1,2), (3,4,5) and column edges 0-3,
// 1-4, 2-5; a hex has caps (0,1,2,3), (4,5,6,7) and column edges 0-4 ... 3-7. Tets and
// pyramids have no caps; metrics that need them are NaN for those types.
#pragma once

#include "blayer/core/vec3.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

struct CellMetrics {
  // Scaled Jacobian, dimensionless, 1 for the ideal cell, <= 0 for a folded corner.
  // At each corner with three edge-neighbours (every node of a tet, wedge, hex; the
  // four base nodes of a pyramid) the Jacobian is det[e1,e2,e3] / (|e1||e2||e3|) with
  // the edge vectors ordered as in the corner validity tets. The minimum over corners
  // (for a hex also the principal-axes Jacobian at the centre, as verdict does) is
  // multiplied by the type's normalisation so that the regular tet (sqrt 2), the
  // equilateral right prism (2/sqrt 3), the equal-edge pyramid (sqrt 2) and the cube (1)
  // score 1, then capped at 1 (only pyramids can exceed it). 0 if a corner has a
  // zero-length edge. Tets follow verdict: all corner determinants are 6V, divided by
  // the largest corner edge-length product (for an inverted tet this is the corner
  // value closest to zero, not the most negative one). For tets and hexes this is verdict's definition (VTK's
  // TetScaledJacobian / HexScaledJacobian). Being corner-based it does not see a twisted
  // wedge column (a half-turn twist keeps every corner positive); cell_validity() and
  // twist_deg do.
  double scaled_jacobian = 0.0;

  // Equiangle skewness in [0, 1]: for a face with angles theta and ideal angle t (60
  // degrees for a triangle, 90 for a quad), max((max theta - t) / (180 - t),
  // (t - min theta) / t). Maximum over the wedge's two caps; over all faces of other
  // types. 0 for an equilateral cap, 1 for a collapsed one.
  double skewness = 0.0;

  // Wedge and hex: mean cap edge length over mean column edge length (a thin boundary
  // layer cell has a large ratio; 1 for a cube). Tet and pyramid: longest over
  // shortest edge. Infinity if the denominator is zero.
  double aspect_ratio = 0.0;

  // Wedge and hex, degrees in [0, 180]: the largest angle between a column edge
  // (bottom node to top node) and a cap normal (unit normal of each cap pointing from
  // the bottom cap to the top cap; a quad cap's normal is the cross product of its
  // diagonals). 0 for a right prism. NaN for tets and pyramids.
  double orthogonality_deg = 0.0;

  // Warpage of the quadrilateral faces, degrees in [0, 180]: for each quad face the
  // angle between the normals of the two triangles of a diagonal split, maximised over
  // both diagonals and over all quad faces. 0 for planar quads and for tets.
  double twist_deg = 0.0;

  // Signed volume of the (trilinear) cell: integral of det J, exact for tets, wedges
  // and hexes (Gauss quadrature of sufficient order); for pyramids the mean of the two
  // splits of the base quad into two tets. Positive for a valid cell.
  double volume = 0.0;
};

// corners: corner_count(type) points in VTK order. Never throws; degenerate cells give
// the limiting values documented above (or NaN where no value is meaningful).
CellMetrics compute_cell_metrics(CellType type, const Vec3* corners);

// Signed volume only (as CellMetrics::volume), cheaper than all metrics.
double cell_volume(CellType type, const Vec3* corners);

}  // namespace blayer
