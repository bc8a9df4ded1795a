#include "blayer/extruder/column_heights.h"

#include <algorithm>
#include <cmath>

#include "blayer/extruder/height_smoothing.h"
#include "parallel.h"

namespace blayer {

namespace {

// Fraction of each column's target total that the wall gap allows (1: no limit).
std::vector<double> wall_gap_fractions(const WallTopology& topo, const ColumnPlan& plan, const ExtrusionParams& p,
                                       const StepDirections& d, const ProximityRays& rays,
                                       const std::vector<Vec3>& wall_points) {
  const std::vector<int>& w = topo.wall_point;
  std::vector<double> fraction(topo.n_points(), 1.0);
  parallel_vertices(topo.n_points(), [&](int v) {
    if (!d.ok[v]) return;
    const double vis = std::max(d.visibility[v], 1.0 / p.max_step_stretch);
    const double path = plan.target_total[v] / vis;
    const double gap = rays.first_hit(v, wall_points[w[v]], d.n[v], path / p.proximity_safety);
    if (gap < HUGE_VAL) fraction[v] = std::min(1.0, p.proximity_safety * gap * vis / plan.target_total[v]);
  });
  return fraction;
}

void end_at_aspect_ratio(const EdgeLengths& edges, const ExtrusionParams& p, ColumnPlan* plan) {
  if (!(p.max_layer_aspect > 0.0)) return;
  for (int v = 0; v < static_cast<int>(edges.mean.size()); ++v)
    for (int k = 0; k < plan->planned_layers[v]; ++k)
      if (plan->height(v, k) > p.max_layer_aspect * edges.mean[v]) {
        end_column_after(plan, v, k, StopReason::kAspectRatio);
        break;
      }
}

// A fan point's columns grow together (the strips between them need every column), so
// each plans the layers of its group's shortest, with that column's reason.
void end_fan_groups_together(const WallTopology& topo, ColumnPlan* plan) {
  const Csr& g = topo.group_columns;
  for (int i = 0; i < g.n_rows(); ++i) {
    const int* shortest = std::min_element(g.begin(i), g.end(i), [&](int a, int b) {
      return plan->planned_layers[a] < plan->planned_layers[b];
    });
    for (const int* c = g.begin(i); c != g.end(i); ++c)
      end_column_after(plan, *c, plan->planned_layers[*shortest], plan->end_reason[*shortest]);
  }
}

}  // namespace

EdgeLengths wall_edge_lengths(const TriSurface& wall, const WallTopology& topo) {
  const int nv = topo.n_points();
  const Csr& nbr = topo.vertex_neighbours;
  EdgeLengths e;
  e.mean.assign(nv, 0.0);
  e.shortest.assign(nv, 0.0);
  parallel_vertices(nv, [&](int v) {
    const int k = nbr.count(v);
    if (k == 0) return;
    double s = 0.0, m = HUGE_VAL;
    for (const int* u = nbr.begin(v); u != nbr.end(v); ++u) {
      const double l = norm(wall.points[*u] - wall.points[v]);
      s += l;
      m = std::min(m, l);
    }
    e.mean[v] = s / k;
    e.shortest[v] = m;
  });
  return e;
}

ColumnPlan plan_column_heights(const TriSurface& wall, const WallTopology& wall_topo, const WallTopology& topo,
                               const ResolvedGrowthLaw& law, const ExtrusionParams& p,
                               const StepDirections& wall_directions, const ProximityRays& wall_rays) {
  const int nv = topo.n_points();
  // The wall's own spacing at each column's wall point (a fan's columns share it).
  const EdgeLengths at_point = wall_edge_lengths(wall, wall_topo);
  EdgeLengths edges;
  edges.mean.resize(nv);
  edges.shortest.resize(nv);
  for (int v = 0; v < nv; ++v) {
    edges.mean[v] = at_point.mean[topo.wall_point[v]];
    edges.shortest[v] = at_point.shortest[topo.wall_point[v]];
  }
  ColumnPlan plan = plan_columns(law, law.relative ? edges.mean : std::vector<double>(nv, 1.0));
  std::vector<double> fraction = wall_gap_fractions(topo, plan, p, wall_directions, wall_rays, wall.points);
  std::vector<StopReason> reason(nv, StopReason::kWallGap);
  smooth_downward(topo.vertex_neighbours, topo.used, p.height_smoothing_rings, &fraction, &reason);
  for (int v = 0; v < nv; ++v) {
    if (!topo.used[v] || !(fraction[v] < 1.0)) continue;
    const double budget = fraction[v] * plan.target_total[v];
    if (p.limit_policy == LimitPolicy::kCompress)
      compress_from(&plan, v, 0, budget, reason[v]);
    else
      end_column_after(&plan, v, layers_that_fit(plan, v, 0, budget), reason[v]);
  }
  end_at_aspect_ratio(edges, p, &plan);
  end_fan_groups_together(topo, &plan);
  return plan;
}

}  // namespace blayer
