// One layer's steps: how far each column moves along its step direction, limited by
// the proximity of the wall and the current front, then settled by the exact checks
// with direction repair and local height reduction.
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/column_heights.h"
#include "blayer/extruder/column_state.h"
#include "blayer/extruder/front_checker.h"
#include "blayer/extruder/step_directions.h"

namespace blayer {

struct LayerSteps {
  std::vector<double> layer_h;         // target layer height above the incident planes
  std::vector<double> step;            // layer_h / V (1/V capped at max_step_stretch)
  std::vector<double> phi;             // fraction of the step taken (<= 1)
  std::vector<StopReason> phi_reason;  // what lowered phi last
};

// Target steps of layer k for the growing (not stopped) columns; phi = 1.
LayerSteps plan_layer_steps(int k, const ResolvedGrowthLaw& law, const ColumnHeights& heights,
                            const StepDirections& d, const ColumnState& columns, const ExtrusionParams& p);

// Proximity: the step segment, extended to step / proximity_safety, is intersected with
// the wall and current-front triangles not incident to the column (front-facing hits
// only); phi is cut to proximity_safety times the hit distance over the step, smoothed
// downward over height_smoothing_rings, and columns whose phi falls below
// min_layer_fraction stop (kProximity).
void limit_steps_by_proximity(const ProximityRays& rays, const WallTopology& topo, const StepDirections& d,
                              const ExtrusionParams& p, ColumnState* columns, LayerSteps* s);

// Exact checks of the layer with local repair, until every cell of it passes: columns
// of failing cells or colliding triangles are first turned (direction_repair_passes
// attempts, turn_failing_columns), then their phi is halved (and the reduction smoothed
// downward), and a column whose phi falls below min_layer_fraction stops (reason of its
// last failure). Returns which columns grow in this layer; *next holds their new tops
// (the current top for the others).
std::vector<char> settle_layer(const std::vector<Triangle>& triangles, const WallTopology& topo,
                               const ExtrusionParams& p, FrontChecker* checker, StepDirections* d, LayerSteps* s,
                               ColumnState* columns, std::vector<Vec3>* next);

}  // namespace blayer
