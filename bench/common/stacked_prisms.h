// A generated prism stack for the benches: `layers` layers over the wavy wall
// z = 0.05 sin(6x) cos(4y) on the unit square, n x n squares, the layers 1e-3 (1.2^k - 1)
// / 0.2 above it; two wall triangles (a,b,c) with +z normals per grid square, each
// written as the VTK wedge (a, c, b, a', c', b'), with the cell array `layer`.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>

#include "blayer/core/volume_mesh.h"

namespace blayer::bench {

// Appends the (layers + 1) x (n + 1)^2 points, layer by layer, calling
// on_point(x, y, layer height) for each (for point arrays).
inline void add_stacked_points(VolumeMesh& m, int n, int layers,
                               const std::function<void(double, double, double)>& on_point = {}) {
  const int np = n + 1;
  const double h0 = 1e-3;
  for (int k = 0; k <= layers; ++k) {
    const double z = h0 * (std::pow(1.2, k) - 1.0) / 0.2;
    for (int j = 0; j < np; ++j)
      for (int i = 0; i < np; ++i) {
        const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
        m.points.push_back({x, y, 0.05 * std::sin(6.0 * x) * std::cos(4.0 * y) + z});
        if (on_point) on_point(x, y, z);
      }
  }
}

// Appends the wedges over the points of add_stacked_points.
inline void add_stacked_wedges(VolumeMesh& m, int n, int layers) {
  const int np = n + 1;
  m.cell_types.reserve(static_cast<std::size_t>(2) * n * n * layers);
  m.connectivity.reserve(static_cast<std::size_t>(12) * n * n * layers);
  DataArray layer{"layer", 1, ArrayValues(ValueType::kInt32)};
  auto id = [&](int k, int i, int j) {
    return static_cast<std::int64_t>(k) * np * np + static_cast<std::int64_t>(j) * np + i;
  };
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int tri[2][3][2] = {{{i, j}, {i + 1, j}, {i + 1, j + 1}}, {{i, j}, {i + 1, j + 1}, {i, j + 1}}};
        for (const auto& t : tri) {
          const std::int64_t nodes[6] = {id(k, t[0][0], t[0][1]),     id(k, t[2][0], t[2][1]),
                                         id(k, t[1][0], t[1][1]),     id(k + 1, t[0][0], t[0][1]),
                                         id(k + 1, t[2][0], t[2][1]), id(k + 1, t[1][0], t[1][1])};
          m.add_cell(CellType::kWedge, nodes);
          layer.values.push_back(k);
        }
      }
  m.cell_data.push_back(std::move(layer));
}

}  // namespace blayer::bench
