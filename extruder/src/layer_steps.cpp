#include "blayer/extruder/layer_steps.h"

#include <algorithm>
#include <cmath>

#include "blayer/extruder/height_smoothing.h"
#include "parallel.h"

namespace blayer {

namespace {

std::vector<char> growing(const ColumnState& c) {
  std::vector<char> g(c.size());
  for (int v = 0; v < c.size(); ++v) g[v] = !c.stopped[v];
  return g;
}

double step_of(int k, int v, const ColumnPlan& plan, const WallPlanes& planes, const Vec3& from, const Vec3& d,
               const ExtrusionParams& p) {
  const double h = plan.height(v, k);
  const double s = planes.step_to_height(v, from, d, plan.cumulative(v, k));
  return std::clamp(s, h, p.max_step_stretch * h);
}

// Lowers layer k of every bad column (or ends it), then smooths the lowering downward;
// *lowered[v] is set where layer k's height changed.
void lower_failing_columns(int k, const FrontVerdict& verdict, const WallTopology& topo, const ExtrusionParams& p,
                           const std::vector<double>& start_height, ColumnPlan* plan, ColumnState* columns,
                           std::vector<char>* grows, std::vector<char>* lowered) {
  const int nv = columns->size();
  std::vector<double> fraction(nv, 1.0);
  std::vector<StopReason> why(nv, StopReason::kNone);
  // Each pass writes only column v's own plan, state and flags: the columns run in
  // parallel.
  parallel_vertices(nv, [&](int v) {
    if (!(*grows)[v]) return;
    fraction[v] = plan->height(v, k) / start_height[v];
    if (!verdict.bad[v]) return;
    const double first = plan->height(v, 0);
    const bool at_floor = plan->height(v, k) <= first * (1.0 + kPlannedHeightRelTol);
    if (p.limit_policy == LimitPolicy::kTerminate || k == 0 || at_floor) {
      end_column_after(plan, v, k, verdict.reason[v]);
      columns->stop(v, verdict.reason[v]);
      (*grows)[v] = 0;
      return;
    }
    fraction[v] = std::max(0.5 * plan->height(v, k), first) / start_height[v];
    why[v] = verdict.reason[v];
  });
  smooth_downward(topo.vertex_neighbours, *grows, p.height_smoothing_rings, &fraction, &why);
  parallel_vertices(nv, [&](int v) {
    if (!(*grows)[v]) return;
    const double h = std::max(fraction[v] * start_height[v], plan->height(v, 0));
    if (h < plan->height(v, k)) {
      lower_layer(plan, v, k, h, why[v]);
      (*lowered)[v] = 1;
    }
  });
}

}  // namespace

std::vector<double> layer_steps(int k, const ColumnPlan& plan, const WallPlanes& planes, const StepDirections& d,
                                const ColumnState& columns, const ExtrusionParams& p) {
  std::vector<double> step(columns.size(), 0.0);
  parallel_vertices(columns.size(), [&](int v) {
    if (!columns.stopped[v]) step[v] = step_of(k, v, plan, planes, columns.top[v], d.n[v], p);
  });
  return step;
}

void stop_planned_ends(int k, const ColumnPlan& plan, ColumnState* columns) {
  for (int v = 0; v < columns->size(); ++v)
    if (!columns->stopped[v] && plan.planned_layers[v] <= k) columns->stop(v, plan.end_reason[v]);
}

void stop_fan_groups(int k, const WallTopology& topo, ColumnPlan* plan, ColumnState* columns,
                     std::vector<char>* grows) {
  const Csr& g = topo.group_columns;
  for (int i = 0; i < g.n_rows(); ++i) {
    // The group's stopped columns all stopped in this step (the group stops with its
    // first); of several, the lowest reason, so that the columns' order does not decide.
    bool any_stopped = false;
    StopReason why = StopReason::kNone;
    for (const int* c = g.begin(i); c != g.end(i); ++c)
      if (columns->stopped[*c] && (!any_stopped || columns->reason[*c] < why)) {
        why = columns->reason[*c];
        any_stopped = true;
      }
    if (!any_stopped) continue;
    for (const int* c = g.begin(i); c != g.end(i); ++c) {
      if (columns->stopped[*c]) continue;
      end_column_after(plan, *c, k, why);
      columns->stop(*c, why);
      if (grows) (*grows)[*c] = 0;
    }
  }
}

void limit_by_proximity(int k, const ProximityRays& rays, const WallTopology& topo, const WallPlanes& planes,
                        const StepDirections& d, const ExtrusionParams& p, ColumnPlan* plan, ColumnState* columns,
                        RaySegments* ray_tree) {
  const int nv = columns->size();
  const std::vector<char> active = growing(*columns);
  // The column's allowed total as a fraction of its target: what it has grown plus
  // what the gap ahead allows, or its planned total where nothing is ahead. Smoothing
  // this (not the fraction of the remaining layers) ramps the column tops, as the
  // wall-gap cap does before marching.
  auto visibility = [&](int v) { return std::max(planes.visibility(v, d.n[v]), 1.0 / p.max_step_stretch); };
  std::vector<double> allowed(nv, 1.0), gap;
  // The rays' reach, in `allowed` until the gaps are known.
  parallel_vertices(nv, [&](int v) {
    if (active[v]) allowed[v] = plan->remaining(v, k) / visibility(v) / p.proximity_safety;
  });
  rays.first_hits(active, columns->top, d.n, allowed, &gap, ray_tree);
  parallel_vertices(nv, [&](int v) {
    if (!active[v]) return;
    const double done = plan->cumulative(v, k - 1), remaining = plan->remaining(v, k), vis = visibility(v);
    allowed[v] = (done + remaining) / plan->target_total[v];
    if (gap[v] < HUGE_VAL && p.proximity_safety * gap[v] * vis < remaining)
      allowed[v] = (done + p.proximity_safety * gap[v] * vis) / plan->target_total[v];
  });
  std::vector<StopReason> why(nv, StopReason::kProximity);
  smooth_downward(topo.vertex_neighbours, active, p.height_smoothing_rings, &allowed, &why);
  for (int v = 0; v < nv; ++v) {
    if (!active[v]) continue;
    const double budget = allowed[v] * plan->target_total[v] - plan->cumulative(v, k - 1);
    if (!(budget < plan->remaining(v, k) * (1.0 - kPlannedHeightRelTol))) continue;
    if (p.limit_policy == LimitPolicy::kCompress)
      compress_from(plan, v, k, std::max(budget, 0.0), why[v]);
    else
      end_column_after(plan, v, layers_that_fit(*plan, v, k, budget), why[v]);
  }
  stop_planned_ends(k, *plan, columns);
}

std::vector<char> settle_layer(int k, const std::vector<Triangle>& triangles, const WallTopology& topo,
                               const WallPlanes& planes, const ExtrusionParams& p, FrontChecker* checker,
                               StepDirections* d, ColumnPlan* plan, ColumnState* columns, std::vector<Vec3>* next) {
  const int nv = columns->size();
  std::vector<char> grows = growing(*columns);
  std::vector<double> start_height(nv, 0.0);
  for (int v = 0; v < nv; ++v)
    if (grows[v]) start_height[v] = plan->height(v, k);
  FrontVerdict verdict;
  // The columns whose step is (re)computed: all in the first attempt, then those a
  // repair turned, lowered or stopped. A step depends only on the column's top, its
  // direction, its planned heights and whether it grows, so the others keep theirs.
  std::vector<char> restep(nv, 1), grew;
  for (int attempt = 0;; ++attempt) {
    parallel_vertices(nv, [&](int v) {
      if (!restep[v]) return;
      if (!grows[v]) {
        (*next)[v] = columns->top[v];
        return;
      }
      const Vec3 q = columns->top[v] + step_of(k, v, *plan, planes, columns->top[v], d->n[v], p) * d->n[v];
      // A column on the symmetry plane stays exactly in it (its direction is in the
      // plane; the projection removes the rounding).
      (*next)[v] = topo.on_plane[v] ? topo.plane->project(q) : q;
    });
    checker->check(attempt, columns->top, *next, grows, &verdict);
    if (!verdict.any_bad) break;
    if (attempt < p.direction_repair_passes) {
      std::vector<char> turned =
          turn_failing_columns(triangles, topo, verdict.bad, verdict.bad_triangle, grows, p.min_visibility, d);
      if (std::find(turned.begin(), turned.end(), 1) != turned.end()) {
        restep.swap(turned);
        continue;
      }
    }
    std::fill(restep.begin(), restep.end(), 0);
    grew = grows;
    lower_failing_columns(k, verdict, topo, p, start_height, plan, columns, &grows, &restep);
    stop_fan_groups(k, topo, plan, columns, &grows);
    for (int v = 0; v < nv; ++v) restep[v] = restep[v] || grows[v] != grew[v];
  }
  return grows;
}

}  // namespace blayer
