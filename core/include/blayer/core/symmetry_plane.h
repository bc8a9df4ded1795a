// A symmetry plane: the cut of a half model. The mesh lives on one side of it (the
// model's side); the plane itself is a boundary of the domain (patch `symmetry`), not
// a wall: layers slide along it and columns on it stay in it.
//
// The plane is normal . x = offset with a unit normal pointing into the model's half
// space. For a coordinate plane (x, y or z = c) `axis` is 0, 1 or 2 and the normal is
// +-e_axis: distances, projections and mirror images are then exact (one coordinate
// set or negated about c), so points snapped onto it are exactly on it.
#pragma once

#include <string>

#include "blayer/core/vec3.h"

namespace blayer {

struct SymmetryPlane {
  Vec3 normal{0.0, 0.0, 1.0};  // unit, towards the model's side
  double offset = 0.0;
  int axis = -1;               // 0, 1, 2 for a coordinate plane; -1 for a general one

  // Signed distance of p from the plane, positive on the model's side.
  double signed_distance(const Vec3& p) const {
    return axis >= 0 ? normal[axis] * (p[axis] - offset) : dot(normal, p) - offset;
  }
  // The closest point of the plane (exactly on it for a coordinate plane).
  Vec3 project(const Vec3& p) const {
    if (axis >= 0) {
      Vec3 q = p;
      q[axis] = offset;
      return q;
    }
    return p - (dot(normal, p) - offset) * normal;
  }
  // The direction without its component along the normal (not normalised).
  Vec3 in_plane(const Vec3& d) const {
    if (axis >= 0) {
      Vec3 q = d;
      q[axis] = 0.0;
      return q;
    }
    return d - dot(normal, d) * normal;
  }
  // Mirror image of a point.
  Vec3 mirror(const Vec3& p) const {
    if (axis >= 0) {
      Vec3 q = p;
      q[axis] = 2.0 * offset - p[axis];
      return q;
    }
    return p - 2.0 * (dot(normal, p) - offset) * normal;
  }
  // Mirror image of a direction.
  Vec3 mirror_direction(const Vec3& d) const {
    if (axis >= 0) {
      Vec3 q = d;
      q[axis] = -q[axis];
      return q;
    }
    return d - 2.0 * dot(normal, d) * normal;
  }
  // "y = 0", or "0.6 0.8 0 = 1.5" for a general plane.
  std::string describe() const;
};

// Parses "x=0", "y = -1.5", "z=2" (a coordinate plane; the side is decided later) or
// "a b c d" (the plane a x + b y + c z = d, (a, b, c) normalised). Returns false when
// the text is neither, or the normal is zero or not finite.
bool parse_symmetry_plane(const std::string& text, SymmetryPlane* out);

}  // namespace blayer
