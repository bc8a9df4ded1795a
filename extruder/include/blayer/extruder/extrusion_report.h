// What an extrusion delivered, measured on the mesh it produced: first heights and
// thicknesses per column (above the incident wall planes and as exact distances to the
// wall, quality/layer_fidelity.h), coverage, the columns each limit compressed or ended,
// the verdict (complete or limited, with shares per reason), cell counts, time per
// phase. Validity is not part of it: the caller's independent check
// (quality/mesh_check.h) decides that.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/column_plan.h"
#include "blayer/extruder/column_state.h"
#include "blayer/extruder/growth_law.h"
#include "blayer/extruder/fan_layout.h"
#include "blayer/extruder/wall_planes.h"
#include "blayer/extruder/wall_topology.h"
#include "blayer/quality/layer_fidelity.h"

namespace blayer {

struct RangeStats {
  double min = 0.0;
  double mean = 0.0;
  double max = 0.0;
};

// A column reaches the thickness when its top stands at least this fraction of its
// target total above its incident wall planes (the verdict's threshold).
constexpr double kThicknessReachedFraction = 0.9;

// Shares of a set of columns by the reason that limited them (index = StopReason;
// [0]: thinner without a recorded limit), as fractions of all columns and of the wall
// area (each column carries a third of its incident triangles' areas).
struct ReasonShares {
  std::array<double, kStopReasonCount> columns{};
  std::array<double, kStopReasonCount> area{};
  double total_columns = 0.0;
  double total_area = 0.0;
};

// Fans at sharp convex edges (fan_layout.h).
struct FanSummary {
  int points = 0;           // wall points with a fan of columns
  int columns = 0;          // their columns (sectors, sub-normals, corner centres)
  int ridge_edges = 0;      // wall edges with a fan strip
  int corners = 0;          // fan points on three or more ridge edges
  int ridge_ends = 0;       // ridge edges from a fan point to a single column
  int fallback_points = 0;  // fan points that fell back to one column (first layer failed)
  int failed_points = 0;    // fan points that still grew no layer in the last attempt
  int attempts = 0;         // marching runs (1 + reruns after fallbacks); 0 without fans
  std::int64_t cells = 0;   // cells on fan strips and corner patches
};

struct ExtrusionReport {
  ResolvedGrowthLaw growth;  // the law as resolved (heights before local limiting)
  int n_wall_points = 0;
  int n_wall_triangles = 0;

  // Heights above the wall, per column the minimum over its incident wall faces of the
  // height of the column point above the face's plane.
  RangeStats first_height;        // level 1, over columns with >= 1 layer
  RangeStats total_thickness;     // column top, over all columns (0 where none grew)
  RangeStats thickness_fraction;  // total_thickness / target total, over all columns
  // The same and more from the mesh alone (layer_fidelity.h): percentiles of first/h1
  // and top/T above the planes and as distance to the wall, shares within 1 % / 10 % of
  // h1 and reaching 0.9 T. Filled for absolute laws (relative laws have no single h1).
  bool has_fidelity = false;
  LayerFidelity fidelity;

  double coverage = 0.0;       // fraction of wall triangles whose 3 columns reach N layers
  double area_coverage = 0.0;  // the same weighted by triangle area
  int n_complete_columns = 0;
  std::array<int, kStopReasonCount> stopped_columns{};  // ended before N, by reason
  std::array<int, kStopReasonCount> limited_columns{};  // compressed or ended, by first limit
  int n_turned_directions = 0;        // column directions turned to stay visible (kKept)
  // kRecomputed: the fronts' most-normal solves that came with a valid warm start from
  // the front below, and those whose certificate held (step_directions.h).
  long n_warm_starts = 0;
  long n_warm_hits = 0;
  // Half models: columns on the symmetry plane, and the largest distance from it of any
  // of their points (0 for a coordinate plane; rounding otherwise).
  int n_symmetry_columns = 0;
  double max_symmetry_distance = 0.0;
  std::vector<int> columns_per_layer; // columns that grew in layer k

  // Verdict: columns whose top is below kThicknessReachedFraction of their target, by
  // the reason that limited them. complete when there are none.
  ReasonShares thin;
  bool complete() const { return thin.total_columns == 0.0; }

  std::int64_t n_wedges = 0;
  std::int64_t n_pyramids = 0;
  std::int64_t n_tets = 0;
  std::int64_t n_hexes = 0;
  std::int64_t n_points = 0;
  FanSummary fans;
  double min_visibility = 0.0;  // min V over all steps taken

  // Wall-clock seconds per phase.
  double t_setup = 0.0;       // wall tables, fans (with discarded attempts), directions, plan
  double t_normals = 0.0;     // directions on every front
  double t_proximity = 0.0;   // ray limiter
  double t_checks = 0.0;      // exact cell validity and front intersection checks
  double t_assembly = 0.0;    // points, cells, arrays
  double t_report = 0.0;      // statistics
  double t_total = 0.0;
};

// Fills the achieved-height, coverage, limit, verdict and cell-count fields of *r from
// the finished columns, their plan and the mesh. Heights are above each column's own
// wall planes; shares count the columns standing on wall triangles (a fan's sub-normal
// and centre columns carry no wall area and are left out).
void summarise_extrusion(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo,
                         const WallPlanes& planes, const ColumnPlan& plan, const ColumnState& columns,
                         const VolumeMesh& mesh, ExtrusionReport* r);

// One line saying what was delivered when the layer is thinner than asked, e.g.
// "12.0 % of the wall (10.5 % of the columns) got less than 90 % of the thickness:
// 9.1 % wall_gap, 2.9 % quality"; empty when complete.
std::string thickness_warning(const ExtrusionReport& r);

// Multi-line human-readable report (the CLI prints it).
std::string format_extrusion_report(const ExtrusionReport& report);

// The report as JSON (the run report's extrusion part): growth law, achieved figures,
// fidelity, coverage, columns by reason, verdict {"outcome": "complete"|"limited",
// "thin_columns": share, "thin_area": share, "by_reason": {...}}, cells, times.
nlohmann::json extrusion_report_to_json(const ExtrusionReport& r);

}  // namespace blayer
