// Small conforming meshes of every cell type on an n x m x k grid of unit cubes, for
// the face topology and the solver writers: hexes; each cube split into two wedges
// (along its x-y diagonal, so the side faces stay quads); six pyramids around the
// cube's centre; six tets (the Kuhn split along the main diagonal); and a mixed grid
// whose first x-column is wedges and whose other columns alternate hex and pyramid
// layers in z, so all quad faces between cell types match. Cells are positively
// oriented in VTK's sense (the tests confirm it with the quality module).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "blayer/core/volume_mesh.h"

namespace blayer::testing {

enum class GridCell { kHex, kWedges, kPyramids, kTets };

class GridBuilder {
 public:
  GridBuilder(int nx, int ny, int nz) : nx_(nx), ny_(ny), nz_(nz) {
    for (int k = 0; k <= nz; ++k)
      for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) mesh_.points.push_back({double(i), double(j), double(k)});
  }

  // Corner c (VTK hex numbering) of cube (i, j, k).
  std::int64_t corner(int i, int j, int k, int c) const {
    static const int dx[8] = {0, 1, 1, 0, 0, 1, 1, 0}, dy[8] = {0, 0, 1, 1, 0, 0, 1, 1},
                     dz[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    return (k + dz[c]) * (nx_ + 1) * (ny_ + 1) + (j + dy[c]) * (nx_ + 1) + (i + dx[c]);
  }

  void add(int i, int j, int k, GridCell type) {
    std::int64_t p[8];
    for (int c = 0; c < 8; ++c) p[c] = corner(i, j, k, c);
    switch (type) {
      case GridCell::kHex: mesh_.add_cell(CellType::kHex, p); break;
      case GridCell::kWedges: {
        // Bottom triangles (0,1,2) and (0,2,3) face up; VTK wants the base facing away
        // from the top, so each is written reversed.
        const std::int64_t a[6] = {p[0], p[2], p[1], p[4], p[6], p[5]};
        const std::int64_t b[6] = {p[0], p[3], p[2], p[4], p[7], p[6]};
        mesh_.add_cell(CellType::kWedge, a);
        mesh_.add_cell(CellType::kWedge, b);
        break;
      }
      case GridCell::kPyramids: {
        Vec3 centre{0, 0, 0};
        for (int c = 0; c < 8; ++c) centre += 0.125 * mesh_.points[p[c]];
        const std::int64_t apex = static_cast<std::int64_t>(mesh_.points.size());
        mesh_.points.push_back(centre);
        // Each face of the cube with its normal pointing into the cube, apex at the centre.
        const int faces[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}};
        for (const auto& f : faces) {
          const std::int64_t q[5] = {p[f[0]], p[f[1]], p[f[2]], p[f[3]], apex};
          mesh_.add_cell(CellType::kPyramid, q);
        }
        break;
      }
      case GridCell::kTets: {
        // Kuhn split: the six paths from corner 0 to corner 6 along the cube's edges.
        const int paths[6][2] = {{1, 2}, {1, 5}, {3, 2}, {3, 7}, {4, 5}, {4, 7}};
        for (const auto& path : paths) {
          std::int64_t t[4] = {p[0], p[path[0]], p[path[1]], p[6]};
          // Orient positively: VTK's tet wants (p1-p0)x(p2-p0) . (p3-p0) > 0.
          const Vec3 a = mesh_.points[t[1]] - mesh_.points[t[0]], b = mesh_.points[t[2]] - mesh_.points[t[0]],
                     c = mesh_.points[t[3]] - mesh_.points[t[0]];
          if (dot(cross(a, b), c) < 0) std::swap(t[1], t[2]);
          mesh_.add_cell(CellType::kTet, t);
        }
        break;
      }
    }
  }

  VolumeMesh take() { return std::move(mesh_); }

 private:
  int nx_, ny_, nz_;
  VolumeMesh mesh_;
};

inline VolumeMesh grid_mesh(int nx, int ny, int nz, GridCell type) {
  GridBuilder g(nx, ny, nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) g.add(i, j, k, type);
  return g.take();
}

// Column x = 0 wedges; columns x >= 1 hexes on even z layers, pyramids on odd ones.
inline VolumeMesh mixed_grid_mesh(int nx, int ny, int nz) {
  GridBuilder g(nx, ny, nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        g.add(i, j, k, i == 0 ? GridCell::kWedges : k % 2 == 0 ? GridCell::kHex : GridCell::kPyramids);
  return g.take();
}

}  // namespace blayer::testing
