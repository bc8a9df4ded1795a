// Validity of a linear cell in VTK node order, decided by exact orient3d on every corner
// tetrahedron: inverted if any corner tet is negative, flat if none is negative but one
// is zero, valid if all are strictly positive.
#pragma once

#include "blayer/core/vec3.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

enum class Validity { kValid = 0, kFlat = 1, kInverted = 2 };

// corners: corner_count(type) points in VTK order.
Validity cell_validity(CellType type, const Vec3* corners);

// A prism in VTK wedge order: (0,1,2) is the cap whose right-hand normal points away
// from (3,4,5); 0-3, 1-4, 2-5 are the column edges. Valid iff all six corner tets
// (each cap against each node of the other cap) are strictly positive.
bool prism_is_valid(const Vec3 corners[6]);

}  // namespace blayer
