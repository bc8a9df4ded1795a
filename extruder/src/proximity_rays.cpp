#include "blayer/extruder/proximity_rays.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace blayer {

void unit_triangle_normals(const std::vector<Triangle>& tris, const std::vector<Vec3>& points,
                           std::vector<Vec3>* out) {
  out->resize(tris.size());
  tbb::parallel_for(0, static_cast<int>(tris.size()), [&](int i) {
    const Triangle& t = tris[i];
    (*out)[i] = normalized(cross(points[t[1]] - points[t[0]], points[t[2]] - points[t[0]]));
  });
}

WallTree::WallTree(const TriSurface& wall) {
  tree.build_triangles(static_cast<int>(wall.triangles.size()), [&](int f, Vec3* c) {
    for (int i = 0; i < 3; ++i) c[i] = wall.points[wall.triangles[f][i]];
  });
  unit_triangle_normals(wall.triangles, wall.points, &normal);
  tree.node_value_boxes([&](int f) { return normal[f]; }, &normal_boxes);
}

ProximityRays wall_proximity_rays(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
                                  const WallTree& tree, const std::vector<Triangle>* front_triangles, const std::vector<int>* wall_point,
                                  const std::optional<SymmetryPlane>& plane, const std::vector<char>* on_plane) {
  ProximityRays r;
  r.triangles = &triangles;
  r.front_triangles = front_triangles;
  r.wall_point = wall_point;
  r.wall_points = &points;
  r.wall_tree = &tree.tree;
  r.wall_normal = &tree.normal;
  r.wall_normal_boxes = &tree.normal_boxes;
  if (plane) {
    r.plane = &*plane;
    r.on_plane = on_plane;
  }
  return r;
}

namespace {

// Distance along dir from o to triangle i of (tris, P) within t_max, or +inf: also +inf
// when the triangle is incident to wall point w (on_columns: has a corner on one of w's
// columns) or does not face the ray.
template <class PointOf>
double distance_if_facing(int w, PointOf&& point_of, const Vec3& o, const Vec3& dir, double t_max,
                          const std::vector<Triangle>& tris, const std::vector<Vec3>& P,
                          const std::vector<Vec3>& normal, bool on_columns, int i) {
  const Triangle& t = tris[i];
  if (on_columns ? (point_of(t[0]) == w || point_of(t[1]) == w || point_of(t[2]) == w)
                 : (t[0] == w || t[1] == w || t[2] == w))
    return HUGE_VAL;
  if (!(dot(dir, normal[i]) < 0.0)) return HUGE_VAL;
  return ray_triangle_distance(o, dir, P[t[0]], P[t[1]], P[t[2]], t_max);
}

// search(tree, triangles, points, unit normals, normal boxes or null, on_columns) over
// the wall and, when the view has one, the front: the obstacles of first_hit and
// first_hits alike.
template <class Search>
void search_obstacles(const ProximityRays& r, Search&& search) {
  search(*r.wall_tree, *r.triangles, *r.wall_points, *r.wall_normal, r.wall_normal_boxes, false);
  if (r.front_points)
    search(*r.front_tree, r.front_triangles ? *r.front_triangles : *r.triangles, *r.front_points, *r.front_normal,
           r.front_normal_boxes, true);
}

// Whether every triangle below node `node` faces away from every ray direction in
// `dirs` (distance_if_facing turns them all down); never without normal boxes.
bool faces_away(const std::vector<UnitVectorBox>* normal_boxes, int node, const UnitVectorBox& dirs) {
  return normal_boxes && dot_positive_throughout(dirs, (*normal_boxes)[node]);
}

}  // namespace

double ProximityRays::distance_to_plane(int v, const Vec3& o, const Vec3& dir, double t_max) const {
  if (!plane || (*on_plane)[v]) return HUGE_VAL;
  // Seen from the model's side the plane faces the ray when dir points towards it.
  const double towards = -dot(dir, plane->normal);
  if (!(towards > 0.0)) return HUGE_VAL;
  const double t = plane->signed_distance(o) / towards;
  return t >= 0.0 && t <= t_max ? t : HUGE_VAL;
}

