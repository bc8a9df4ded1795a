// Assembly of the layer mesh: the wall points, one new point per growing column and
// layer, one cell per layout element and layer (a wall triangle's wedge, pyramid or tet
// by how many of its columns grow; fan wedges, hexahedra and their closures on fan
// strips; layer_cells.h), and the point and cell arrays of the output.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/column_state.h"
#include "blayer/extruder/fan_layout.h"
#include "blayer/extruder/step_directions.h"

namespace blayer {

class LayerAssembler {
 public:
  // Starts the mesh with the wall points (ids 0..V-1); wall point v's `normal` is the
  // wall direction of its column where it has one.
  LayerAssembler(const TriSurface& wall, const StepDirections& wall_directions);
  // The columns of a layout; wall point w's `normal` is that of its first column. The
  // second form shares the layout (the march's, which the checker shares too) instead of
  // holding a copy of it.
  LayerAssembler(const TriSurface& wall, const ColumnLayout& layout, const StepDirections& wall_directions);
  LayerAssembler(const TriSurface& wall, std::shared_ptr<const ColumnLayout> layout,
                 const StepDirections& wall_directions);

  // Reserves room for the most cells n_layers layers can hold (each element's largest
  // split, with every column growing): the mesh's arrays then never reallocate while
  // they grow, which briefly held both the old and the new buffer of the largest ones
  // (the peak memory of a large run). Runs whose columns stop, or whose elements are
  // not split, use less.
  void reserve_layers(int n_layers);

  // Appends layer k: a point for every column with grows set at next[v], the cells of
  // the layer, and advances the columns (top, top_id, layers, path).
  void commit_layer(int k, const std::vector<char>& grows, const std::vector<Vec3>& next, const StepDirections& d,
                    ColumnState* columns);

  // Columns that grew in each committed layer.
  const std::vector<int>& columns_per_layer() const { return columns_per_layer_; }
  // Cells on fan strips and corner patches (the elements after the wall triangles).
  std::int64_t fan_cells() const { return fan_cells_; }
  // Smallest visibility of a step taken (1 when none was).
  double min_visibility() const { return min_visibility_; }
  // Mesh point p belongs to column point_column()[p].
  const std::vector<int>& point_column() const { return point_column_; }

  // The mesh in two steps: take_mesh moves out its points and cells, attach_arrays then
  // adds its arrays:
  //   point  normal (3, Float32), column_height, stop_reason, layers, fan_column   (extrude_layers.h)
  //   cell   layer
  // A run summarises its cells in between, so that the summary's tables and the arrays
  // never add up in its peak memory.
  VolumeMesh take_mesh() {
    cell_blocks_ = {};
    return std::move(mesh_);
  }
  void attach_arrays(const ColumnState& columns, VolumeMesh* mesh);

 private:
  void set_point_normal(std::int64_t p, const Vec3& n);
  // Appends layer k's cells: each element's by which of its columns grow, from their
  // point ids at the layer's base (bottom) and one layer up (top).
  void append_layer_cells(int k, const std::vector<char>& grows, const std::vector<std::int64_t>& bottom,
                          const std::vector<std::int64_t>& top);

  std::shared_ptr<const ColumnLayout> layout_;
  const std::vector<LayerElement>& elements_;
  const std::vector<char>& in_fan_;  // per column
  std::size_t n_wall_elements_ = 0;
  std::int64_t fan_cells_ = 0;
  VolumeMesh mesh_;
  // Per point, its column's direction in the layer that made it, in single precision
  // (the array is for viewing, and doubles were a tenth of a run's peak memory).
  std::vector<float> point_normal_;
  std::vector<int> point_column_;
  // Per cell, its layer, in two bytes while the layers grow (kMaxLayers fits): written
  // as the Int32 array `layer`.
  std::vector<std::uint16_t> cell_layer_;
  std::vector<int> columns_per_layer_;
  // The cells of a block of elements, in element order, as the mesh stores them; kept
  // from layer to layer, so that their buffers are allocated once.
  struct CellBlock {
    std::vector<CellType> types;
    std::vector<PointId> ids;
    std::int64_t n_fan = 0;  // cells on fan elements
  };
  std::vector<CellBlock> cell_blocks_;
  double min_visibility_ = 1.0;
};

}  // namespace blayer
