// The piecewise linear complex handed to TetGen: the envelope's and the farfield's
// triangles on the points they use, renumbered (TetGen sees no unused point), and the
// hole points that keep the bodies empty.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "fill_input.h"
#include "tetgen_adapter.h"

namespace blayer::fill_detail {

// The points a surface's triangles use, in their original order: used[j] is the
// surface point of local point j, local_of[i] the local index of point i (-1 unused).
struct UsedPoints {
  std::vector<int> local_of;
  std::vector<int> used;
};
UsedPoints used_points(const TriSurface& s);

struct FillPlc {
  TetgenPlc tetgen;          // local indices: used envelope points, then used farfield points
  std::vector<Vec3> points;  // the local points
  UsedPoints envelope, farfield;
  std::size_t n_envelope_triangles = 0;
};

// The outer boundary of the fill: the farfield's triangles with a marker each
// (kFarfieldMarker; kSymmetryMarker on a half model's symmetry plane). A triangle
// index i >= surface.points.size() names envelope point i - surface.points.size(): the
// symmetry plane's facet meets the envelope along its cut.
struct OuterBoundary {
  TriSurface surface;
  std::vector<int> markers;
  // A point's own target size where it is not the fill's size field (> 0): the new
  // points of a half model's plane facet (half_domain.h); empty or 0 elsewhere.
  std::vector<double> point_size;
  int envelope_point(int i) const { return i - static_cast<int>(surface.points.size()); }
  bool is_envelope_point(int i) const { return i >= static_cast<int>(surface.points.size()); }
};

// Envelope triangles (marker kEnvelopeMarker) then the outer boundary's triangles with
// their markers. Throws InputError when two boundary points coincide.
FillPlc assemble_plc(const TriSurface& envelope, UsedPoints envelope_points, const OuterBoundary& outer);

// "envelope triangle 12 near (x, y, z)" for a face given in local indices.
std::string describe_plc_face(const FillPlc& plc, const std::array<int, 3>& face);

// One hole point per body component (positive volume), behind one of its largest
// triangles and confirmed by ray parity against the whole envelope to lie outside the
// fill region. Meaningful only once the boundary is known not to intersect itself.
// Throws InputError when no candidate is confirmed.
std::vector<Vec3> hole_points(const TriSurface& envelope, const EnvelopeParts& parts, bool outside,
                              double length_scale);

}  // namespace blayer::fill_detail
