// Faces of the VTK linear cells with outward right-hand normals (internal to quality).
#pragma once

#include <array>

#include "blayer/core/volume_mesh.h"

namespace blayer::detail {

struct FaceDef {
  int n;                  // 3 or 4 nodes
  std::array<int, 4> v;   // local node ids, outward right-hand winding
};

struct CellFaces {
  int n_faces;
  std::array<FaceDef, 6> faces;
  int bottom_cap;  // index of the bottom cap face (wedge, hex) or -1
  int top_cap;     // index of the top cap face (wedge, hex) or -1
};

inline const CellFaces& cell_faces(CellType t) {
  static const CellFaces kTet{4, {{{3, {0, 2, 1, -1}}, {3, {0, 1, 3, -1}}, {3, {1, 2, 3, -1}},
                                   {3, {2, 0, 3, -1}}}}, -1, -1};
  static const CellFaces kPyramid{5, {{{4, {0, 3, 2, 1}}, {3, {0, 1, 4, -1}}, {3, {1, 2, 4, -1}},
                                       {3, {2, 3, 4, -1}}, {3, {3, 0, 4, -1}}}}, -1, -1};
  static const CellFaces kWedge{5, {{{3, {0, 1, 2, -1}}, {3, {3, 5, 4, -1}}, {4, {0, 3, 4, 1}},
                                     {4, {1, 4, 5, 2}}, {4, {2, 5, 3, 0}}}}, 0, 1};
  static const CellFaces kHex{6, {{{4, {0, 3, 2, 1}}, {4, {4, 5, 6, 7}}, {4, {0, 1, 5, 4}},
                                   {4, {1, 2, 6, 5}}, {4, {2, 3, 7, 6}}, {4, {3, 0, 4, 7}}}}, 0, 1};
  switch (t) {
    case CellType::kTet: return kTet;
    case CellType::kPyramid: return kPyramid;
    case CellType::kWedge: return kWedge;
    case CellType::kHex: return kHex;
  }
  return kTet;
}

}  // namespace blayer::detail
