// Simulated layer fronts for the normals benches: front 0 is the wall; front f+1 moves
// every point of front f along its most-normal normal by h_f, h_0 = first_height
// (default 2e-4 times the bounding-box diagonal, as case 001) and h_{f+1} = 1.2 h_f.
// Real fronts are also limited and smoothed; these keep every point moving, which makes
// the fans non-planar the way offset fronts are.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/vertex_fans.h"
#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/point_normals.h"

namespace blayer {
namespace bench {

struct FrontMarch {
  TriSurface surface;
  VertexFans fans;
  double height = 0.0;  // the next step
  double growth = 1.2;

  FrontMarch(const TriSurface& wall, double first_height_over_diagonal = 2e-4)
      : surface(wall), fans(build_vertex_fans(wall)) {
    height = first_height_over_diagonal * bounding_box_diagonal(wall.points);
  }

  // Moves every point along `normals` (one per point) by the current height.
  void advance(const std::vector<Vec3>& normals) {
    for (std::size_t v = 0; v < surface.points.size(); ++v) surface.points[v] += height * normals[v];
    height *= growth;
  }

  void advance() { advance(compute_point_normals(surface, fans, NormalMethod::kMostNormal).normal); }

  // The closed fan of point v without degenerate triangles, or false.
  bool closed_fan(std::size_t v, FanGeometry* g) const {
    const VertexFan& fan = fans.fans[v];
    if (fan.triangles.empty() || !fan.closed) return false;
    thread_local std::vector<Vec3> ring;
    ring.clear();
    for (int r : fan.ring) ring.push_back(surface.points[r]);
    build_fan_geometry(surface.points[v], ring, true, default_tolerances(), g);
    return !g->any_degenerate;
  }
};

}  // namespace bench
}  // namespace blayer
