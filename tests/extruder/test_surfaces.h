// Small analytic surfaces built in code for the extruder tests, their parameters, and
// independent mesh checks (exact validity of every cell, face sharing, volumes).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/extrusion_params.h"
#include "blayer/quality/cell_validity.h"
#include "blayer/quality/orient3d.h"
#include "analytic_surfaces.h"

namespace blayer::test {

using test_surfaces::flipped;
using test_surfaces::icosphere;
using test_surfaces::square_plate;

// Parameters with the growth law N layers from first height h1 growing by ratio r.
// Single columns (fans off): the marching stages these tests pin down index columns by
// wall point; fans_test.cpp turns fans on where it tests them.
inline ExtrusionParams growth_params(int n, double h1, double r) {
  ExtrusionParams p;
  p.fan_angle_deg = 0.0;
  p.growth.layers = n;
  p.growth.first_height = h1;
  p.growth.growth_ratio = r;
  return p;
}

// The same surface read in another order: its points renumbered and its triangles
// shuffled, each with its corners rotated (the winding kept).
inline TriSurface shuffled(const TriSurface& s, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<int> to(s.points.size());
  std::iota(to.begin(), to.end(), 0);
  std::shuffle(to.begin(), to.end(), rng);
  TriSurface out;
  out.points.resize(s.points.size());
  for (std::size_t v = 0; v < s.points.size(); ++v) out.points[to[v]] = s.points[v];
  for (const Triangle& t : s.triangles) {
    const int r = static_cast<int>(rng() % 3);
    out.triangles.push_back({to[t[r]], to[t[(r + 1) % 3]], to[t[(r + 2) % 3]]});
  }
  std::shuffle(out.triangles.begin(), out.triangles.end(), rng);
  return out;
}

// Boundary of a union of unit voxels (i,j,k) in [0,n)^3 where filled(i,j,k), scaled by
// `cell`; faces outward from the solid. The union must be a manifold solid (no voxels
// touching along an edge or corner only).
inline TriSurface voxel_surface(std::array<int, 3> n, const std::function<bool(int, int, int)>& filled,
                                double cell) {
  TriSurface s;
  std::map<std::array<int, 3>, int> ids;
  auto id = [&](std::array<int, 3> g) {
    auto it = ids.find(g);
    if (it != ids.end()) return it->second;
    s.points.push_back({g[0] * cell, g[1] * cell, g[2] * cell});
    return ids[g] = static_cast<int>(s.points.size()) - 1;
  };
  auto in = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2] && filled(i, j, k);
  };
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        if (!in(i, j, k)) continue;
        for (int a = 0; a < 3; ++a)
          for (int sgn : {-1, 1}) {
            std::array<int, 3> nb{i, j, k};
            nb[a] += sgn;
            if (in(nb[0], nb[1], nb[2])) continue;
            const int u = (a + 1) % 3, w = (a + 2) % 3;
            std::array<int, 3> base{i, j, k};
            if (sgn > 0) base[a] += 1;
            std::array<int, 3> c0 = base, c1 = base, c2 = base, c3 = base;
            c1[u] += 1;
            c2[u] += 1;
            c2[w] += 1;
            c3[w] += 1;
            // cross(e_u, e_w) = e_a: counter-clockwise seen from +a.
            std::array<int, 4> q{id(c0), id(c1), id(c2), id(c3)};
            if (sgn < 0) std::swap(q[1], q[3]);
            s.triangles.push_back({q[0], q[1], q[2]});
            s.triangles.push_back({q[0], q[2], q[3]});
          }
      }
  return s;
}

inline std::vector<Vec3> cell_corners(const VolumeMesh& m, std::size_t c) {
  std::vector<Vec3> p;
  for (std::int64_t i = m.offsets[c]; i < m.offsets[c + 1]; ++i) p.push_back(m.points[m.connectivity[i]]);
  return p;
}

