// The cell one layer of one wall triangle becomes, given which of its three columns
// grow in that layer (SMESH-style closure of stopped columns), and the cell quality
// figure written to the output.
#pragma once

#include <array>
#include <cstdint>

#include "blayer/core/vec3.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/fan_layout.h"

namespace blayer {

// One cell in VTK node order (only the first corner_count(type) nodes are used).
struct LayerCell {
  CellType type = CellType::kWedge;
  std::array<std::int64_t, 8> nodes{};
};

// Wall triangle (a,b,c) with right-hand normal into the fluid; bottom[i] is the point id
// of column i at the layer's base, top[i] its id one layer up (only read when grows[i]).
//   3 grow: wedge   (a, c, b, a', c', b')  VTK's wedge cap (0,1,2) faces away from the top
//   2 grow: pyramid (y, y', z', z, x)       x stopped, (x,y,z) a rotation of (a,b,c); the
//                                           quad is the side face of edge yz, apex x
//   1 grows: tet    (x, y, z, z')           z grows, (x,y,z) a rotation of (a,b,c)
//   0 grow: no cell, returns false.
// A side face then depends only on the two columns of its edge (quad if both grow,
// triangle if one does, nothing otherwise), so neighbouring cells always conform.
bool layer_cell(const std::array<std::int64_t, 3>& bottom, const std::array<std::int64_t, 3>& top,
                const std::array<bool, 3>& grows, LayerCell* out);

// The cells (one or two) of one layer of an element (fan_layout.h), from the point ids
// of its columns at the layer's base and one layer up. Columns of one fan point share
// their wall point, so on the wall layer their bottom ids coincide; they always grow
// together. Returns the number of cells in out (room for two).
//   triangle, three equal bottoms (a corner patch on the wall), all grow:
//            tet (a', c', b', p)        p the corner, (a,b,c) the patch triangle
//   triangle with split_at = i (its column P = column i ends a ridge), P grows with
//            another: all grow: pyramid (y, y', z', z, p) + tet (p', z', y', p), (p, y, z)
//            the triangle from P on, bottoms unprimed; one of y, z stopped: the closure
//            pyramid split into two tets along the diagonal from p (otherwise as
//            layer_cell). Every side face at P is then two triangles split from p, in
//            every layer: those faces twist between P's direction and a fan's.
//   triangle otherwise: layer_cell.
//   strip (q0 q1 q2 q3), fan point x = q0 q1, y = q2 q3, B bottoms, T tops:
//     both grow, on the wall (B0 = B1, B2 = B3):
//            wedge (x, T1, T0, y, T2, T3)    the fan wedge: its ends lie in the fan
//                                            planes, its column edges 0-3 along the ridge
//     both grow above it: hex (B0, B1, B2, B3, T0, T1, T2, T3)
//     x grows, y stopped, on the wall: tet (x, T0, T1, y)
//     x grows, y stopped, above it: wedge (B1, B2, T1, B0, B3, T0): the hex with y's
//            column edges collapsed; its column edges 0-3, 1-4, 2-5 run across the fan
//     y grows alone: the same with the quad read from q2.
//   strip end (P, X, Y) on the wall (X, Y at fan point q, P at p), q grows:
//            tet (q, X', Y', p), and with P growing also tet (P', Y', X', p): the side
//            faces at P are split along p-X' and p-Y', as the triangles at p are
//   strip end above the wall: as a triangle split at P.
//   Nothing grows: 0.
// Faces shared with neighbours depend only on the columns they contain (a strip's end
// face on its fan point's columns, its side faces on one column of each point; at a
// ridge end always split from p), so neighbouring cells conform.
int element_layer_cells(const LayerElement& e, const std::array<std::int64_t, 4>& bottom,
                        const std::array<std::int64_t, 4>& top, const std::array<bool, 4>& grows, LayerCell* out);

// Whether a cell of element e's layer is accepted: exactly valid (cell_validity.h), and,
// for a fan strip's cell, with the quad face that can end on the layers' envelope (a
// hexahedron's top, a wedge's face (1, 4, 5, 2): the fan wedge's top on the wall, or the
// face of a closure wedge from the stopped point's tops to the new ones) able to take
// the pyramid that caps it for the tetrahedral fill (quality/quad_cap.h). Such a face
// of a twisted thin strip can be valid in its cell and yet have a reflex corner.
// corners: the cell's node positions in its order.
bool layer_cell_accepted(const LayerElement& e, const LayerCell& cell, const Vec3* corners);

// The same, with the ids and growth read per column c of the element: bottom_id(c),
// top_id(c), grows(c).
template <class BottomId, class TopId, class Grows>
int element_layer_cells(const LayerElement& e, BottomId bottom_id, TopId top_id, Grows grows, LayerCell* out) {
  std::array<std::int64_t, 4> bottom{}, top{};
  std::array<bool, 4> g{};
  for (int i = 0; i < e.n_columns(); ++i) {
    const int c = e.column[i];
    bottom[i] = bottom_id(c);
    top[i] = top_id(c);
    g[i] = grows(c);
  }
  return element_layer_cells(e, bottom, top, g, out);
}

}  // namespace blayer
