// Hand-made reference cells in VTK node order shared by the quality tests.
#pragma once

#include <array>
#include <vector>

#include "blayer/core/vec3.h"
#include "blayer/core/volume_mesh.h"

namespace blayer::test {

// Unit right tet: (0,1,2) normal +z points to node 3.
inline std::vector<Vec3> unit_tet() { return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}; }

// Unit-square-base pyramid with apex above the centre at height h.
inline std::vector<Vec3> unit_pyramid(double h = 1.0) {
  return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, h}};
}

// Right prism over the wall triangle a=(0,0,0), b=(1,0,0), c=(0,1,0) (normal +z, into
// the fluid) with column height h, written the VTK way (a, c, b, a', c', b').
inline std::vector<Vec3> right_prism(double h = 1.0) {
  return {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, h}, {0, 1, h}, {1, 0, h}};
}

// Unit cube hex.
inline std::vector<Vec3> unit_hex() {
  return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
}

// Mirror image (z -> -z) of a cell: same node order, opposite orientation.
inline std::vector<Vec3> mirrored(std::vector<Vec3> p) {
  for (Vec3& v : p) v[2] = -v[2];
  return p;
}

}  // namespace blayer::test