// Faces of a cell in VTK order as node lists (orientation irrelevant here).
inline std::vector<std::vector<std::int64_t>> cell_faces(const VolumeMesh& m, std::size_t c) {
  const PointId* n = m.cell_nodes(c);
  switch (m.cell_types[c]) {
    case CellType::kTet: return {{n[0], n[1], n[2]}, {n[0], n[1], n[3]}, {n[1], n[2], n[3]}, {n[0], n[2], n[3]}};
    case CellType::kPyramid:
      return {{n[0], n[1], n[2], n[3]}, {n[0], n[1], n[4]}, {n[1], n[2], n[4]}, {n[2], n[3], n[4]}, {n[3], n[0], n[4]}};
    case CellType::kWedge:
      return {{n[0], n[1], n[2]}, {n[3], n[4], n[5]}, {n[0], n[1], n[4], n[3]}, {n[1], n[2], n[5], n[4]},
              {n[2], n[0], n[3], n[5]}};
    case CellType::kHex:
      return {{n[0], n[1], n[2], n[3]}, {n[4], n[5], n[6], n[7]}, {n[0], n[1], n[5], n[4]},
              {n[1], n[2], n[6], n[5]}, {n[2], n[3], n[7], n[6]}, {n[3], n[0], n[4], n[7]}};
  }
  return {};
}

// Number of cells per face (faces keyed by their sorted node set).
inline std::map<std::vector<std::int64_t>, int> face_use(const VolumeMesh& m) {
  std::map<std::vector<std::int64_t>, int> use;
  for (std::size_t c = 0; c < m.n_cells(); ++c)
    for (auto f : cell_faces(m, c)) {
      std::sort(f.begin(), f.end());
      ++use[f];
    }
  return use;
}

// Volume of a cell by splitting it into tets from its first node (exact for planar
// faces; boundary-layer quads are nearly planar, and the split is consistent between
// neighbours because each quad is split along the diagonal through its smallest id).
inline double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dot(cross(b - a, c - a), d - a) / 6.0;
}

// Signed volume via the divergence theorem over the faces with outward orientation.
// Each quad is split along the diagonal through its smallest node id, so a quad shared
// by two cells is split the same way in both and the volumes add up exactly.
inline double cell_volume_divergence(const VolumeMesh& m, std::size_t c) {
  const PointId* n = m.cell_nodes(c);
  std::vector<std::vector<std::int64_t>> faces;  // outward orientation
  switch (m.cell_types[c]) {
    case CellType::kTet: faces = {{n[0], n[2], n[1]}, {n[0], n[1], n[3]}, {n[1], n[2], n[3]}, {n[2], n[0], n[3]}}; break;
    case CellType::kPyramid:
      faces = {{n[0], n[3], n[2], n[1]}, {n[0], n[1], n[4]}, {n[1], n[2], n[4]}, {n[2], n[3], n[4]}, {n[3], n[0], n[4]}};
      break;
    case CellType::kWedge:
      faces = {{n[0], n[1], n[2]}, {n[3], n[5], n[4]}, {n[0], n[3], n[4], n[1]}, {n[1], n[4], n[5], n[2]},
               {n[2], n[5], n[3], n[0]}};
      break;
    case CellType::kHex:
      faces = {{n[0], n[3], n[2], n[1]}, {n[4], n[5], n[6], n[7]}, {n[0], n[1], n[5], n[4]},
               {n[1], n[2], n[6], n[5]}, {n[2], n[3], n[7], n[6]}, {n[3], n[0], n[4], n[7]}};
      break;
  }
  const Vec3 o{0, 0, 0};
  double v = 0.0;
  for (const auto& f : faces) {
    if (f.size() == 3) {
      v += tet_volume(o, m.points[f[0]], m.points[f[1]], m.points[f[2]]);
    } else {
      const int s = static_cast<int>(std::min_element(f.begin(), f.end()) - f.begin());
      const auto& P = m.points;
      v += tet_volume(o, P[f[s]], P[f[(s + 1) % 4]], P[f[(s + 2) % 4]]);
      v += tet_volume(o, P[f[s]], P[f[(s + 2) % 4]], P[f[(s + 3) % 4]]);
    }
  }
  return v;
}

}  // namespace blayer::test
