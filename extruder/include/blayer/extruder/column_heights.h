// Column heights before marching: the growth law's heights per column (times the local
// mean edge length when the law is relative), and the caps on a column's total height
// known from the wall alone.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/extrusion_params.h"
#include "blayer/extruder/proximity_rays.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_topology.h"

namespace blayer {

struct ColumnHeights {
  // base[v] * scale[v] * law.heights[k] is the target height of layer k in column v.
  std::vector<double> base;   // 1, or the mean wall edge length at v for a relative law
  std::vector<double> scale;  // <= 1: the caps below, smoothed downward
  std::vector<char> capped;       // scaled down by max_height_to_edge_ratio
  std::vector<char> gap_limited;  // scaled down by the wall-gap cap
};

// Mean and shortest length of the wall edges at each point (0 for unused points).
// Relative heights use the mean (the vertex's size); the default height cap uses the
// shortest, because on stretched triangles the short side is the distance over which
// neighbouring columns must not overtake each other sideways.
struct EdgeLengths {
  std::vector<double> mean;
  std::vector<double> shortest;
};
EdgeLengths wall_edge_lengths(const TriSurface& wall, const WallTopology& topo);

// The two caps, both scaling all layers of a column alike:
//   height cap  total <= max_height_to_edge_ratio x the height_cap_length at v;
//   wall gap    the whole column (about total / V long, V its wall visibility, 1/V
//               capped at max_step_stretch) spans at most proximity_safety of the
//               distance to the wall part its wall direction faces (rays: wall only).
// The scale is smoothed downward over height_smoothing_rings.
ColumnHeights plan_column_heights(const TriSurface& wall, const WallTopology& topo, const ResolvedGrowthLaw& law,
                                  const ExtrusionParams& p, const StepDirections& wall_directions,
                                  const ProximityRays& wall_rays);

}  // namespace blayer
