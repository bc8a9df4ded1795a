// Heights above the wall as a RANS user reads them off a column: the height of a point
// above the planes of the wall triangles the column stands on (the minimum over them),
// which is the first-cell height h1 at a smooth wall.
//
// A column stands on the wall triangles incident to its wall point; with fans
// (fan_layout.h) a sector column stands on its sector's triangles only, and a
// sub-normal or corner-centre column, which stands on none, measures its height along
// its own wall direction (at a convex ridge that is the distance to the wall).
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/fan_layout.h"
#include "blayer/extruder/wall_topology.h"

namespace blayer {

class WallPlanes {
 public:
  // The columns of a layout (topo = build_column_topology(layout); one column per wall
  // point: single_column_layout(wall) and build_wall_topology(wall)).
  WallPlanes(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo);

  // min over the column's planes of (q - its wall point) . unit normal.
  double height_above(int v, const Vec3& q) const;
  // min over the column's planes of d . unit normal.
  double visibility(int v, const Vec3& d) const;
  // The path length s along the unit direction d from `from` that lifts the point to
  // `height` above every plane of the column the direction rises over (max over those
  // planes of (height - a) / (d . f), a the current height above the plane); -1 when d
  // rises over none of them.
  double step_to_height(int v, const Vec3& from, const Vec3& d, double height) const;

 private:
  std::vector<Vec3> origin_;   // per column: its wall point
  CsrTable normal_of_;         // per column: indices into normal_
  std::vector<Vec3> normal_;
};

}  // namespace blayer
