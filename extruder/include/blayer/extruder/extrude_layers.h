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
//   cell   min_corner_jacobian  min over corners of the scaled Jacobian (layer_cells.h)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/growth_law.h"
#include "blayer/normals/point_normals.h"

namespace blayer {

// Why a column ended before layer N; written as the int point array `stop_reason`.
enum class StopReason : int {
  kNone = 0,        // reached all layers
  kCollision = 1,   // the new front would intersect itself, the previous front or the wall
  kQuality = 2,     // a new cell failed the exact corner-tet test even at reduced height
  kProximity = 3,   // the gap ahead (another front or wall) allows less than a useful layer
  kVisibility = 4,  // no direction sees all incident front faces by min_visibility
};
constexpr int kStopReasonCount = 5;
const char* stop_reason_name(StopReason r);

// The wall length a column's total height is capped against (max_height_to_edge_ratio).
enum class HeightCapLength : int {
  kShortestEdge = 0,  // shortest wall edge at the vertex
  kMeanEdge = 1,      // mean wall edge length at the vertex
  kFaceSize = 2,      // sqrt(2 x mean area of the incident wall triangles): the leg of a
                      // right isosceles triangle of that area, a size of the prism caps
                      // that, unlike the shortest edge, is not set by one short side
};

// Parameters; each default is what the CLI shows in --help.
struct ExtrusionParams {
  // Layer count and heights (growth_law.h). The default law only fixes N = 10 and the
  // ratio; one of first_height / last_height / total_thickness must be set.
  GrowthLaw growth;
  // Point-normal method on every front (point_normals.h).
  NormalMethod normal_method = NormalMethod::kMostNormal;
  // Jacobi passes averaging each direction with its neighbours'; 0 disables smoothing.
  int normal_smoothing_iterations = 2;
  // Rings over which a height reduction ramps back to full height (0: no smoothing).
  int height_smoothing_rings = 3;
  // A column may cover at most this fraction of the gap ahead of it (0 < x <= 0.5: two
  // fronts growing towards each other meet in the middle).
  double proximity_safety = 0.45;
  // Column height cap relative to the shortest wall edge at the vertex, so that small
  // faces do not grow needles and columns on stretched triangles cannot overtake each
  // other sideways (on the pyHyp wing meshes, 2 gives full coverage at ~35 % of the
  // requested thickness, 5 gives 99 % coverage at ~50 %, 10 drops coverage to 89 %);
  // 0 disables the cap.
  double max_height_to_edge_ratio = 4.0;
  // Which wall length max_height_to_edge_ratio multiplies. The shortest edge stays the
  // default: measured (N=10, h1 = 2e-4 x diagonal, r = 1.2) as coverage / mean thickness
  // fraction on the pyHyp 717 wing, the pyHyp BWB and the 16k ONERA M6,
  //   shortest x4  1.000/0.43  1.000/0.47  1.000/0.99
  //   shortest x6  0.991/0.51  0.976/0.53  1.000/1.00  (min scaled Jacobian 0.0016 -> 0 on the 717)
  //   mean x3      0.981/0.75  0.838/0.71  1.000/0.99
  //   mean x4      0.979/0.80  0.830/0.73  1.000/1.00
  //   face x4      0.899/0.64  0.842/0.64  1.000/0.99
  //   no cap       0.939/0.97  0.772/0.85  1.000/1.00
  // every longer reference length loses the BWB's coverage to quality and collision
  // stops, and a larger ratio buys thickness with coverage and cell quality.
  HeightCapLength height_cap_length = HeightCapLength::kShortestEdge;
  // Smallest accepted visibility min_i n.f_i (cosine of the largest angle between the
  // step direction and an incident face normal); 0.05 is about 87 degrees.
  double min_visibility = 0.05;
  // Cap on the step stretch 1/V; a column with smaller V still steps, but ends less
  // than h above its steepest incident face.
  double max_step_stretch = 5.0;
  // A layer cut below this fraction of its height stops the column instead, so that no
  // sliver layers are made.
  double min_layer_fraction = 0.25;
  // Passes that first turn the columns of failing cells / colliding triangles towards
  // the mean direction of those triangles (keeping half their visibility) before any
  // height is cut; 0 goes straight to height reduction.
  int direction_repair_passes = 2;
  // Exact per-layer intersection check of the new front (off: faster, no guarantee
  // that the envelope is free of self-intersections).
  bool check_collisions = true;
};

struct RangeStats {
  double min = 0.0;
  double mean = 0.0;
  double max = 0.0;
};

struct ExtrusionReport {
  ResolvedGrowthLaw growth;  // the law as resolved (heights before local limiting)
  int n_wall_points = 0;
  int n_wall_triangles = 0;

  // Heights above the wall: per column, the minimum over its incident wall faces of the
  // distance of the column point above the face's plane.
  RangeStats first_height;     // level 1, over columns with >= 1 layer
  RangeStats total_thickness;  // column top, over all columns (0 where none grew)
  RangeStats thickness_fraction;  // total_thickness / target total, over all columns

  double coverage = 0.0;       // fraction of wall triangles whose 3 columns reach N layers
  double area_coverage = 0.0;  // the same weighted by triangle area
  int n_complete_columns = 0;
  std::array<int, kStopReasonCount> stopped_columns{};  // index = StopReason ([0] unused)
  int n_height_capped_columns = 0;    // total scaled down by max_height_to_edge_ratio
  int n_gap_limited_columns = 0;      // total scaled down by the wall-gap cap
  std::vector<int> columns_per_layer; // columns that grew in layer k

  std::int64_t n_wedges = 0;
  std::int64_t n_pyramids = 0;
  std::int64_t n_tets = 0;
  std::int64_t n_points = 0;
  std::int64_t n_invalid_cells = 0;    // independent exact re-check of every cell: must be 0
  double min_scaled_jacobian = 0.0;    // min over cells of min_corner_jacobian
  double min_visibility = 0.0;         // min V over all steps taken

  // Wall-clock seconds per phase.
  double t_setup = 0.0;       // fans, growth law, height caps
  double t_normals = 0.0;     // point normals, smoothing, visibility
  double t_proximity = 0.0;   // ray limiter
  double t_checks = 0.0;      // exact cell validity and front intersection checks
  double t_assembly = 0.0;    // points, cells, arrays
  double t_report = 0.0;      // final re-check and statistics
  double t_total = 0.0;
};

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

// Multi-line human-readable report (the CLI prints it; every field is in ExtrusionReport
// for machine-readable output).
std::string format_extrusion_report(const ExtrusionReport& report);

// Intersecting pairs among the wall triangles (ids 0..F-1) and the envelope triangles
// (ids F..2F-1), decided exactly on the mesh points; adjacency is by shared mesh point,
// so an envelope triangle whose columns did not grow is the wall face itself and is
// skipped. Empty for a valid result.
std::vector<std::pair<int, int>> find_envelope_intersections(
    const TriSurface& wall, const ExtrusionResult& result,
    std::size_t max_pairs = std::numeric_limits<std::size_t>::max());

}  // namespace blayer
