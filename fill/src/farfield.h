// The outer boundary of an external-flow fill (tet_fill.h, "Farfield"): a generated box
// or the user's surface, in both cases wound with normals into the domain.
#pragma once

#include "blayer/core/surface.h"
#include "blayer/core/surface_components.h"
#include "size_field.h"

namespace blayer::fill_detail {

// Box centred on [lo, hi] (the envelope's bounding box) with side scale times
// max(extent_k, extent_max / 2) along axis k; its faces are structured triangle grids
// with spacing close to the smallest target size on the box, returned in *spacing.
TriSurface farfield_box(const Vec3& lo, const Vec3& hi, double scale, const SizeField& size, double* spacing);

// The user's farfield: checked closed, wound into the domain (flipped when its signed
// volume is positive), and required to enclose a point of every envelope component.
// *size_on_farfield: the largest target size at its points. Throws InputError.
TriSurface user_farfield(const TriSurface& farfield, const TriSurface& envelope,
                         const SurfaceComponents& envelope_components, const SizeField& size,
                         double* size_on_farfield);

}  // namespace blayer::fill_detail
