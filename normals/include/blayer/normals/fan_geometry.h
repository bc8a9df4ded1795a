// Geometry of one vertex fan on the unit sphere around its vertex p, and the two
// per-direction figures every normal method is judged by (docs/normals.md, Part 1 and 2).
//
// A fan of k triangles T_i = (p, r_i, r_{i+1}) gives
//   dirs[j]          u_j = unit(r_j - p), the link vertices on S^2 (k of them when the
//                    fan is closed, k+1 when open),
//   face_normals[i]  f_i = unit((r_i - p) x (r_{i+1} - p)), pointing into the fluid,
//   angles[i]        alpha_i, the corner angle at p (radians, in (0, pi)),
//   areas[i]         A_i, the triangle area (squared length units of the input),
//   max_weights[i]   sin(alpha_i) / (|r_i - p| |r_{i+1} - p|) (Max 1999),
// and arc i runs on the great circle with normal f_i from dirs[i] to dirs[i+1 mod size].
#pragma once

#include <vector>

#include "blayer/core/cyclic_index.h"
#include "blayer/core/tolerances.h"
#include "blayer/core/vec3.h"

namespace blayer {

struct FanGeometry {
  std::vector<Vec3> dirs;
  std::vector<Vec3> face_normals;
  std::vector<double> angles;
  std::vector<double> areas;
  std::vector<double> max_weights;
  std::vector<char> degenerate;  // per triangle: relative height below tolerance
  bool closed = false;
  bool any_degenerate = false;

  int n_faces() const { return static_cast<int>(face_normals.size()); }
  const Vec3& arc_start(int i) const { return dirs[i]; }
  // i < n_faces(); read for every arc of every cell and candidate of a solve.
  const Vec3& arc_end(int i) const { return dirs[cyclic_next(i, static_cast<int>(dirs.size()))]; }
};

// Builds the fan geometry of vertex p with ring points `ring` (closed: triangles
// (p, ring[j], ring[j+1 mod n]); open: j = 0..n-2). A triangle whose twice-area over its
// longest edge squared is below tol.degenerate_relative_height is flagged degenerate
// (its face normal is then whatever the rounding gives, possibly zero).
// Precondition: ring.size() >= 3 when closed, >= 2 when open.
FanGeometry build_fan_geometry(const Vec3& p, const std::vector<Vec3>& ring, bool closed,
                               const Tolerances& tol = default_tolerances());

// The same into *out, reusing its storage (one FanGeometry per thread for a loop over
// vertices).
void build_fan_geometry(const Vec3& p, const std::vector<Vec3>& ring, bool closed, const Tolerances& tol,
                        FanGeometry* out);

// V(n) = min_i n.f_i over non-degenerate faces (+infinity for a fan with none).
double fan_visibility(const FanGeometry& g, const Vec3& n);

// Angular distance (radians) from unit n to the great-circle arc from u to v (length
// < pi) whose plane normal is the unit vector f.
double distance_to_arc(const Vec3& n, const Vec3& u, const Vec3& v, const Vec3& f);

// D(n) = min over arcs of the angular distance from unit n to the arc (radians): the
// angle from n to the nearest direction inside any incident triangle.
double fan_normality(const FanGeometry& g, const Vec3& n);

}  // namespace blayer
