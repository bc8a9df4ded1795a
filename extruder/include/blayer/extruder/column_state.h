// Where every column stands while the layers are marched: plain per-column arrays
// (column v grows from wall point v, or from its wall point in a fan layout).
#pragma once

#include <cstdint>
#include <vector>

#include "blayer/core/vec3.h"
#include "blayer/extruder/extrusion_params.h"

namespace blayer {

struct ColumnState {
  std::vector<Vec3> top;               // current top point (the wall point before layer 1)
  std::vector<std::int64_t> top_id;    // mesh point id of the top
  std::vector<int> layers;             // layers grown so far
  std::vector<char> stopped;           // ended (or never started: unused points)
  std::vector<StopReason> reason;      // why it ended early (kNone while growing)
  std::vector<double> path;            // length of the column's polyline so far
  std::vector<Vec3> first;             // the column's first point above the wall (once grown)

  // Starts every used point on the wall; unused points are stopped with kNone.
  static ColumnState on_wall(const std::vector<Vec3>& wall_points, const std::vector<char>& used);
  // Columns at the positions of their wall points, top_id = wall_point[v].
  static ColumnState on_wall(const std::vector<Vec3>& column_points, const std::vector<char>& used,
                             const std::vector<int>& wall_point);

  // Ends column v for `why`; a column already stopped keeps its first reason.
  void stop(int v, StopReason why) {
    if (stopped[v]) return;
    stopped[v] = 1;
    reason[v] = why;
  }
  int size() const { return static_cast<int>(top.size()); }
};

}  // namespace blayer
