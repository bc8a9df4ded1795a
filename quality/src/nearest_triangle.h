// Nearest point on a triangle surface: exact Euclidean distance from a query point to
// the closest point of any triangle, through a bounding-volume hierarchy. Private to the
// quality module (layer_fidelity.cpp); the tests reach it through its own header.
#pragma once

#include <vector>

#include "blayer/core/surface.h"

namespace blayer {
namespace detail {

// Closest point of the triangle (a, b, c) to p, by the Voronoi region of p among the
// triangle's vertices, edges and interior. Exact up to rounding for any triangle,
// degenerate ones included (they fall into an edge or vertex region).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// Axis-aligned box tree over the triangles of a surface (copied), built once, leaves of
// at most kLeafSize triangles. Nodes are split by the binned surface-area heuristic
// (core/surface_area_split.h), which keeps the long thin triangles of graded wings out
// of the small ones' boxes: on the pyHyp BWB, 107k queries near the wall took 235
// instead of 316 ms with median splits. Below depth kMaxSurfaceAreaDepth, and where no
// axis splits, the median of the longest centroid axis is used, so the depth stays
// below 72 and the query's fixed stack (one entry per level plus one) cannot overflow.
// A query visits boxes nearest first and skips every box farther than the best distance
// so far, so the answer is the same as the brute-force minimum over all triangles.
class NearestTriangleTree {
 public:
  explicit NearestTriangleTree(const TriSurface& surface);

  struct Hit {
    double distance = 0.0;  // Euclidean distance to the nearest point
    int triangle = -1;      // a triangle holding that point (-1 for an empty surface)
    Vec3 point{0.0, 0.0, 0.0};
  };
  Hit nearest(const Vec3& p) const;
  // Whether the nodes form one tree from node 0 (each node reached once) whose leaves
  // hold every triangle once, each inner node's range split between its children and
  // its box holding theirs (for the tests).
  bool well_formed() const;

 private:
  static constexpr int kLeafSize = 4;
  static constexpr int kMaxSurfaceAreaDepth = 40;
  static constexpr int kMaxStack = 128;
  struct Node {
    Vec3 lo, hi;
    int begin = 0, end = 0;  // range of order_ for leaves
    int left = -1, right = -1;
  };
  struct Builder;
  void triangle_box(int t, Vec3* lo, Vec3* hi) const;

  TriSurface surface_;  // a copy: the tree outlives no caller's surface by accident
  std::vector<int> order_;
  std::vector<Vec3> centroid_;
  std::vector<Node> nodes_;
};

}  // namespace detail
}  // namespace blayer