double ProximityRays::first_hit(int v, const Vec3& o, const Vec3& dir, double t_max) const {
  double best = HUGE_VAL;
  const int w = wall_point ? (*wall_point)[v] : v;
  auto point_of = [&](int c) { return wall_point ? (*wall_point)[c] : c; };
  const UnitVectorBox dir_box = UnitVectorBox::of(dir);
  auto search = [&](const TriangleBvh& tree, const std::vector<Triangle>& tris, const std::vector<Vec3>& P,
                    const std::vector<Vec3>& normal, const std::vector<UnitVectorBox>* normal_boxes, bool on_columns) {
    tree.for_each_on_segment(
        o, dir, std::min(t_max, best),
        [&](int i, double* tm) {
          const double d = distance_if_facing(w, point_of, o, dir, *tm, tris, P, normal, on_columns, i);
          if (d < best) {
            best = d;
            *tm = d;
          }
        },
        [&](int node) { return !faces_away(normal_boxes, node, dir_box); });
  };
  search_obstacles(*this, search);
  return std::min(best, distance_to_plane(v, o, dir, t_max));
}

void ProximityRays::first_hits(const std::vector<char>& active, const std::vector<Vec3>& origin,
                               const std::vector<Vec3>& dir, const std::vector<double>& t_max,
                               std::vector<double>* gap, RaySegments* kept) const {
  const int n = static_cast<int>(origin.size());
  gap->assign(n, HUGE_VAL);
  // Each segment's box holds it, so every triangle the segment meets overlaps it in the
  // pair traversal. Boxes only: with diagonal slabs (diagonal_slabs.h) as well, the
  // perforated block's peak memory rose by 1 to 2.5 MB and its proximity time stayed.
  auto box_of = [&](int v) {
    const Vec3 end = active[v] ? origin[v] + t_max[v] * dir[v] : origin[v];
    return Box::of_triangle(origin[v], end, end);
  };
  RaySegments local;
  TriangleBvh& segments = kept ? kept->tree : local.tree;
  std::vector<UnitVectorBox>& dir_boxes = kept ? kept->dir_boxes : local.dir_boxes;
  if (segments.empty() || segments.size() != n) {
    std::vector<Box> boxes(n);
    tbb::parallel_for(0, n, [&](int v) { boxes[v] = box_of(v); });
    segments.build(boxes);
  } else {
    segments.refit_each(box_of);
  }
  std::vector<char> node_wanted;
  segments.mark_nodes(active, &node_wanted);
  segments.node_value_boxes([&](int v) { return dir[v]; }, &dir_boxes);
  auto point_of = [&](int c) { return wall_point ? (*wall_point)[c] : c; };
  // Hits are few next to the pairs tested (most rays meet nothing): each thread lists
  // its own.
  tbb::enumerable_thread_specific<std::vector<std::pair<int, double>>> hits;
  auto search = [&](const TriangleBvh& tree, const std::vector<Triangle>& tris, const std::vector<Vec3>& P,
                    const std::vector<Vec3>& normal, const std::vector<UnitVectorBox>* normal_boxes, bool on_columns) {
    segments.for_each_overlapping_pair(
        active, node_wanted, tree,
        [&](int v, int i) {
          const double d =
              distance_if_facing(point_of(v), point_of, origin[v], dir[v], t_max[v], tris, P, normal, on_columns, i);
          if (d < HUGE_VAL) hits.local().emplace_back(v, d);
        },
        [&](int a, int b) { return !faces_away(normal_boxes, b, dir_boxes[a]); });
  };
  search_obstacles(*this, search);
  for (const auto& list : hits)
    for (const auto& [v, d] : list) (*gap)[v] = std::min((*gap)[v], d);
  if (plane)
    for (int v = 0; v < n; ++v)
      if (active[v]) (*gap)[v] = std::min((*gap)[v], distance_to_plane(v, origin[v], dir[v], t_max[v]));
}

}  // namespace blayer
