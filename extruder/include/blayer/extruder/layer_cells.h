// The cell one layer of one wall triangle becomes, given which of its three columns
// grow in that layer (SMESH-style closure of stopped columns), and the cell quality
// figure written to the output.
#pragma once

#include <array>
#include <cstdint>

#include "blayer/core/vec3.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

// One cell in VTK node order (only the first corner_count(type) nodes are used).
struct LayerCell {
  CellType type = CellType::kWedge;
  std::array<std::int64_t, 6> nodes{};
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


}  // namespace blayer
