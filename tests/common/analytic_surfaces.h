// Small analytic surfaces built in code, shared by the test suites: icosphere,
// subdivided box, flat square plate (open), reversed orientation, union of two surfaces.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>
#include <map>
#include <utility>

#include "blayer/core/surface.h"

namespace blayer::test_surfaces {

// A flat square plate in z = 0 of side `size`, n x n squares each split into two
// triangles facing +z (open: its border is a boundary). Point (i, j) has index
// plate_index(n, i, j).
inline int plate_index(int n, int i, int j) { return j * (n + 1) + i; }
inline TriSurface square_plate(int n, double size) {
  TriSurface s;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) s.points.push_back({size * i / n, size * j / n, 0.0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({plate_index(n, i, j), plate_index(n, i + 1, j), plate_index(n, i + 1, j + 1)});
      s.triangles.push_back({plate_index(n, i, j), plate_index(n, i + 1, j + 1), plate_index(n, i, j + 1)});
    }
  return s;
}

// Icosphere of the given radius and centre: the icosahedron with each triangle split
// into four `levels` times, points projected onto the sphere. Normals point outward.
inline TriSurface icosphere(int levels, double radius = 1.0, Vec3 centre = {0, 0, 0}) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  TriSurface s;
  s.points = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
              {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (Vec3& p : s.points) p = normalized(p);
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      s.points.push_back(normalized(s.points[a] + s.points[b]));
      const int id = static_cast<int>(s.points.size()) - 1;
      mid[key] = id;
      return id;
    };
    std::vector<Triangle> next;
    for (const Triangle& t : s.triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    s.triangles = std::move(next);
  }
  for (Vec3& p : s.points) p = centre + radius * p;
  return s;
}

// Axis-aligned box [lo, hi] with n x n quads per face split into triangles. Normals
// point outward (inward = false) or into the box (inward = true).
inline TriSurface box(Vec3 lo, Vec3 hi, int n, bool inward = false) {
  TriSurface s;
  std::map<std::array<int, 3>, int> id;
  auto point = [&](std::array<int, 3> ijk) {
    auto it = id.find(ijk);
    if (it != id.end()) return it->second;
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = ijk[k] == n ? hi[k] : lo[k] + (hi[k] - lo[k]) * ijk[k] / n;
    s.points.push_back(p);
    return id[ijk] = static_cast<int>(s.points.size()) - 1;
  };
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      Vec3 out{0, 0, 0};
      out[axis] = (side ? 1.0 : -1.0) * (inward ? -1.0 : 1.0);
      for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
          int c[4];
          for (int q = 0; q < 4; ++q) {
            std::array<int, 3> ijk;
            ijk[axis] = side ? n : 0;
            ijk[u] = a + (q == 1 || q == 2);
            ijk[v] = b + (q >= 2);
            c[q] = point(ijk);
          }
          for (Triangle t : {Triangle{c[0], c[1], c[2]}, Triangle{c[0], c[2], c[3]}}) {
            if (dot(triangle_area_vector(s, t), out) < 0) std::swap(t[1], t[2]);
            s.triangles.push_back(t);
          }
        }
    }
  }
  return s;
}

// Latitude-longitude sphere: poles plus n_lat - 1 rings of n_lon points; ring i is turned
// by i x ring_twist radians so that no meridian lines up (vertex valences stay mixed).
// Normals point outward.
inline TriSurface uv_sphere(int n_lat, int n_lon, double radius, double ring_twist) {
  TriSurface s;
  s.points.push_back({0, 0, radius});
  for (int i = 1; i < n_lat; ++i)
    for (int j = 0; j < n_lon; ++j) {
      const double th = M_PI * i / n_lat, ph = 2 * M_PI * j / n_lon + ring_twist * i;
      s.points.push_back({radius * std::sin(th) * std::cos(ph), radius * std::sin(th) * std::sin(ph),
                          radius * std::cos(th)});
    }
  s.points.push_back({0, 0, -radius});
  const int south = static_cast<int>(s.points.size()) - 1;
  auto id = [&](int i, int j) { return 1 + (i - 1) * n_lon + (j % n_lon); };
  for (int j = 0; j < n_lon; ++j) s.triangles.push_back({0, id(1, j), id(1, j + 1)});
  for (int i = 1; i < n_lat - 1; ++i)
    for (int j = 0; j < n_lon; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (int j = 0; j < n_lon; ++j) s.triangles.push_back({south, id(n_lat - 1, j + 1), id(n_lat - 1, j)});
  return s;
}

inline TriSurface flipped(TriSurface s) {
  for (Triangle& t : s.triangles) std::swap(t[1], t[2]);
  return s;
}

// Two surfaces as one (the second's indices shifted).
inline TriSurface merged(TriSurface a, const TriSurface& b) {
  const int off = static_cast<int>(a.points.size());
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for (Triangle t : b.triangles) a.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
  return a;
}

}  // namespace blayer::test_surfaces
