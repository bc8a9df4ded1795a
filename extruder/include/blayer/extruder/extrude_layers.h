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
// Algorithm (marching, layer by layer)
//   0. Heights: the growth law gives h_k (times the local mean edge length e_v when
//      relative; e_v = mean wall edge length at v). Per column, the total is capped at
//      max_height_to_edge_ratio times the shortest wall edge at v (height_cap_length) and
//      at proximity_safety times the gap seen along the wall normal (a ray against the
//      other wall triangles); both caps scale all N layers of the column alike, so the
//      column keeps its layers, and are smoothed downward over height_smoothing_rings.
//   1. On the current front (same triangles, current column tops) point normals are
//      recomputed with compute_point_normals (normal_method), and optionally smoothed
//      with neighbours (Jacobi passes; the full, half or quarter blend towards the
//      neighbour average, whichever comes first); a smoothed direction is kept only if
//      its visibility V = min_i n.f_i over the incident front faces does not drop below
//      the unsmoothed one's (and below min_visibility).
//   2. Step s = h / V, so the new point is h above every incident face plane (1/V capped
//      at max_step_stretch). A column with V < min_visibility stops (visibility).
//   3. Proximity: the step segment, extended to s / proximity_safety, is intersected with
//      the wall and current-front triangles not incident to the column (front-facing
//      hits only); the step is cut to proximity_safety times the hit distance.
//   4. The step factors are smoothed downward (linear ramp over height_smoothing_rings
//      rings), so limited spots leave no steps. A column cut below min_layer_fraction of
//      its layer height stops instead.
//   5. Every cell of the new layer is checked exactly (all corner tets); the new front
//      triangles are checked exactly against the new front, the current front and the
//      wall. Columns of failing cells / triangles are first turned towards the mean
//      direction of the failing triangles around them (direction_repair_passes; the
//      usual cause is sideways shear between neighbouring columns on thin triangles),
//      then get their step halved (and the reduction smoothed) and are re-checked;
//      below min_layer_fraction they stop (quality / collision). The loop ends when
//      everything passes.
//   6. Per wall triangle the layer becomes a wedge, pyramid or tet by how many of its
//      columns grow (layer_cells.h); side faces depend on one edge only, so the mesh
//      stays conforming.
//   Per-vertex and per-cell work runs in parallel (TBB); results are deterministic.
//
// Output arrays
//   point  normal        (3) direction of the column segment leaving the point (the
//                            arriving one for a column top)
//   point  column_height     path length of the point's whole column (on all its points)
//   point  stop_reason   int StopReason of the point's column (0 = reached all layers)
//   point  layers        int layers the point's column reached
//   cell   layer         int 0 = the layer on the wall
//
// Stages (one header each): wall_topology (tables), step_directions (1 and the
// direction repair of 5), column_heights (0), proximity_rays and layer_steps (2-5),
// front_checker (the exact checks of 5), layer_assembly (6), extrusion_report.
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
  TriSurface envelope;                         // wall triangles on the column tops
  std::vector<std::int64_t> envelope_point_ids;  // envelope point v = mesh point id
  std::vector<int> column_layers;                // layers reached per wall vertex
  std::vector<StopReason> stop_reason;           // per wall vertex
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
