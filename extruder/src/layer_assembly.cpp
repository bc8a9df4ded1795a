#include "blayer/extruder/layer_assembly.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <memory>

#include "blayer/extruder/growth_law.h"
#include "blayer/extruder/layer_cells.h"

namespace blayer {

static_assert(kMaxLayers <= std::numeric_limits<std::uint16_t>::max(), "a cell's layer is kept in two bytes");

LayerAssembler::LayerAssembler(const TriSurface& wall, const StepDirections& wall_directions)
    : LayerAssembler(wall, std::make_shared<const ColumnLayout>(single_column_layout(wall)), wall_directions) {}

LayerAssembler::LayerAssembler(const TriSurface& wall, const ColumnLayout& layout,
                               const StepDirections& wall_directions)
    : LayerAssembler(wall, std::make_shared<const ColumnLayout>(layout), wall_directions) {}

LayerAssembler::LayerAssembler(const TriSurface& wall, std::shared_ptr<const ColumnLayout> layout_ptr,
                               const StepDirections& wall_directions)
    : layout_(std::move(layout_ptr)),
      elements_(layout_->elements),
      in_fan_(layout_->in_fan),
      n_wall_elements_(wall.triangles.size()) {
  const ColumnLayout& layout = *layout_;
  const int nv = static_cast<int>(wall.points.size());
  mesh_.points = wall.points;
  point_normal_.assign(3 * static_cast<std::size_t>(nv), 0.0f);
  point_column_.assign(nv, -1);
  for (int c = 0; c < layout.n_columns(); ++c) {
    const int w = layout.wall_point[c];
    if (point_column_[w] >= 0) continue;
    point_column_[w] = c;
    if (wall_directions.ok[c]) set_point_normal(w, wall_directions.n[c]);
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
  point_normal_.reserve(3 * points);
  point_column_.reserve(points);
  mesh_.connectivity.reserve(layers * ids);
  mesh_.offsets.reserve(cells + 1);
  mesh_.cell_types.reserve(cells);
  cell_layer_.reserve(cells);
}

void LayerAssembler::set_point_normal(std::int64_t p, const Vec3& n) {
  for (int i = 0; i < 3; ++i) point_normal_[3 * static_cast<std::size_t>(p) + i] = static_cast<float>(n[i]);
}

void LayerAssembler::commit_layer(int k, const std::vector<char>& grows, const std::vector<Vec3>& next,
                                  const StepDirections& d, ColumnState* columns) {
  const int nv = columns->size();
  std::vector<std::int64_t> new_top(nv, -1);
  const std::size_t first = mesh_.points.size();
  std::size_t n_points = first;
  for (int v = 0; v < nv; ++v)
    if (grows[v]) {
      new_top[v] = static_cast<std::int64_t>(n_points++);
      min_visibility_ = std::min(min_visibility_, d.visibility[v]);
    }
  columns_per_layer_.push_back(static_cast<int>(n_points - first));
  require_indexable_points(n_points, "layer " + std::to_string(k + 1));
  // The new points side by side (serially they took 32 ms of the perforated block's
  // run): each column writes its own point, and its top's normal, which no other
  // growing column shares (a fan's wall point is written by its first column only).
  mesh_.points.resize(n_points);
  point_normal_.resize(3 * n_points);
  point_column_.resize(n_points);
  tbb::parallel_for(tbb::blocked_range<int>(0, nv, 1024), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v < r.end(); ++v) {
      if (!grows[v]) continue;
      const std::size_t p = static_cast<std::size_t>(new_top[v]);
      mesh_.points[p] = next[v];
      // A fan point's wall point shows its first column's direction.
      if (columns->layers[v] > 0 || point_column_[columns->top_id[v]] == v)
        set_point_normal(columns->top_id[v], d.n[v]);
      set_point_normal(static_cast<std::int64_t>(p), d.n[v]);
      point_column_[p] = v;
    }
  });
  append_layer_cells(k, grows, columns->top_id, new_top);
  for (int v = 0; v < nv; ++v) {
    if (!grows[v]) continue;
    columns->path[v] += norm(next[v] - columns->top[v]);
    if (columns->layers[v] == 0) columns->first[v] = next[v];
    columns->top[v] = next[v];
    columns->top_id[v] = new_top[v];
    ++columns->layers[v];
  }
}

namespace {

// Elements per block of a layer's cells, and blocks built at a time (append_layer_cells):
// the buffers of one wave, about 0.6 MB, are all the memory the blocks add.
constexpr std::size_t kElementsPerBlock = 2048;
constexpr std::size_t kBlocksPerWave = 8;

}  // namespace

