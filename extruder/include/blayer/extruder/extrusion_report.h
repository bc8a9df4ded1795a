// What an extrusion delivered: the resolved growth law, achieved heights, coverage,
// stops per reason, cell counts, and time per phase. Validity is not part of it: the
// caller's independent check (quality/mesh_check.h) decides that.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/column_heights.h"
#include "blayer/extruder/column_state.h"
#include "blayer/extruder/growth_law.h"
#include "blayer/extruder/wall_topology.h"

namespace blayer {

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
  double min_visibility = 0.0;         // min V over all steps taken

  // Wall-clock seconds per phase.
  double t_setup = 0.0;       // fans, growth law, height caps
  double t_normals = 0.0;     // point normals, smoothing, visibility
  double t_proximity = 0.0;   // ray limiter
  double t_checks = 0.0;      // exact cell validity and front intersection checks
  double t_assembly = 0.0;    // points, cells, arrays
  double t_report = 0.0;      // statistics
  double t_total = 0.0;
};

// Fills the achieved-height, coverage, stop and cell-count fields of *r from the
// finished columns and mesh (point_column[p]: the column of mesh point p).
void summarise_extrusion(const TriSurface& wall, const WallTopology& topo, const ColumnHeights& heights,
                         const ColumnState& columns, const VolumeMesh& mesh, const std::vector<int>& point_column,
                         ExtrusionReport* r);

// Multi-line human-readable report (the CLI prints it; every field is in ExtrusionReport
// for machine-readable output).
std::string format_extrusion_report(const ExtrusionReport& report);

}  // namespace blayer
