// A mixed-element volume mesh as plain arrays, in VTK's cell types and node orders,
// with named point and cell arrays. This is what the extruder and the tetrahedral fill
// produce, what the quality module judges and what io/ writes to .vtu.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "blayer/core/data_array.h"
#include "blayer/core/errors.h"
#include "blayer/core/vec3.h"

namespace blayer {

// Values are VTK's cell type ids, so they can be written as-is.
enum class CellType : std::uint8_t { kTet = 10, kHex = 12, kWedge = 13, kPyramid = 14 };

inline int corner_count(CellType t) {
  switch (t) {
    case CellType::kTet: return 4;
    case CellType::kPyramid: return 5;
    case CellType::kWedge: return 6;
    case CellType::kHex: return 8;
  }
  return 0;
}

inline const char* cell_type_name(CellType t) {
  switch (t) {
    case CellType::kTet: return "tet";
    case CellType::kPyramid: return "pyramid";
    case CellType::kWedge: return "wedge";
    case CellType::kHex: return "hex";
  }
  return "unknown";
}

// A point id in a cell's connectivity. 32 bits: the connectivity is the largest array
// of a layer mesh, and 64-bit ids made it a fifth of a run's peak memory. Meshes of
// 2^31 points and more (48 GiB of coordinates) are refused where they would be made
// (kMaxMeshPoints). Offsets stay 64-bit: a mesh of 360M wedges has more corners.
using PointId = std::int32_t;
inline constexpr std::int64_t kMaxMeshPoints = std::numeric_limits<PointId>::max();

// Throws InputError, "<what>: N points, more than a mesh can index", past kMaxMeshPoints.
inline void require_indexable_points(std::size_t n, const std::string& what) {
  if (n > static_cast<std::size_t>(kMaxMeshPoints))
    throw InputError(what + ": " + std::to_string(n) + " points, more than a mesh can index (" +
                     std::to_string(kMaxMeshPoints) + ")");
}

struct VolumeMesh {
  std::vector<Vec3> points;
  std::vector<CellType> cell_types;
  std::vector<std::int64_t> offsets{0};  // cell c uses connectivity[offsets[c], offsets[c+1])
  std::vector<PointId> connectivity;
  std::vector<DataArray> point_data;
  std::vector<DataArray> cell_data;

  std::size_t n_cells() const { return cell_types.size(); }

  // The corners of cell c.
  const PointId* cell_nodes(std::size_t c) const { return connectivity.data() + offsets[c]; }

  // Ids of any integer type, each in [0, kMaxMeshPoints).
  template <class Id>
  void add_cell(CellType t, const Id* nodes) {
    cell_types.push_back(t);
    for (int i = 0; i < corner_count(t); ++i) connectivity.push_back(static_cast<PointId>(nodes[i]));
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }

  const DataArray* find_cell_array(const std::string& name) const {
    for (const DataArray& a : cell_data)
      if (a.name == name) return &a;
    return nullptr;
  }
  const DataArray* find_point_array(const std::string& name) const {
    for (const DataArray& a : point_data)
      if (a.name == name) return &a;
    return nullptr;
  }
};

}  // namespace blayer
