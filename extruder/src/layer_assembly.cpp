#include "blayer/extruder/layer_assembly.h"

#include <algorithm>

#include "blayer/extruder/layer_cells.h"

namespace blayer {

LayerAssembler::LayerAssembler(const TriSurface& wall, const StepDirections& wall_directions)
    : triangles_(&wall.triangles) {
  const int nv = static_cast<int>(wall.points.size());
  mesh_.points = wall.points;
  point_normal_.assign(nv, Vec3{0.0, 0.0, 0.0});
  point_column_.resize(nv);
  for (int v = 0; v < nv; ++v) {
    point_column_[v] = v;
    if (wall_directions.ok[v]) point_normal_[v] = wall_directions.n[v];
  }
}

void LayerAssembler::commit_layer(int k, const std::vector<char>& grows, const std::vector<Vec3>& next,
                                  const StepDirections& d, ColumnState* columns) {
  const int nv = columns->size();
  std::vector<std::int64_t> new_top(nv, -1);
  int n_grown = 0;
  for (int v = 0; v < nv; ++v) {
    if (!grows[v]) continue;
    new_top[v] = static_cast<std::int64_t>(mesh_.points.size());
    mesh_.points.push_back(next[v]);
    point_normal_[columns->top_id[v]] = d.n[v];
    point_normal_.push_back(d.n[v]);
    point_column_.push_back(v);
    min_visibility_ = std::min(min_visibility_, d.visibility[v]);
    ++n_grown;
  }
  columns_per_layer_.push_back(n_grown);
  for (const Triangle& t : *triangles_) {
    const std::array<bool, 3> g = {bool(grows[t[0]]), bool(grows[t[1]]), bool(grows[t[2]])};
    LayerCell cell;
    if (!layer_cell({columns->top_id[t[0]], columns->top_id[t[1]], columns->top_id[t[2]]},
                    {new_top[t[0]], new_top[t[1]], new_top[t[2]]}, g, &cell))
      continue;
    mesh_.add_cell(cell.type, cell.nodes.data());
    cell_layer_.push_back(k);
  }
  for (int v = 0; v < nv; ++v) {
    if (!grows[v]) continue;
    columns->path[v] += norm(next[v] - columns->top[v]);
    if (columns->layers[v] == 0) columns->first[v] = next[v];
    columns->top[v] = next[v];
    columns->top_id[v] = new_top[v];
    ++columns->layers[v];
  }
}

VolumeMesh LayerAssembler::finish(const ColumnState& columns) {
  const std::int64_t np = static_cast<std::int64_t>(mesh_.points.size());
  DataArray normal{"normal", 3, false, std::vector<double>(3 * np)};
  DataArray height{"column_height", 1, false, std::vector<double>(np)};
  DataArray reason{"stop_reason", 1, true, std::vector<double>(np)};
  DataArray layers{"layers", 1, true, std::vector<double>(np)};
  for (std::int64_t p = 0; p < np; ++p) {
    const int v = point_column_[p];
    for (int i = 0; i < 3; ++i) normal.values[3 * p + i] = point_normal_[p][i];
    height.values[p] = columns.path[v];
    reason.values[p] = static_cast<int>(columns.reason[v]);
    layers.values[p] = columns.layers[v];
  }
  mesh_.point_data = {std::move(normal), std::move(height), std::move(reason), std::move(layers)};
  mesh_.cell_data = {DataArray{"layer", 1, true, std::vector<double>(cell_layer_.begin(), cell_layer_.end())}};
  point_normal_ = {};
  cell_layer_ = {};
  return std::move(mesh_);
}

}  // namespace blayer
