// One layer's steps: how far each column moves along its direction so that its new
// point stands at the column's planned cumulative height above its incident wall
// planes, the proximity limit of the fronts ahead, and the exact checks that settle the
// layer with direction repair, then lowering, then ending columns (LimitPolicy).
#pragma once

#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/column_plan.h"
#include "blayer/extruder/column_state.h"
#include "blayer/extruder/front_checker.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_planes.h"

namespace blayer {

// Path length of layer k's step of every growing column (0 for the others): the step
// that lifts the column's new point to plan.cumulative(v, k) above its incident wall
// planes (WallPlanes::step_to_height), kept within [h_k, max_step_stretch x h_k] so
// that a layer is never shorter than its height nor a needle.
std::vector<double> layer_steps(int k, const ColumnPlan& plan, const WallPlanes& planes, const StepDirections& d,
                                const ColumnState& columns, const ExtrusionParams& p);

// Columns whose plan ends before layer k stop now, with the limit that ended the plan.
void stop_planned_ends(int k, const ColumnPlan& plan, ColumnState* columns);

// The columns of a fan point grow together (their strip cells have no closure for a
// fan split in between): once one of them has stopped, the others stop after the same
// k layers with its reason (the lowest of those that stopped together) and, with grows,
// do not grow in layer k. Called after each stopper of the march (planned ends,
// visibility, proximity, the checks).
void stop_fan_groups(int k, const WallTopology& topo, ColumnPlan* plan, ColumnState* columns,
                     std::vector<char>* grows = nullptr);

// Proximity of the fronts ahead: the column's remaining path (remaining planned height
// over its wall visibility) is extended by 1 / proximity_safety and intersected with
// the wall and current-front triangles not incident to it (front-facing hits only).
// A hit at distance g allows the remaining layers proximity_safety x g x V of height;
// that fraction of the remaining plan is smoothed downward over height_smoothing_rings
// and the columns are fitted into it: compressed from layer k up (kCompress) or ended
// after the layers that fit at the law's heights (kTerminate), reason kProximity.
// Columns left with no layer at k stop. ray_tree, when given, keeps the rays' tree from
// one layer to the next (ProximityRays::first_hits).
void limit_by_proximity(int k, const ProximityRays& rays, const WallTopology& topo, const WallPlanes& planes,
                        const StepDirections& d, const ExtrusionParams& p, ColumnPlan* plan, ColumnState* columns,
                        RaySegments* ray_tree = nullptr);

// Exact checks of layer k with local repair, until every cell of it passes. Columns of
// failing cells or colliding triangles are
//   1. turned (direction_repair_passes attempts, turn_failing_columns);
//   2. kCompress: lowered -- the layer's height is halved, never below the first
//      height, the layers above restart the law from it (lower_layer), and the lowering
//      is smoothed downward over height_smoothing_rings among the growing columns;
//   3. ended at k layers when the layer is already at the first height, when k == 0
//      (the first height is kept: a first layer that cannot be made valid is not grown),
//      or at once under kTerminate; reason kQuality (a failing cell) or kCollision;
//      the other columns of its fan point end with it (stop_fan_groups).
// Returns which columns grow in this layer; *next holds their new tops (the current top
// for the others).
std::vector<char> settle_layer(int k, const std::vector<Triangle>& triangles, const WallTopology& topo,
                               const WallPlanes& planes, const ExtrusionParams& p, FrontChecker* checker,
                               StepDirections* d, ColumnPlan* plan, ColumnState* columns, std::vector<Vec3>* next);

}  // namespace blayer
