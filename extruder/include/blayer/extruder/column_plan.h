// The planned layer heights of every column, and the rule by which a limit changes
// them: the first height is kept, and a limit compresses the column's upper layers
// (a smaller growth ratio from some layer up, every layer at least the first height)
// before it ends the column early.
#pragma once

#include <vector>

#include "blayer/extruder/extrusion_params.h"
#include "blayer/extruder/growth_law.h"

namespace blayer {

// Two planned heights (or sums of a few) are the same height when they differ by less
// than this relative amount: they come from a handful of multiplications and additions
// of the same numbers (rounding ~1e-16 each), and no limit changes a height by that
// little.
constexpr double kPlannedHeightRelTol = 1e-12;

struct ColumnPlan {
  int n_layers = 0;                  // N of the law
  double growth_ratio = 1.0;         // the law's ratio: no compressed ratio exceeds it
  std::vector<double> heights;       // heights[v * n_layers + k]: planned height of layer k
  std::vector<double> target_total;  // per column: the law's total (x base when relative)
  std::vector<int> planned_layers;   // layers column v will grow unless stopped (<= N)
  std::vector<StopReason> limit;       // first limit that compressed or shortened the column
  std::vector<StopReason> end_reason;  // the limit that last cut planned_layers below N

  double height(int v, int k) const { return heights[static_cast<std::size_t>(v) * n_layers + k]; }
  double& height(int v, int k) { return heights[static_cast<std::size_t>(v) * n_layers + k]; }
  // Sum of the planned heights of layers 0..k of column v (0 for k < 0).
  double cumulative(int v, int k) const;
  // Sum of the planned heights of layers k..planned_layers-1.
  double remaining(int v, int k) const;
};

// The law's heights on every column: h_k x base[v] (base = 1, or the local mean edge
// length for a relative law), all N layers planned, no limit.
ColumnPlan plan_columns(const ResolvedGrowthLaw& law, const std::vector<double>& base);

// Fits layers k..N-1 of column v into `budget` (a height): when their planned sum
// exceeds it, they become p r'^1, p r'^2, ... with p the height of layer k-1 and r' the
// largest ratio that fits, r' <= growth_ratio, and r' < 1 only as far as keeps the top
// layer at least the first height h1; when even that does not fit, only
// floor(budget / h1) layers of height h1 remain planned. k == 0 keeps the first layer's
// height (the layers from 1 up are fitted into budget - h1); a budget below h1 plans no
// layer at all. Records `why` as the column's limit (and as its end reason when layers
// are dropped) when anything changed. Returns whether the plan changed.
bool compress_from(ColumnPlan* plan, int v, int k, double budget, StopReason why);

// Layer k of column v is lowered to `height` (>= the first height, <= planned); the
// layers above it restart the law's growth from that height (h_j = height r^(j-k), never
// above their planned heights), so no ratio exceeds the law's. Records `why`.
void lower_layer(ColumnPlan* plan, int v, int k, double height, StopReason why);

// How many layers column v has after fitting layers k.. at their planned heights into
// `budget` (the terminate policy): k + the count whose running sum stays within it.
int layers_that_fit(const ColumnPlan& plan, int v, int k, double budget);

// Records `why` as column v's limit unless an earlier limit is recorded.
void note_limit(ColumnPlan* plan, int v, StopReason why);

// Ends column v after `layers` layers (planned_layers = min(planned, layers)).
void end_column_after(ColumnPlan* plan, int v, int layers, StopReason why);

}  // namespace blayer
