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

// The part of s on the side coord[axis] >= 0 (points within 1e-12 of the plane are put
// on it exactly): the triangles whose three points lie there, on their points only. A
// half model cut by the plane coord[axis] = 0, when s is symmetric about it and has
// points on it.
inline TriSurface cut_at_coordinate_plane(TriSurface s, int axis) {
  for (Vec3& p : s.points)
    if (std::fabs(p[axis]) < 1e-12) p[axis] = 0.0;
  std::vector<int> id(s.points.size(), -1);
  TriSurface out;
  for (const Triangle& t : s.triangles) {
    if (s.points[t[0]][axis] < 0 || s.points[t[1]][axis] < 0 || s.points[t[2]][axis] < 0) continue;
    Triangle u;
    for (int k = 0; k < 3; ++k) {
      if (id[t[k]] < 0) {
        id[t[k]] = static_cast<int>(out.points.size());
        out.points.push_back(s.points[t[k]]);
      }
      u[k] = id[t[k]];
    }
    out.triangles.push_back(u);
  }
  return out;
}

// A half model and its mirror image about coord[axis] = 0, merged along the cut: the
// full model whose half it is (the mirrored triangles reversed, so the whole stays
// consistently oriented). Points 0..#half-1 are the half's, the mirror's off-plane
// points follow.
inline TriSurface mirrored_about_coordinate_plane(const TriSurface& half, int axis) {
  TriSurface full = half;
  std::vector<int> mirror(half.points.size());
  for (std::size_t i = 0; i < half.points.size(); ++i) {
    if (half.points[i][axis] == 0.0) {
      mirror[i] = static_cast<int>(i);
      continue;
    }
    Vec3 q = half.points[i];
    q[axis] = -q[axis];
    mirror[i] = static_cast<int>(full.points.size());
    full.points.push_back(q);
  }
  for (const Triangle& t : half.triangles) full.triangles.push_back({mirror[t[0]], mirror[t[2]], mirror[t[1]]});
  return full;
}

// A closed cylinder of radius r along z from 0 to length, n_around points per ring
// (start at angle 0), n_along rings, caps fanned from their centre points.
inline TriSurface capped_cylinder(int n_around, int n_along, double r, double length) {
  TriSurface s;
  for (int k = 0; k <= n_along; ++k)
    for (int j = 0; j < n_around; ++j) {
      const double a = 2 * M_PI * j / n_around;
      s.points.push_back({r * std::cos(a), r * std::sin(a), length * k / n_along});
    }
  auto id = [&](int k, int j) { return k * n_around + (j % n_around); };
  for (int k = 0; k < n_along; ++k)
    for (int j = 0; j < n_around; ++j) {
      s.triangles.push_back({id(k, j), id(k, j + 1), id(k + 1, j + 1)});
      s.triangles.push_back({id(k, j), id(k + 1, j + 1), id(k + 1, j)});
    }
  const int bottom = static_cast<int>(s.points.size());
  s.points.push_back({0, 0, 0});
  const int top = static_cast<int>(s.points.size());
  s.points.push_back({0, 0, length});
  for (int j = 0; j < n_around; ++j) {
    s.triangles.push_back({bottom, id(0, j + 1), id(0, j)});
    s.triangles.push_back({top, id(n_along, j), id(n_along, j + 1)});
  }
  return s;
}


// A NACA 0012 wing segment (chord 1 along x, span 1 along z), tessellated as CAD STL
// exports are: every side triangle spans the whole span, and each end cap is a strip of
// triangles between the upper and lower surface points with no interior point. With
// `per_side` cosine-spaced points per surface the trailing-edge triangles are about
// 1 / (0.5 (1 - cos(pi / (per_side - 1)))) times as long as they are wide (3.6e4 for
// 300). Every point lies on a 90 degree edge (root or tip). Faces point outward.
inline TriSurface sliver_wing_segment(int per_side) {
  const int n = per_side;
  auto half_thickness = [](double x) {
    return 0.6 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
  };
  std::vector<std::array<double, 2>> loop;  // upper LE -> TE, then lower TE -> LE
  std::vector<double> xs(n);
  for (int i = 0; i < n; ++i) xs[i] = 0.5 * (1.0 - std::cos(M_PI * i / (n - 1)));
  for (int i = 0; i < n; ++i) loop.push_back({xs[i], half_thickness(xs[i])});
  for (int i = n - 2; i >= 1; --i) loop.push_back({xs[i], -half_thickness(xs[i])});
  const int m = static_cast<int>(loop.size());
  TriSurface s;
  for (double z : {0.0, 1.0})
    for (const auto& p : loop) s.points.push_back({p[0], p[1], z});
  for (int i = 0; i < m; ++i) {
    const int a = i, b = (i + 1) % m;
    s.triangles.push_back({a, m + b, b});
    s.triangles.push_back({a, m + a, m + b});
  }
  auto lower = [&](int i) { return i == 0 || i == n - 1 ? i : m - i; };  // the lower point at xs[i]
  auto cap = [&](int a, int b, int c) {
    s.triangles.push_back({a, b, c});          // root, facing -z
    s.triangles.push_back({m + a, m + c, m + b});  // tip, facing +z
  };
  for (int i = 0; i + 1 < n; ++i) {
    if (i + 1 < n - 1) cap(i, i + 1, lower(i + 1));
    if (i > 0) cap(i, i + 1 < n - 1 ? lower(i + 1) : i + 1, lower(i));
  }
  return s;
}

}  // namespace blayer::test_surfaces
