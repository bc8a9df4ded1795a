// The tolerances shared by several modules, each with the reason for its value. Lengths
// are relative to a local edge length or the bounding-box diagonal; angles are in
// radians. Tolerances of one module are named constants next to their use, with their
// reasons; docs/tolerances.md lists every tolerance and where it lives.
#pragma once

namespace blayer {

struct Tolerances {
  // A triangle is degenerate when its area is below this fraction of the square of its
  // longest edge: twice the area over the longest edge squared is the triangle's
  // relative height; 1e-12 is six orders above double rounding (1e-16 relative) on the
  // products involved, so only truly collapsed triangles are rejected.
  double degenerate_relative_height = 1e-12;

  // Face normals closer than this (Euclidean distance of unit vectors) are one normal
  // for the most-visible QP: the Gram matrix of duplicates is singular.
  double duplicate_normal = 1e-12;

  // Below this visibility (min n.f) a direction is treated as invisible: sin(0.01 deg).
  // Steps scale as 1/V, so smaller margins would give needle columns anyway.
  double min_visibility = 1.7453292519943295e-4;

  // Consecutive link arcs are merged into one site when the next ring direction lies
  // within this distance of the arc's great circle (|f_i . v_{i+1}|).
  double coplanar_arc = 1e-12;

  // Maximisers of the most-normal objective within this many radians are ties.
  double normality_tie = 1e-9;
};

inline const Tolerances& default_tolerances() {
  static const Tolerances t{};
  return t;
}

}  // namespace blayer
