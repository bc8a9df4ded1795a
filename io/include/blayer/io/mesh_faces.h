// The faces of a mixed-element volume mesh, each once, with the cell on either side:
// what face-based formats (OpenFOAM's polyMesh) store, and where every boundary format
// finds its boundary (the faces used by exactly one cell).
//
// Contract
//   in   a VolumeMesh in VTK node order whose cells are positively oriented (the
//        quality check's verdict) and conforming: two cells share a face only whole,
//        with the same nodes.
//   out  every distinct face, its nodes ordered so that the right-hand normal points
//        out of its owner cell:
//          internal faces [0, n_internal): owner < neighbour, sorted by owner, then by
//            neighbour (OpenFOAM's upper-triangular order); the normal points from the
//            owner into the neighbour;
//          boundary faces [n_internal, n): neighbour = -1, sorted by owner, then by the
//            owner's local face number; the normal points out of the mesh.
// Algorithm: faces are bucketed by their smallest node (a counting sort, O(#faces)),
// and two faces match when their sorted node lists are equal; no hashing, no global
// sort, so memory is about 24 bytes per cell face.
// Failure: a face shared by three or more cells, or a cell face with a repeated node,
// throws InputError naming the cells and the nodes.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "blayer/core/triangle_ids.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

struct MeshFaces {
  std::vector<std::array<std::int64_t, 4>> nodes;  // per face; a triangle leaves nodes[3] = -1
  std::vector<std::uint8_t> n_nodes;               // 3 or 4
  std::vector<std::int64_t> owner;
  std::vector<std::int64_t> neighbour;             // -1 for a boundary face
  std::size_t n_internal = 0;

  std::size_t size() const { return owner.size(); }
  std::size_t n_boundary() const { return size() - n_internal; }
};

// Local faces of one cell type, in VTK's corner numbering, each with its right-hand
// normal pointing out of the cell (VTK's own face tables). Unused slots are -1.
struct CellFaceTable {
  int n_faces = 0;
  std::array<std::array<int, 4>, 6> corners{};
  std::array<int, 6> n_corners{};
};
const CellFaceTable& cell_face_table(CellType t);

MeshFaces build_mesh_faces(const VolumeMesh& mesh);

// The two triangles that quad face q splits into along diagonal d (0: q0-q2, 1: q1-q3;
// no other value), as sorted triangles: a quad of the mesh (the top of a fan strip)
// appears in triangle lists (the envelope, the boundary patches) as the two halves of
// one diagonal.
std::array<TriangleKey, 2> quad_halves(const std::array<std::int64_t, 4>& q, int d);

}  // namespace blayer
