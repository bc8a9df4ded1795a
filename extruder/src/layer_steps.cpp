#include "blayer/extruder/layer_steps.h"

#include <algorithm>
#include <cmath>

#include "blayer/extruder/height_smoothing.h"
#include "parallel.h"

namespace blayer {

namespace {

double step_of(double layer_h, double visibility, const ExtrusionParams& p) {
  return layer_h / std::max(visibility, 1.0 / p.max_step_stretch);
}

std::vector<char> growing(const ColumnState& c) {
  std::vector<char> g(c.size());
  for (int v = 0; v < c.size(); ++v) g[v] = !c.stopped[v];
  return g;
}

}  // namespace

LayerSteps plan_layer_steps(int k, const ResolvedGrowthLaw& law, const ColumnHeights& heights,
                            const StepDirections& d, const ColumnState& columns, const ExtrusionParams& p) {
  const int nv = columns.size();
  LayerSteps s;
  s.layer_h.assign(nv, 0.0);
  s.step.assign(nv, 0.0);
  s.phi.assign(nv, 0.0);
  s.phi_reason.assign(nv, StopReason::kNone);
  parallel_vertices(nv, [&](int v) {
    if (columns.stopped[v]) return;
    s.layer_h[v] = heights.base[v] * heights.scale[v] * law.heights[k];
    s.step[v] = step_of(s.layer_h[v], d.visibility[v], p);
    s.phi[v] = 1.0;
    s.phi_reason[v] = StopReason::kProximity;
  });
  return s;
}

void limit_steps_by_proximity(const ProximityRays& rays, const WallTopology& topo, const StepDirections& d,
                              const ExtrusionParams& p, ColumnState* columns, LayerSteps* s) {
  const int nv = columns->size();
  const std::vector<char> active = growing(*columns);
  parallel_vertices(nv, [&](int v) {
    if (!active[v]) return;
    const double gap = rays.first_hit(v, columns->top[v], d.n[v], s->step[v] / p.proximity_safety);
    if (gap < HUGE_VAL) s->phi[v] = std::min(1.0, p.proximity_safety * gap / s->step[v]);
  });
  smooth_downward(topo.vertex_neighbours, active, p.height_smoothing_rings, &s->phi, &s->phi_reason);
  for (int v = 0; v < nv; ++v)
    if (active[v] && s->phi[v] < p.min_layer_fraction) columns->stop(v, s->phi_reason[v]);
}

std::vector<char> settle_layer(const std::vector<Triangle>& triangles, const WallTopology& topo,
                               const ExtrusionParams& p, FrontChecker* checker, StepDirections* d, LayerSteps* s,
                               ColumnState* columns, std::vector<Vec3>* next) {
  const int nv = columns->size();
  std::vector<char> grows = growing(*columns);
  FrontVerdict verdict;
  for (int attempt = 0;; ++attempt) {
    parallel_vertices(nv, [&](int v) {
      (*next)[v] = grows[v] ? columns->top[v] + (s->phi[v] * s->step[v]) * d->n[v] : columns->top[v];
    });
    checker->check(attempt, columns->top, *next, grows, &verdict);
    if (!verdict.any_bad) break;

    if (attempt < p.direction_repair_passes) {
      const std::vector<char> turned =
          turn_failing_columns(triangles, topo, verdict.bad, verdict.bad_triangle, grows, p.min_visibility, d);
      if (std::find(turned.begin(), turned.end(), 1) != turned.end()) {
        for (int v = 0; v < nv; ++v)
          if (turned[v]) s->step[v] = step_of(s->layer_h[v], d->visibility[v], p);
        continue;
      }
    }
    for (int v = 0; v < nv; ++v)
      if (verdict.bad[v]) {
        s->phi[v] *= 0.5;
        s->phi_reason[v] = verdict.reason[v];
      }
    smooth_downward(topo.vertex_neighbours, grows, p.height_smoothing_rings, &s->phi, &s->phi_reason);
    for (int v = 0; v < nv; ++v)
      if (grows[v] && s->phi[v] < p.min_layer_fraction) {
        grows[v] = 0;
        columns->stop(v, s->phi_reason[v]);
      }
  }
  return grows;
}

}  // namespace blayer
