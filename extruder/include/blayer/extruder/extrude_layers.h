// Prism boundary-layer extrusion from an oriented wall surface.
//
// Contract
//   Input: a manifold, consistently oriented TriSurface (closed or open) whose triangles'
//   right-hand normals point into the fluid. Lengths are in the surface's units.
//   Output: a conforming VolumeMesh of wedges, plus pyramids and tets where columns stop
//   early (see layer_cells.h), in VTK node order; the wall points keep their indices
//   0..V-1. The envelope (the outer surface of the layers) has the wall's triangles and
//   one point per column, the column's top. Every cell passes the exact corner-tet test
//   of quality/cell_validity.h; the envelope does not intersect itself or the wall
//   wherever the per-layer collision check is on (the default).
//   Throws InputError for an unusable growth law or parameters. Never returns a
//   partially written mesh: stopping columns is a normal outcome, shown in the report.
//   The marching's per-layer checks are the guard that keeps cells valid; whether the
//   result is valid is decided once, by the caller's independent check
//   (quality/mesh_check.h).
//
// Algorithm (marching, layer by layer; the design and its measurements are in
// docs/extrusion.md)
//   The rule: the first height is sacred, the growth law is the target, and a limit ends
//   or compresses the top of a column, never its bottom.
//   0. Plan (column_heights.h, column_plan.h): the growth law's heights on every column
//      (times the local mean edge length when relative), fitted into proximity_safety
//      of the gap to the wall each column faces along its wall direction: the upper
//      layers are compressed (a smaller ratio, below 1 only as far as keeps every layer
//      at least h1), and only when even that does not fit are layers dropped; a gap
//      below h1 / proximity_safety plans no layer. Optionally (max_layer_aspect) a
//      column ends before its first layer taller than that multiple of its wall spacing.
//   1. Directions (step_directions.h): the wall's point normals (normal_method),
//      smoothed without losing visibility. On later layers (column_directions):
//      kKept, the default, keeps each column's direction while it sees the current
//      front's faces by min_visibility and turns it only as far as needed towards the
//      front's own normal; kRecomputed takes the front's point normals every layer.
//      A column with no direction visible by min_visibility stops (kVisibility).
//   2. Step (layer_steps.h): the path length that lifts the column's new point to its
//      planned cumulative height above its incident wall planes, within
//      [h_k, max_step_stretch h_k] (a column held back by that cap is reported as
//      kStepStretch).
//   3. Proximity: the rest of the column, extended by 1 / proximity_safety, is cast
//      against the wall and the current front; the column's remaining layers are fitted
//      into proximity_safety of the gap ahead (compressed, or ended under kTerminate),
//      ramped over height_smoothing_rings so limited spots leave no steps.
//   4. Checks (front_checker.h): every cell of the new layer exactly (all corner and
//      split tets), and the new front against itself, the current front and the wall.
//      Columns of failing cells or triangles are first turned towards their neighbours
//      (direction_repair_passes), then the layer is lowered (halved, never below h1;
//      the layers above restart the growth from it), and only at h1 -- or on the first
//      layer, whose height is never lowered -- does the column end (kQuality,
//      kCollision). The loop ends when every cell passes.
//   5. Per wall triangle the layer becomes a wedge, pyramid or tet by how many of its
//      columns grow (layer_cells.h); side faces depend on one edge only, so the mesh
//      stays conforming.
//   Per-vertex and per-cell work runs in parallel (TBB); results are deterministic.
//   The report (extrusion_report.h) measures what was delivered on the mesh itself.
//
// Output arrays
//   point  normal        (3) direction of the column segment leaving the point (the
//                            arriving one for a column top), single precision
//   point  column_height     path length of the point's whole column (on all its points)
//   point  stop_reason   int StopReason of the point's column (0 = reached all layers)
//   point  layers        int layers the point's column reached
//   cell   layer         int 0 = the layer on the wall
//
// Stages (one header each): wall_topology and wall_planes (tables, heights above the
// wall), column_heights and column_plan (0), step_directions (1 and the turn of 4),
// proximity_rays and layer_steps (2-4), front_checker (the exact checks of 4),
// layer_assembly (5), extrusion_report.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/extrusion_params.h"
#include "blayer/extruder/extrusion_report.h"

namespace blayer {

struct ExtrusionResult {
  VolumeMesh mesh;
  // The front's triangles on the column tops (one point per column; without fans the
  // wall's triangles; with fans also the strips' halves and the corner patches, some of
  // which name one mesh point twice where a fan did not grow: fill_envelope() gives the
  // closed surface the tet fill needs).
  TriSurface envelope;
  std::vector<std::int64_t> envelope_point_ids;  // envelope point (column) c = mesh point id
  std::vector<int> column_layers;                // layers reached per column
  std::vector<StopReason> stop_reason;           // per column
  std::vector<int> column_wall_point;            // per column: its wall point
  std::vector<int> front_wall_face;              // per envelope triangle: its wall triangle, or -1
  ExtrusionReport report;
};

// Extrudes the layers. progress(k, N) is called after layer k (1-based) is finished.
ExtrusionResult extrude_layers(const TriSurface& wall, const ExtrusionParams& params,
                               const std::function<void(int layer, int n_layers)>& progress = {});

// Intersecting pairs among the wall triangles (ids 0..F-1) and the envelope triangles
// (ids F..2F-1), decided exactly on the mesh points; adjacency is by shared mesh point,
// so an envelope triangle whose columns did not grow is the wall face itself and is
// skipped. Empty for a valid result.
std::vector<std::pair<int, int>> find_envelope_intersections(
    const TriSurface& wall, const ExtrusionResult& result,
    std::size_t max_pairs = std::numeric_limits<std::size_t>::max());

}  // namespace blayer
