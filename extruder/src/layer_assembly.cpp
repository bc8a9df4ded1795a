#include "blayer/extruder/layer_assembly.h"

#include <algorithm>

#include "blayer/extruder/layer_cells.h"

namespace blayer {

LayerAssembler::LayerAssembler(const TriSurface& wall, const StepDirections& wall_directions)
    : LayerAssembler(wall, single_column_layout(wall), wall_directions) {}

LayerAssembler::LayerAssembler(const TriSurface& wall, const ColumnLayout& layout,
                               const StepDirections& wall_directions)
    : elements_(layout.elements), in_fan_(layout.in_fan), n_wall_elements_(wall.triangles.size()) {
  const int nv = static_cast<int>(wall.points.size());
  mesh_.points = wall.points;
  point_normal_.assign(nv, Vec3{0.0, 0.0, 0.0});
  point_column_.assign(nv, -1);
  for (int c = 0; c < layout.n_columns(); ++c) {
    const int w = layout.wall_point[c];
    if (point_column_[w] >= 0) continue;
    point_column_[w] = c;
    if (wall_directions.ok[c]) point_normal_[w] = wall_directions.n[c];
  }
}

void LayerAssembler::reserve_layers(int n_layers) {
  const std::size_t layers = static_cast<std::size_t>(std::max(0, n_layers));
  // Per layer, at most: a strip's hex; a split triangle's or strip end's pyramid and tet
  // (or two tets); a triangle's wedge.
  std::size_t ids = 0, cells = 0;
  for (const LayerElement& e : elements_) {
    const bool split = e.kind == ElementKind::kStripEnd || e.split_at >= 0;
    ids += split ? 9 : e.kind == ElementKind::kStrip ? 8 : 6;
    cells += split ? 2 : 1;
  }
  cells *= layers;
  const std::size_t points = mesh_.points.size() + layers * in_fan_.size();
  mesh_.points.reserve(points);
  point_normal_.reserve(points);
  point_column_.reserve(points);
  mesh_.connectivity.reserve(layers * ids);
  mesh_.offsets.reserve(cells + 1);
  mesh_.cell_types.reserve(cells);
  cell_layer_.reserve(cells);
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
    // A fan point's wall point shows its first column's direction.
    if (columns->layers[v] > 0 || point_column_[columns->top_id[v]] == v) point_normal_[columns->top_id[v]] = d.n[v];
    point_normal_.push_back(d.n[v]);
    point_column_.push_back(v);
    min_visibility_ = std::min(min_visibility_, d.visibility[v]);
    ++n_grown;
  }
  columns_per_layer_.push_back(n_grown);
  require_indexable_points(mesh_.points.size(), "layer " + std::to_string(k + 1));
  for (std::size_t i_e = 0; i_e < elements_.size(); ++i_e) {
    LayerCell cells[2];
    const int n_cells = element_layer_cells(
        elements_[i_e], [&](int c) { return columns->top_id[c]; }, [&](int c) { return new_top[c]; },
        [&](int c) { return grows[c] != 0; }, cells);
    for (int i = 0; i < n_cells; ++i) {
      mesh_.add_cell(cells[i].type, cells[i].nodes.data());
      if (i_e >= n_wall_elements_) ++fan_cells_;
      cell_layer_.push_back(k);
    }
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

void LayerAssembler::attach_arrays(const ColumnState& columns, VolumeMesh* mesh) {
  const std::size_t n = point_column_.size();
  DataArray normal{"normal", 3, ArrayValues(ValueType::kFloat64, 3 * n)};
  DataArray height{"column_height", 1, ArrayValues(ValueType::kFloat64, n)};
  DataArray reason{"stop_reason", 1, ArrayValues(ValueType::kInt32, n)};
  DataArray layers{"layers", 1, ArrayValues(ValueType::kInt32, n)};
  DataArray fan{"fan_column", 1, ArrayValues(ValueType::kInt32, n)};
  double* normal_out = normal.values.as<double>().data();
  double* height_out = height.values.as<double>().data();
  std::int32_t* reason_out = reason.values.as<std::int32_t>().data();
  std::int32_t* layers_out = layers.values.as<std::int32_t>().data();
  std::int32_t* fan_out = fan.values.as<std::int32_t>().data();
  for (std::size_t p = 0; p < n; ++p) {
    const int v = point_column_[p];
    for (int i = 0; i < 3; ++i) normal_out[3 * p + i] = point_normal_[p][i];
    if (v < 0) continue;  // a wall point no triangle uses
    height_out[p] = columns.path[v];
    reason_out[p] = static_cast<std::int32_t>(columns.reason[v]);
    layers_out[p] = columns.layers[v];
    fan_out[p] = in_fan_[v];
  }
  // Freed before the cell array is built. Assigning {} would keep their capacity, and a
  // brace list would copy every array: both held the peak memory of a run.
  std::vector<Vec3>().swap(point_normal_);
  for (DataArray* a : {&normal, &height, &reason, &layers, &fan}) mesh->point_data.push_back(std::move(*a));
  mesh->cell_data.push_back(DataArray{"layer", 1, ArrayValues(std::move(cell_layer_))});
  cell_layer_ = {};
}

}  // namespace blayer
