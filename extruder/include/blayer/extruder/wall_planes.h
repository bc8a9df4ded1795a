// Heights above the wall as a RANS user reads them off a column: the height of a point
// above the planes of the wall triangles incident to the column's wall point (the
// minimum over them), which is the first-cell height h1 at a smooth wall.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/wall_topology.h"

namespace blayer {

class WallPlanes {
 public:
  WallPlanes(const TriSurface& wall, const WallTopology& topo);

  // min over the incident wall triangles of (q - wall point v) . unit normal.
  double height_above(int v, const Vec3& q) const;
  // min over the incident wall triangles of d . unit normal.
  double visibility(int v, const Vec3& d) const;
  // The path length s along the unit direction d from `from` that lifts the point to
  // `height` above every incident plane the direction rises over (max over those planes
  // of (height - a) / (d . f), a the current height above the plane); -1 when d rises
  // over none of them.
  double step_to_height(int v, const Vec3& from, const Vec3& d, double height) const;

 private:
  const std::vector<Vec3>* points_;
  const Csr* vertex_triangles_;
  std::vector<Vec3> face_normal_;
};

}  // namespace blayer
