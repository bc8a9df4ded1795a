// Column heights before marching: the growth law on every column (times the local mean
// edge length when the law is relative), fitted into the gap to the wall that each
// column faces, and ended where a layer would outgrow the wall spacing when
// max_layer_aspect is set.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/column_plan.h"
#include "blayer/extruder/extrusion_params.h"
#include "blayer/extruder/proximity_rays.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_topology.h"

namespace blayer {

// Mean and shortest length of the wall edges at each point (0 for unused points).
struct EdgeLengths {
  std::vector<double> mean;
  std::vector<double> shortest;
};
EdgeLengths wall_edge_lengths(const TriSurface& wall, const WallTopology& topo);

// The wall-gap rays of a run's previous attempt (extrude_layers.cpp plans again after
// fan points fall back), grouped by wall point. A wall-gap ray is a pure function of its
// column's wall point, direction, reach and whether the column is on the symmetry plane,
// so a column whose ray is bitwise one of the previous attempt's takes its gap: most
// columns keep their directions from one fan round to the next.
struct WallGapMemo {
  struct Ray {
    Vec3 dir;
    double reach = 0.0;
    bool on_plane = false;
    double gap = 0.0;
  };
  std::vector<int> start;  // per wall point, with a final end: its rays in rays[start[w], start[w + 1])
  std::vector<Ray> rays;
  long reused = 0;  // gaps taken from the memo, over the run
};

// The plan before marching:
//   law        h_k x base (base: 1, or the mean wall edge length at v when relative);
//   wall gap   a column may cover at most proximity_safety of the distance, along its
//              wall direction, to the wall part it faces (rays against the wall only):
//              the budget proximity_safety x gap x V (V: the direction's visibility
//              over the incident wall faces, so the budget is a height above them) is
//              smoothed downward over height_smoothing_rings (as a fraction of the
//              column's target), and the column is compressed into it (compress_from:
//              the first height is kept; a gap below first height / proximity_safety
//              plans no layer, reason kWallGap);
//   aspect     with max_layer_aspect > 0, the column ends before the first layer
//              higher than max_layer_aspect x the mean wall edge length at v
//              (reason kAspectRatio).
// A fan point's columns (topo.group_columns) all plan the layers of the shortest of
// them: they grow together.
// wall_topo: the wall's own tables (build_wall_topology(wall)); topo: the columns'
// (wall_topo itself, or a layout's build_column_topology). gap_memo (optional): the
// previous attempt's rays, replaced by this plan's.
ColumnPlan plan_column_heights(const TriSurface& wall, const WallTopology& wall_topo, const WallTopology& topo,
                               const ResolvedGrowthLaw& law, const ExtrusionParams& p,
                               const StepDirections& wall_directions, const ProximityRays& wall_rays,
                               WallGapMemo* gap_memo = nullptr);

}  // namespace blayer
