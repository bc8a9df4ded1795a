// A mesh of separate wedges, each on its own six points (VTK order), with a cell array
// `layer` numbering them: small meshes of chosen cells for the check's tests.
#pragma once

#include <cstdint>
#include <vector>

#include "blayer/core/volume_mesh.h"

namespace blayer::test {

inline VolumeMesh separate_wedges(const std::vector<std::vector<Vec3>>& cells) {
  VolumeMesh m;
  DataArray layer{"layer", 1, ArrayValues(ValueType::kInt32)};
  for (const auto& cell : cells) {
    const auto base = static_cast<std::int64_t>(m.points.size());
    std::int64_t nodes[6];
    for (int i = 0; i < 6; ++i) {
      m.points.push_back(cell[i]);
      nodes[i] = base + i;
    }
    m.add_cell(CellType::kWedge, nodes);
    layer.values.push_back(static_cast<double>(layer.values.size()));
  }
  m.cell_data.push_back(layer);
  return m;
}

}  // namespace blayer::test
