#include "blayer/extruder/column_state.h"

namespace blayer {

ColumnState ColumnState::on_wall(const std::vector<Vec3>& wall_points, const std::vector<char>& used) {
  const int nv = static_cast<int>(wall_points.size());
  ColumnState c;
  c.top = wall_points;
  c.top_id.resize(nv);
  for (int v = 0; v < nv; ++v) c.top_id[v] = v;
  c.layers.assign(nv, 0);
  c.stopped.assign(nv, 0);
  for (int v = 0; v < nv; ++v) c.stopped[v] = !used[v];
  c.reason.assign(nv, StopReason::kNone);
  c.path.assign(nv, 0.0);
  c.first = wall_points;
  return c;
}

ColumnState ColumnState::on_wall(const std::vector<Vec3>& column_points, const std::vector<char>& used,
                                 const std::vector<int>& wall_point) {
  ColumnState c = on_wall(column_points, used);
  for (int v = 0; v < c.size(); ++v) c.top_id[v] = wall_point[v];
  return c;
}

}  // namespace blayer
