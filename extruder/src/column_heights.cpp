#include "blayer/extruder/column_heights.h"

#include <algorithm>
#include <atomic>
#include <cmath>

#include "blayer/extruder/height_smoothing.h"
#include "parallel.h"

namespace blayer {

namespace {

// The memo's ray from wall point w bitwise equal to `ray` (its gap aside), or null.
const WallGapMemo::Ray* remembered_ray(const WallGapMemo& memo, int w, const WallGapMemo::Ray& ray) {
  if (w + 1 >= static_cast<int>(memo.start.size())) return nullptr;
  for (int i = memo.start[w]; i < memo.start[w + 1]; ++i) {
    const WallGapMemo::Ray& r = memo.rays[i];
    if (same_bits(r.dir, ray.dir) && same_bits(r.reach, ray.reach) && r.on_plane == ray.on_plane) return &r;
  }
  return nullptr;
}

// The memo of this plan's rays (ray[v], for the columns with a direction).
void remember_rays(const WallTopology& topo, const StepDirections& d, const std::vector<WallGapMemo::Ray>& ray,
                   int n_wall_points, WallGapMemo* memo) {
  memo->start.assign(static_cast<std::size_t>(n_wall_points) + 1, 0);
  for (int v = 0; v < topo.n_points(); ++v)
    if (d.ok[v]) ++memo->start[topo.wall_point[v] + 1];
  for (int w = 0; w < n_wall_points; ++w) memo->start[w + 1] += memo->start[w];
  memo->rays.resize(memo->start[n_wall_points]);
  std::vector<int> fill(memo->start.begin(), memo->start.end() - 1);
  for (int v = 0; v < topo.n_points(); ++v)
    if (d.ok[v]) memo->rays[fill[topo.wall_point[v]]++] = ray[v];
}

// Fraction of each column's target total that the wall gap allows (1: no limit).
std::vector<double> wall_gap_fractions(const WallTopology& topo, const ColumnPlan& plan, const ExtrusionParams& p,
                                       const StepDirections& d, const ProximityRays& rays,
                                       const std::vector<Vec3>& wall_points, WallGapMemo* memo) {
  const std::vector<int>& w = topo.wall_point;
  std::vector<double> fraction(topo.n_points(), 1.0);
  std::vector<WallGapMemo::Ray> ray(memo ? topo.n_points() : 0);
  std::atomic<long> reused{0};
  parallel_vertices(topo.n_points(), [&](int v) {
    if (!d.ok[v]) return;
    const double vis = std::max(d.visibility[v], 1.0 / p.max_step_stretch);
    const double path = plan.target_total[v] / vis;
    const double reach = path / p.proximity_safety;
    const WallGapMemo::Ray* known = nullptr;
    if (memo) {
      ray[v] = {d.n[v], reach, rays.on_plane && (*rays.on_plane)[v], 0.0};
      known = remembered_ray(*memo, w[v], ray[v]);
      if (known) reused.fetch_add(1, std::memory_order_relaxed);
    }
    const double gap = known ? known->gap : rays.first_hit(v, wall_points[w[v]], d.n[v], reach);
    if (memo) ray[v].gap = gap;
    if (gap < HUGE_VAL) fraction[v] = std::min(1.0, p.proximity_safety * gap * vis / plan.target_total[v]);
  });
  if (memo) {
    memo->reused += reused.load();
    remember_rays(topo, d, ray, static_cast<int>(wall_points.size()), memo);
  }
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
                               const StepDirections& wall_directions, const ProximityRays& wall_rays,
                               WallGapMemo* gap_memo) {
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
  std::vector<double> fraction =
      wall_gap_fractions(topo, plan, p, wall_directions, wall_rays, wall.points, gap_memo);
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