// The blocks of a wave are built in parallel and appended in element order, so the mesh
// is the one an element-by-element loop builds; the loop took 0.07 s of the perforated
// block's run, on one core. A wave at a time, the buffers stay near 0.6 MB where a whole
// layer's blocks would hold a layer of cells at the march's end, the run's peak.
void LayerAssembler::append_layer_cells(int k, const std::vector<char>& grows, const std::vector<std::int64_t>& bottom,
                                        const std::vector<std::int64_t>& top) {
  const std::size_t n_elements = elements_.size();
  std::vector<CellBlock>& blocks = cell_blocks_;
  blocks.resize(kBlocksPerWave);
  for (std::size_t wave = 0; wave < n_elements; wave += kBlocksPerWave * kElementsPerBlock) {
    const std::size_t n_blocks = std::min(kBlocksPerWave, (n_elements - wave + kElementsPerBlock - 1) / kElementsPerBlock);
    tbb::parallel_for(std::size_t{0}, n_blocks, [&](std::size_t b) {
      CellBlock& out = blocks[b];
      out.types.clear();
      out.ids.clear();
      out.n_fan = 0;
      const std::size_t first = wave + b * kElementsPerBlock, last = std::min(n_elements, first + kElementsPerBlock);
      for (std::size_t i_e = first; i_e < last; ++i_e) {
        LayerCell cells[2];
        const int n_cells = element_layer_cells(
            elements_[i_e], [&](int c) { return bottom[c]; }, [&](int c) { return top[c]; },
            [&](int c) { return grows[c] != 0; }, cells);
        for (int i = 0; i < n_cells; ++i) {
          out.types.push_back(cells[i].type);
          for (int j = 0; j < corner_count(cells[i].type); ++j)
            out.ids.push_back(static_cast<PointId>(cells[i].nodes[j]));
        }
        if (i_e >= n_wall_elements_) out.n_fan += n_cells;
      }
    });
    // Then appended in order, each block at its place (appended one by one, the cells took
    // 32 ms of the perforated block's run on one core).
    std::size_t cells[kBlocksPerWave + 1], ids[kBlocksPerWave + 1];
    cells[0] = mesh_.cell_types.size();
    ids[0] = mesh_.connectivity.size();
    for (std::size_t b = 0; b < n_blocks; ++b) {
      cells[b + 1] = cells[b] + blocks[b].types.size();
      ids[b + 1] = ids[b] + blocks[b].ids.size();
      fan_cells_ += blocks[b].n_fan;
    }
    mesh_.cell_types.resize(cells[n_blocks]);
    mesh_.connectivity.resize(ids[n_blocks]);
    mesh_.offsets.resize(cells[n_blocks] + 1);
    cell_layer_.resize(cells[n_blocks], static_cast<std::uint16_t>(k));
    tbb::parallel_for(std::size_t{0}, n_blocks, [&](std::size_t b) {
      const CellBlock& block = blocks[b];
      std::copy(block.types.begin(), block.types.end(), mesh_.cell_types.begin() + cells[b]);
      std::copy(block.ids.begin(), block.ids.end(), mesh_.connectivity.begin() + ids[b]);
      std::int64_t end = static_cast<std::int64_t>(ids[b]);
      for (std::size_t c = 0; c < block.types.size(); ++c) {
        end += corner_count(block.types[c]);
        mesh_.offsets[cells[b] + c + 1] = end;
      }
    });
  }
}

void LayerAssembler::attach_arrays(const ColumnState& columns, VolumeMesh* mesh) {
  const std::size_t n = point_column_.size();
  DataArray height{"column_height", 1, ArrayValues(ValueType::kFloat64, n)};
  DataArray reason{"stop_reason", 1, ArrayValues(ValueType::kInt32, n)};
  DataArray layers{"layers", 1, ArrayValues(ValueType::kInt32, n)};
  DataArray fan{"fan_column", 1, ArrayValues(ValueType::kInt32, n)};
  double* height_out = height.values.as<double>().data();
  std::int32_t* reason_out = reason.values.as<std::int32_t>().data();
  std::int32_t* layers_out = layers.values.as<std::int32_t>().data();
  std::int32_t* fan_out = fan.values.as<std::int32_t>().data();
  for (std::size_t p = 0; p < n; ++p) {
    const int v = point_column_[p];
    if (v < 0) continue;  // a wall point no triangle uses
    height_out[p] = columns.path[v];
    reason_out[p] = static_cast<std::int32_t>(columns.reason[v]);
    layers_out[p] = columns.layers[v];
    fan_out[p] = in_fan_[v];
  }
  // Moved, not copied: a brace list of the arrays would copy every one, which held the
  // peak memory of a run.
  DataArray normal{"normal", 3, ArrayValues(std::move(point_normal_))};
  point_normal_ = {};
  for (DataArray* a : {&normal, &height, &reason, &layers, &fan}) mesh->point_data.push_back(std::move(*a));
  std::vector<std::int32_t> cell_layer(cell_layer_.begin(), cell_layer_.end());
  cell_layer_ = {};
  mesh->cell_data.push_back(DataArray{"layer", 1, ArrayValues(std::move(cell_layer))});
}

}  // namespace blayer
