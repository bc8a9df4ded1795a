// Validity of a linear cell in VTK node order, decided by exact orient3d on a fixed set
// of tetrahedra spanned by the cell's nodes (its "validity tets"). They come in two
// groups: the corner tets (a node with its three edge-neighbours: the sign of the
// corner Jacobian, which VTK, Gmsh and ParaView test), listed first, then, for wedges
// only, the split tets that only some decompositions of the cell use. The classes:
//   inverted  some corner tet is negative (a negative corner Jacobian);
//   flat      no corner tet is negative and one is zero (a zero corner Jacobian);
//   twisted   every corner tet is positive, but a split tet is negative or zero: every
//             corner looks fine, yet the quad faces are twisted so far that some split
//             into tets folds (only wedges can be twisted; see below);
//   valid     every validity tet is strictly positive.
// inverted and flat together are the cells with a non-positive corner Jacobian.
//
// Node orders (VTK 9.1, see volume_mesh.h):
//   tet     (0,1,2) has its right-hand normal pointing to node 3.
//   pyramid base quad (0,1,2,3) has its right-hand normal pointing to the apex 4.
//   wedge   cap (0,1,2) has its right-hand normal pointing AWAY from cap (3,4,5);
//           column edges 0-3, 1-4, 2-5. A wall triangle (a,b,c) whose normal points
//           into the fluid, extruded to (a',b',c'), is the wedge (a,c,b,a',c',b').
//   hex     base quad (0,1,2,3) has its right-hand normal pointing to (4,5,6,7);
//           column edges 0-4, 1-5, 2-6, 3-7.
//
// Validity tets, each ordered so that it is positive in a valid cell:
//   tet     1: the cell itself.
//   pyramid 4: each of the four triangles of the two base-quad splits, (0,1,2), (0,2,3),
//           (0,1,3), (1,2,3), against the apex. These are also the corner tets of the
//           four base nodes, and every corner tet of the apex is one of them.
//   wedge   12: the six corner tets (a node with its three edge-neighbours) are exactly
//           the six "cap against each node of the other cap" tets. They only say that
//           each cap lies on the correct side of the other; a top cap rotated by 180
//           degrees about the column passes them (a twisted cell). So the six split
//           tets (two nodes of one cap edge, two nodes of the other cap not forming the
//           matching edge) are added:
//           the 12 tets are all the tets of all six splits of the wedge into three
//           tets, and a wedge passes iff every split is a valid tet mesh. This rejects
//           twisted quad faces whose twist makes some split fold; every affine image
//           (e.g. a sheared prism) of a valid right prism passes.
//   hex     58: every tet spanned by four nodes not on one face or one diagonal plane
//           of the reference cube, i.e. all tets of all splits of the hex into tets
//           (the corner tets, the customary check, come first). As for the wedge, the
//           corner tets alone pass a top face twisted by 45 to 90 degrees; these do
//           not. Every affine image of a cube passes. blayer writes hexes on fan
//           strips (extruder/layer_cells.h).
//
// Exactness: each sign is orient3d_sign's (one error bound for the whole cell certifies
// the cells whose every tet is clearly positive; filtered_orient3d.h decides the other
// clear cases in floating point and passes the rest to the exact predicate), so the
// result is exact for the given doubles:
// a prism of relative height 1e-12 is decided correctly and the same on every machine.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "blayer/core/vec3.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

// The values are written as the int cell array `validity`: part of the output contract.
// One byte each: a whole-mesh check keeps one per cell beside its metrics.
enum class Validity : std::uint8_t { kValid = 0, kFlat = 1, kInverted = 2, kTwisted = 3 };

// corners: corner_count(type) points in VTK order.
Validity cell_validity(CellType type, const Vec3* corners);

// cell_validity(type, corners) == Validity::kValid, stopping at the first tet that is
// not strictly positive: the test of the extruder's loops, where most cells are valid
// and a failing one needs no diagnosis.
bool cell_is_valid(CellType type, const Vec3* corners);

// A prism in VTK wedge order: (0,1,2) is the cap whose right-hand normal points away
// from (3,4,5); 0-3, 1-4, 2-5 are the column edges. Valid iff all 12 wedge validity
// tets above are strictly positive: the six corner tets (= each cap against each node
// of the other cap) and the six cap-edge/other-cap tets that catch twisted columns.
// Same answer as cell_validity(CellType::kWedge, corners) == Validity::kValid.
bool prism_is_valid(const Vec3 corners[6]);

// The validity tets of a cell type as local node indices, each positive (orient3d_sign
// of (t[0], t[1], t[2], t[3]) > 0) in a valid cell. count receives their number; the
// first corner_tet_count(type) of them are the corner tets.
const std::array<int, 4>* validity_tets(CellType type, std::size_t* count);
std::size_t corner_tet_count(CellType type);

}  // namespace blayer
