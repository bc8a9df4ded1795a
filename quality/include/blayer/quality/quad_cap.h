// The pyramid that caps a quad face of the layer mesh for the tetrahedral fill
// (fill_envelope.h): TetGen takes triangles only, so each quad on the layers' envelope
// gets a pyramid whose four side triangles the tetrahedra meet. The extruder accepts a
// fan strip's cell only when its quad that can end on the envelope can be capped
// (extruder/layer_cells.h), so that every quad it leaves there can be; both call this
// function on the same points.
#pragma once

#include <array>
#include <optional>

#include "blayer/core/vec3.h"

namespace blayer {

// The apex of a valid pyramid (cell_validity.h, exact) on quad q, whose right-hand
// normal points away from the cell below it: on the quad's Newell normal through its
// centre, at the first height of a fixed list (half the shortest edge, then lower, then
// higher, never above the longest edge) that gives a valid pyramid; nullopt when none
// does (a quad with a reflex corner, or one folded along a diagonal). The result does
// not depend on which corner q starts at.
std::optional<Vec3> quad_cap_apex(const std::array<Vec3, 4>& q);

}  // namespace blayer
