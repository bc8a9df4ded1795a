#include "blayer/extruder/column_heights.h"

#include <algorithm>
#include <cmath>

#include "blayer/extruder/height_smoothing.h"
#include "parallel.h"

namespace blayer {

namespace {

// The wall length the height cap multiplies at v.
double cap_length(const TriSurface& wall, const WallTopology& topo, const EdgeLengths& edges, HeightCapLength which,
                  int v) {
  switch (which) {
    case HeightCapLength::kShortestEdge: return edges.shortest[v];
    case HeightCapLength::kMeanEdge: return edges.mean[v];
    case HeightCapLength::kFaceSize: {
      const Csr& vtri = topo.vertex_triangles;
      double area = 0.0;
      for (const int* f = vtri.begin(v); f != vtri.end(v); ++f)
        area += 0.5 * norm(triangle_area_vector(wall, wall.triangles[*f]));
      const int n = vtri.size(v);
      return n > 0 ? std::sqrt(2.0 * area / n) : 0.0;
    }
  }
  return edges.shortest[v];
}

void apply_height_cap(const TriSurface& wall, const WallTopology& topo, const ResolvedGrowthLaw& law,
                      const ExtrusionParams& p, ColumnHeights* h) {
  if (!(p.max_height_to_edge_ratio > 0.0)) return;
  const EdgeLengths edges = wall_edge_lengths(wall, topo);
  parallel_vertices(topo.n_points(), [&](int v) {
    const double target = h->base[v] * law.total_thickness;
    const double cap = p.max_height_to_edge_ratio * cap_length(wall, topo, edges, p.height_cap_length, v);
    if (topo.used[v] && target > cap) {
      h->scale[v] = cap / target;
      h->capped[v] = 1;
    }
  });
}

void apply_wall_gap_cap(const WallTopology& topo, const ResolvedGrowthLaw& law, const ExtrusionParams& p,
                        const StepDirections& d, const ProximityRays& rays, const std::vector<Vec3>& wall_points,
                        ColumnHeights* h) {
  parallel_vertices(topo.n_points(), [&](int v) {
    if (!d.ok[v]) return;
    const double extent =
        h->base[v] * h->scale[v] * law.total_thickness / std::max(d.visibility[v], 1.0 / p.max_step_stretch);
    const double gap = rays.first_hit(v, wall_points[v], d.n[v], extent / p.proximity_safety);
    if (gap < HUGE_VAL && extent > p.proximity_safety * gap) {
      h->scale[v] *= p.proximity_safety * gap / extent;
      h->gap_limited[v] = 1;
    }
  });
}

}  // namespace

EdgeLengths wall_edge_lengths(const TriSurface& wall, const WallTopology& topo) {
  const int nv = topo.n_points();
  const Csr& nbr = topo.vertex_neighbours;
  EdgeLengths e;
  e.mean.assign(nv, 0.0);
  e.shortest.assign(nv, 0.0);
  parallel_vertices(nv, [&](int v) {
    const int k = nbr.size(v);
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

ColumnHeights plan_column_heights(const TriSurface& wall, const WallTopology& topo, const ResolvedGrowthLaw& law,
                                  const ExtrusionParams& p, const StepDirections& wall_directions,
                                  const ProximityRays& wall_rays) {
  const int nv = topo.n_points();
  ColumnHeights h;
  h.base.assign(nv, 1.0);
  if (law.relative) h.base = wall_edge_lengths(wall, topo).mean;
  h.scale.assign(nv, 1.0);
  h.capped.assign(nv, 0);
  h.gap_limited.assign(nv, 0);
  apply_height_cap(wall, topo, law, p, &h);
  apply_wall_gap_cap(topo, law, p, wall_directions, wall_rays, wall.points, &h);
  std::vector<StopReason> reason(nv, StopReason::kNone);
  smooth_downward(topo.vertex_neighbours, topo.used, p.height_smoothing_rings, &h.scale, &reason);
  return h;
}

}  // namespace blayer
