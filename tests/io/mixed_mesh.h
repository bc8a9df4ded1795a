// A small volume mesh with one cell of each type blayer writes (tet, pyramid, wedge,
// hex) and point and cell arrays of each storage kind (Float64, Float32, Int32), for
// tests of the file formats. The cells need not form a conforming mesh.
#pragma once

#include <cstdint>

#include "blayer/core/volume_mesh.h"

namespace blayer::testing {

inline VolumeMesh mixed_mesh() {
  VolumeMesh m;
  // 0-7 unit cube, 8 apex above it, 9-14 a prism beside it, 15 apex of a tet on the floor.
  m.points = {{0, 0, 0},   {1, 0, 0},   {1, 1, 0}, {0, 1, 0}, {0, 0, 1},   {1, 0, 1},   {1, 1, 1},   {0, 1, 1},
              {0.5, 0.5, 2}, {2, 0, 0}, {2, 1, 0}, {3, 0, 0}, {2, 0, 0.5}, {2, 1, 0.5}, {3, 0, 0.5}, {0.25, 0.25, -1}};
  const std::int64_t hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  const std::int64_t pyramid[5] = {4, 5, 6, 7, 8};
  const std::int64_t wedge[6] = {9, 10, 11, 12, 13, 14};
  const std::int64_t tet[4] = {0, 2, 1, 15};
  m.add_cell(CellType::kHex, hex);
  m.add_cell(CellType::kPyramid, pyramid);
  m.add_cell(CellType::kWedge, wedge);
  m.add_cell(CellType::kTet, tet);
  m.add_cell(CellType::kWedge, wedge);  // a second wedge, so counts by type differ

  const std::size_t np = m.points.size();
  DataArray normal{"normal", 3, std::vector<double>{}};
  DataArray height{"column_height", 1, std::vector<double>{}};
  DataArray layers{"layers", 1, ArrayValues(ValueType::kInt32)};
  for (std::size_t i = 0; i < np; ++i) {
    for (double x : {0.0, 0.6, 0.8}) normal.values.push_back(x);
    height.values.push_back(0.1 * static_cast<double>(i) + 1.0 / 3.0);
    layers.values.push_back(static_cast<double>(i % 4));
  }
  m.point_data = {normal, height, layers};
  DataArray volume{"volume", 1, ArrayValues(ValueType::kFloat32, std::vector<double>{1.0, 1.0 / 3.0, 0.25, 1.0 / 6.0, 0.25})};
  m.cell_data = {{"layer", 1, ArrayValues(ValueType::kInt32, {0, 1, 0, -1, 0})}, volume};
  return m;
}

}  // namespace blayer::testing
