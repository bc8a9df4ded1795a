#include "blayer/io/mesh_faces.h"

#include <algorithm>
#include <limits>
#include <string>

#include "blayer/core/errors.h"

namespace blayer {

namespace {

CellFaceTable make_table(std::initializer_list<std::initializer_list<int>> faces) {
  CellFaceTable t;
  for (const auto& f : faces) {
    t.corners[t.n_faces].fill(-1);
    std::copy(f.begin(), f.end(), t.corners[t.n_faces].begin());
    t.n_corners[t.n_faces] = static_cast<int>(f.size());
    ++t.n_faces;
  }
  return t;
}

constexpr std::int64_t kNoNode = std::numeric_limits<std::int64_t>::max();

// One cell face: its nodes in the cell's outward order and sorted (the match key).
struct CellFace {
  std::array<std::int64_t, 4> nodes{-1, -1, -1, -1};
  std::array<std::int64_t, 4> key{};  // sorted nodes, a triangle's padded with kNoNode at the end
  int n = 0;
};

CellFace cell_face(const VolumeMesh& mesh, std::size_t cell, int local) {
  const CellFaceTable& table = cell_face_table(mesh.cell_types[cell]);
  const PointId* corners = mesh.cell_nodes(cell);
  CellFace f;
  f.n = table.n_corners[local];
  for (int k = 0; k < f.n; ++k) f.nodes[k] = corners[table.corners[local][k]];
  f.key = f.nodes;
  if (f.n == 3) f.key[3] = kNoNode;
  std::sort(f.key.begin(), f.key.end());
  for (int k = 1; k < f.n; ++k)
    if (f.key[k] == f.key[k - 1])
      throw InputError("cell " + std::to_string(cell) + " (" + cell_type_name(mesh.cell_types[cell]) +
                       "): face " + std::to_string(local) + " repeats node " + std::to_string(f.key[k]));
  return f;
}

std::string describe_face(const CellFace& f) {
  std::string s;
  for (int k = 0; k < f.n; ++k) s += (k ? " " : "") + std::to_string(f.key[k]);
  return s;
}

}  // namespace

const CellFaceTable& cell_face_table(CellType t) {
  static const CellFaceTable tet = make_table({{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  static const CellFaceTable pyramid = make_table({{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  static const CellFaceTable wedge = make_table({{0, 1, 2}, {3, 5, 4}, {0, 3, 4, 1}, {1, 4, 5, 2}, {2, 5, 3, 0}});
  static const CellFaceTable hex =
      make_table({{0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 3, 2, 1}, {4, 5, 6, 7}});
  switch (t) {
    case CellType::kTet: return tet;
    case CellType::kPyramid: return pyramid;
    case CellType::kWedge: return wedge;
    case CellType::kHex: return hex;
  }
  return tet;
}

MeshFaces build_mesh_faces(const VolumeMesh& mesh) {
  const std::size_t n_cells = mesh.n_cells();
  // Slot s = first_slot[c] + local face: one per cell face.
  std::vector<std::int64_t> first_slot(n_cells + 1, 0);
  for (std::size_t c = 0; c < n_cells; ++c)
    first_slot[c + 1] = first_slot[c] + cell_face_table(mesh.cell_types[c]).n_faces;
  const std::int64_t n_slots = first_slot[n_cells];

  // Bucket the slots by their face's smallest node (counting sort).
  const std::size_t n_points = mesh.points.size();
  std::vector<std::int64_t> bucket_start(n_points + 1, 0);
  for (std::size_t c = 0; c < n_cells; ++c)
    for (int f = 0; f < cell_face_table(mesh.cell_types[c]).n_faces; ++f) ++bucket_start[cell_face(mesh, c, f).key[0] + 1];
  for (std::size_t p = 0; p < n_points; ++p) bucket_start[p + 1] += bucket_start[p];
  std::vector<std::int64_t> bucket_fill(bucket_start.begin(), bucket_start.end() - 1);
  std::vector<std::int64_t> bucketed(n_slots);
  for (std::size_t c = 0; c < n_cells; ++c)
    for (int f = 0; f < cell_face_table(mesh.cell_types[c]).n_faces; ++f)
      bucketed[bucket_fill[cell_face(mesh, c, f).key[0]]++] = first_slot[c] + f;

  // Within a bucket, faces with equal keys are one face. partner[s]: the other slot, or -1.
  std::vector<std::int64_t> slot_cell(n_slots);
  for (std::size_t c = 0; c < n_cells; ++c)
    for (std::int64_t s = first_slot[c]; s < first_slot[c + 1]; ++s) slot_cell[s] = static_cast<std::int64_t>(c);
  auto face_of_slot = [&](std::int64_t s) {
    const std::int64_t c = slot_cell[s];
    return cell_face(mesh, c, static_cast<int>(s - first_slot[c]));
  };
  std::vector<std::int64_t> partner(n_slots, -1);
  for (std::size_t p = 0; p < n_points; ++p) {
    const std::int64_t begin = bucket_start[p], end = bucket_start[p + 1];
    for (std::int64_t i = begin; i < end; ++i) {
      const CellFace fi = face_of_slot(bucketed[i]);
      for (std::int64_t j = i + 1; j < end; ++j) {
        const CellFace fj = face_of_slot(bucketed[j]);
        if (fi.n != fj.n || fi.key != fj.key) continue;
        const std::int64_t a = bucketed[i], b = bucketed[j];
        if (partner[a] != -1 || partner[b] != -1) {
          const std::int64_t third = partner[a] != -1 ? partner[a] : partner[b];
          throw InputError("mesh face (nodes " + describe_face(fi) + ") is shared by more than two cells: " +
                           std::to_string(slot_cell[a]) + ", " + std::to_string(slot_cell[b]) + ", " +
                           std::to_string(slot_cell[third]));
        }
        partner[a] = b;
        partner[b] = a;
      }
    }
  }

  // Internal faces from their owner (the smaller cell), in owner-then-neighbour order;
  // then the boundary faces in cell order.
  MeshFaces out;
  auto emit = [&](const CellFace& f, std::int64_t owner, std::int64_t neighbour) {
    out.nodes.push_back(f.nodes);
    out.n_nodes.push_back(static_cast<std::uint8_t>(f.n));
    out.owner.push_back(owner);
    out.neighbour.push_back(neighbour);
  };
  std::vector<std::pair<std::int64_t, int>> upper;  // (neighbour, local face) of one owner
  for (std::size_t c = 0; c < n_cells; ++c) {
    upper.clear();
    for (std::int64_t s = first_slot[c]; s < first_slot[c + 1]; ++s)
      if (partner[s] != -1 && slot_cell[partner[s]] > static_cast<std::int64_t>(c))
        upper.emplace_back(slot_cell[partner[s]], static_cast<int>(s - first_slot[c]));
    std::sort(upper.begin(), upper.end());
    for (const auto& [neighbour, local] : upper) emit(cell_face(mesh, c, local), static_cast<std::int64_t>(c), neighbour);
  }
  out.n_internal = out.size();
  for (std::size_t c = 0; c < n_cells; ++c)
    for (std::int64_t s = first_slot[c]; s < first_slot[c + 1]; ++s)
      if (partner[s] == -1)
        emit(cell_face(mesh, c, static_cast<int>(s - first_slot[c])), static_cast<std::int64_t>(c), -1);
  return out;
}

std::array<TriangleKey, 2> quad_halves(const std::array<std::int64_t, 4>& q, int d) {
  return {sorted_triangle(q[d], q[d + 1], q[d + 2]), sorted_triangle(q[d + 2], q[(d + 3) % 4], q[d])};
}

}  // namespace blayer
