// Assembly of the layer mesh: the wall points, one new point per growing column and
// layer, one cell per wall triangle and layer (wedge, pyramid or tet by how many of its
// columns grow, layer_cells.h), and the point and cell arrays of the output.
#pragma once

#include <cstdint>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/column_state.h"
#include "blayer/extruder/step_directions.h"

namespace blayer {

class LayerAssembler {
 public:
  // Starts the mesh with the wall points (ids 0..V-1); wall point v's `normal` is the
  // wall direction of its column where it has one.
  LayerAssembler(const TriSurface& wall, const StepDirections& wall_directions);

  // Appends layer k: a point for every column with grows set at next[v], the cells of
  // the layer, and advances the columns (top, top_id, layers, path).
  void commit_layer(int k, const std::vector<char>& grows, const std::vector<Vec3>& next, const StepDirections& d,
                    ColumnState* columns);

  // Columns that grew in each committed layer.
  const std::vector<int>& columns_per_layer() const { return columns_per_layer_; }
  // Smallest visibility of a step taken (1 when none was).
  double min_visibility() const { return min_visibility_; }
  // Mesh point p belongs to column point_column()[p].
  const std::vector<int>& point_column() const { return point_column_; }

  // Moves the mesh out with its arrays:
  //   point  normal (3), column_height, stop_reason, layers    (extrude_layers.h)
  //   cell   layer
  VolumeMesh finish(const ColumnState& columns);

 private:
  const std::vector<Triangle>* triangles_;
  VolumeMesh mesh_;
  std::vector<Vec3> point_normal_;
  std::vector<int> point_column_;
  std::vector<int> cell_layer_;
  std::vector<int> columns_per_layer_;
  double min_visibility_ = 1.0;
};

}  // namespace blayer
