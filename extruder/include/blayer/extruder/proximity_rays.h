// Proximity: the distance ahead of a column, along its step, to the wall or to the
// current front, for the height limiters (the wall-gap cap before marching, the step
// limit on every layer).
//
// Floating point (Moller-Trumbore): the limiter is a heuristic that keeps fronts apart;
// exact predicates decide validity and intersections elsewhere (front_checker.h).
#pragma once

#include <optional>
#include <vector>

#include "blayer/core/ray_triangle.h"
#include "blayer/core/surface.h"
#include "blayer/core/symmetry_plane.h"
#include "blayer/extruder/triangle_bvh.h"
#include "blayer/extruder/unit_vector_box.h"

namespace blayer {

// The rays' segments as first_hits keeps them from one call to the next: their tree and,
// per node of it, a box of the rays' directions.
struct RaySegments {
  TriangleBvh tree;
  std::vector<UnitVectorBox> dir_boxes;
};

// A view of the wall and, optionally, the current front (the wall's triangles on the
// column tops), each with a tree over its triangles' boxes and unit triangle normals.
// Nothing is owned; the arrays must outlive the view.
struct ProximityRays {
  const std::vector<Triangle>* triangles = nullptr;        // the wall's
  // The front's triangles over the columns and each column's wall point (null: the
  // wall's triangles, one column per wall point).
  const std::vector<Triangle>* front_triangles = nullptr;
  const std::vector<int>* wall_point = nullptr;
  const std::vector<Vec3>* wall_points = nullptr;
  const TriangleBvh* wall_tree = nullptr;
  const std::vector<Vec3>* wall_normal = nullptr;
  // Per node of each tree, a box of its triangles' unit normals
  // (TriangleBvh::node_value_boxes), or null: first_hit skips the nodes whose triangles
  // all face away from the ray, first_hits the node pairs whose triangles all face away
  // from the rays below them.
  const std::vector<UnitVectorBox>* wall_normal_boxes = nullptr;
  const std::vector<Vec3>* front_points = nullptr;  // null: the wall only
  const TriangleBvh* front_tree = nullptr;
  const std::vector<Vec3>* front_normal = nullptr;
  const std::vector<UnitVectorBox>* front_normal_boxes = nullptr;
  // A half model's symmetry plane, an obstacle for the columns not on it (on_plane).
  const SymmetryPlane* plane = nullptr;
  const std::vector<char>* on_plane = nullptr;

  // Distance to the first triangle hit along dir from o within t_max that is not
  // incident to column v's wall point (on the front: to a column of that wall point)
  // and faces the ray (dir . normal < 0: a wall or front seen
  // from its fluid side), or to the symmetry plane for a column off it; +inf if none.
  double first_hit(int v, const Vec3& o, const Vec3& dir, double t_max) const;

  // (*gap)[v] = first_hit(v, origin[v], dir[v], t_max[v]) for every column v with
  // active[v], +inf for the others. The same distances, found by descending a tree over
  // the segments together with the wall's and the front's trees
  // (TriangleBvh::for_each_overlapping_pair), where one descent per ray would walk
  // their upper nodes again for every column. Where the trees' normal boxes are given,
  // a node pair whose triangles all face away from all its rays
  // (dot_positive_throughout) is not descended: on the perforated block and the sliver
  // wing more than 99 % of the pairs the boxes find are such pairs, most of them a
  // column's own incident triangles. With `kept`, the segments' tree is kept there
  // between calls: built when it holds another number of columns, refitted
  // otherwise (the columns move little from one layer to the next, and a build per call
  // took nearly as long as the descents it saved on the perforated block).
  void first_hits(const std::vector<char>& active, const std::vector<Vec3>& origin, const std::vector<Vec3>& dir,
                  const std::vector<double>& t_max, std::vector<double>* gap, RaySegments* kept = nullptr) const;

 private:
  // Distance to the symmetry plane for a column off it, +inf otherwise (see first_hit).
  double distance_to_plane(int v, const Vec3& o, const Vec3& dir, double t_max) const;
};

// Unit normals of triangles (zero-area ones give NaN and face no ray).
void unit_triangle_normals(const std::vector<Triangle>& tris, const std::vector<Vec3>& points,
                           std::vector<Vec3>* out);

// The wall's tree (with the triangles' diagonal slabs) and unit triangle normals. They
// depend on the wall alone, so one serves a whole run: the wall-gap cap of every fan
// attempt and the checker's wall side (front_checker.h).
struct WallTree {
  TriangleBvh tree;
  std::vector<Vec3> normal;
  std::vector<UnitVectorBox> normal_boxes;  // per node of the tree (ProximityRays)

  explicit WallTree(const TriSurface& wall);
};

// The wall-only view of a wall (its triangles and points) over its tree.
// front_triangles and wall_point: a column layout's (null: one column per wall point);
// plane and on_plane: a half model's.
ProximityRays wall_proximity_rays(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
                                  const WallTree& tree,
                                  const std::vector<Triangle>* front_triangles = nullptr,
                                  const std::vector<int>* wall_point = nullptr,
                                  const std::optional<SymmetryPlane>& plane = std::nullopt,
                                  const std::vector<char>* on_plane = nullptr);

}  // namespace blayer
