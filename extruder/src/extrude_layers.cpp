#include "blayer/extruder/extrude_layers.h"

#include <algorithm>
#include <cmath>

#include "blayer/core/assert.h"
#include "blayer/core/errors.h"
#include "blayer/core/stopwatch.h"
#include "blayer/extruder/column_heights.h"
#include "blayer/extruder/column_plan.h"
#include "blayer/extruder/column_state.h"
#include "blayer/extruder/front_checker.h"
#include "blayer/extruder/layer_assembly.h"
#include "blayer/extruder/layer_steps.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_planes.h"
#include "blayer/extruder/wall_topology.h"
#include "blayer/quality/cell_validity.h"

namespace blayer {

namespace {


// A column point below its planned height above the wall planes by more than this
// relative amount was held back by the step-stretch cap (the step formula is exact
// otherwise; 1e-9 is far above its rounding).
constexpr double kShortfallTolerance = 1e-9;

void check_wall(const TriSurface& wall) {
  const int nv = static_cast<int>(wall.points.size());
  for (const Triangle& t : wall.triangles)
    for (int v : t)
      if (v < 0 || v >= nv) throw InputError("extrude_layers: a wall triangle refers to a missing point");
}

// Every cell of the layer mesh passes the exact validity test: what the per-layer checks
// guarantee, re-established from scratch (checked builds only; the caller's mesh check
// is the run's decision).
// Marching attempts with fans: the first, and reruns after fan points fell back to one
// column. A failed first layer at a fan point is rare (the fan's cells are as valid as
// the wall's own where the sectors are smooth), so two reruns cover what happens.
constexpr int kMaxFanAttempts = 3;

[[maybe_unused]] bool every_cell_valid(const VolumeMesh& m) {
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    Vec3 corners[8];
    const int n = corner_count(m.cell_types[c]);
    for (int i = 0; i < n; ++i) corners[i] = m.points[m.connectivity[m.offsets[c] + i]];
    if (cell_validity(m.cell_types[c], corners) != Validity::kValid) return false;
  }
  return true;
}

std::vector<char> growing(const ColumnState& c) {
  std::vector<char> g(c.size());
  for (int v = 0; v < c.size(); ++v) g[v] = !c.stopped[v];
  return g;
}


// One marching run on a column layout (fan_layout.h).
ExtrusionResult march(const TriSurface& wall, const ColumnLayout& layout, WallTopology topo,
                      const ExtrusionParams& params, const std::function<void(int, int)>& progress) {
  const Stopwatch total;
  ExtrusionResult res;
  ExtrusionReport& rep = res.report;
  rep.growth = resolve_growth_law(params.growth);
  rep.n_wall_points = static_cast<int>(wall.points.size());
  rep.n_wall_triangles = static_cast<int>(wall.triangles.size());

  // Setup: wall directions, checker trees, column plan.
  Stopwatch phase;
  const WallPlanes planes(wall, layout, topo);
  const TriSurface& start = layout.front;
  StepDirections dirs;
  if (layout.has_fans()) {
    PrescribedDirections fan{layout.direction, std::vector<double>(layout.n_columns(), 0.0)};
    for (int c = 0; c < layout.n_columns(); ++c)
      if (layout.in_fan[c]) fan.visibility[c] = planes.visibility(c, fan.n[c]);
    dirs = compute_step_directions(start, topo, topo.used, params, &fan);
  } else {
    dirs = compute_step_directions(start, topo, topo.used, params);
  }
  FrontChecker checker(wall, layout, topo, params.check_collisions);
  ColumnPlan plan = plan_column_heights(wall, topo, rep.growth, params, dirs, checker.wall_rays());
  ColumnState columns = ColumnState::on_wall(start.points, topo.used, layout.wall_point);
  LayerAssembler assembler(wall, layout, dirs);
  TriSurface front;
  front.triangles = start.triangles;
  std::vector<Vec3> next(start.points.size());
  rep.t_setup = phase.seconds();

  for (int k = 0; k < rep.growth.layers; ++k) {
    stop_planned_ends(k, plan, &columns);
    stop_fan_groups(k, topo, &plan, &columns);
    const std::vector<char> active = growing(columns);
    if (std::find(active.begin(), active.end(), 1) == active.end()) break;

    phase.restart();
    if (k > 0) {
      front.points = columns.top;
      int n_turned = 0;
      dirs = update_step_directions(front, topo, active, params, dirs, &n_turned);
      rep.n_turned_directions += n_turned;
    }
    for (int v = 0; v < columns.size(); ++v)
      if (active[v] && !dirs.ok[v]) {
        end_column_after(&plan, v, k, StopReason::kVisibility);
        columns.stop(v, StopReason::kVisibility);
      }
    stop_fan_groups(k, topo, &plan, &columns);
    rep.t_normals += phase.seconds();

    phase.restart();
    checker.begin_layer(k, columns.top, columns.layers);
    limit_by_proximity(k, checker.front_rays(), topo, planes, dirs, params, &plan, &columns);
    stop_fan_groups(k, topo, &plan, &columns);
    rep.t_proximity += phase.seconds();

    phase.restart();
    const std::vector<char> grows =
        settle_layer(k, start.triangles, topo, planes, params, &checker, &dirs, &plan, &columns, &next);
    rep.t_checks += phase.seconds();
    for (int v = 0; v < columns.size(); ++v)
      if (grows[v] && planes.height_above(v, next[v]) < (1.0 - kShortfallTolerance) * plan.cumulative(v, k))
        note_limit(&plan, v, StopReason::kStepStretch);

    phase.restart();
    assembler.commit_layer(k, grows, next, dirs, &columns);
    rep.t_assembly += phase.seconds();
    if (progress) progress(k + 1, rep.growth.layers);
  }
  // The marching state is no longer needed; freeing it here keeps it out of the peak
  // memory, which is reached while the output arrays are filled.
  checker.release();

  phase.restart();
  res.mesh = assembler.finish(columns);
  BLAYER_EXPENSIVE_ASSERT(every_cell_valid(res.mesh));
  res.envelope.points = columns.top;
  res.envelope.triangles = start.triangles;
  res.envelope_point_ids = columns.top_id;
  res.column_layers = columns.layers;
  res.stop_reason = columns.reason;
  res.column_wall_point = layout.wall_point;
  rep.columns_per_layer = assembler.columns_per_layer();
  rep.fans.cells = assembler.fan_cells();
  rep.min_visibility = rep.columns_per_layer.empty() ? 0.0 : assembler.min_visibility();
  rep.t_assembly += phase.seconds();

  phase.restart();
  summarise_extrusion(wall, layout, topo, planes, plan, columns, res.mesh, &rep);
  if (topo.plane) {
    for (int v = 0; v < topo.n_points(); ++v) rep.n_symmetry_columns += topo.on_plane[v];
    const std::vector<int>& column_of = assembler.point_column();
    for (std::size_t q = 0; q < res.mesh.points.size(); ++q)
      if (topo.on_plane[column_of[q]])
        rep.max_symmetry_distance =
            std::max(rep.max_symmetry_distance, std::fabs(topo.plane->signed_distance(res.mesh.points[q])));
  }
  rep.t_report = phase.seconds();
  rep.t_total = total.seconds();
  return res;
}

// Fan points none of whose columns grew a layer because a cell, a collision or the
// visibility stopped them: they fall back to one column in the next attempt.
std::vector<int> failed_fan_points(const ColumnLayout& layout, const ExtrusionResult& res) {
  std::vector<int> failed;
  for (int c = 0; c < layout.n_columns(); ++c) {
    if (!layout.in_fan[c] || res.column_layers[c] > 0) continue;
    const StopReason r = res.stop_reason[c];
    if (r == StopReason::kQuality || r == StopReason::kCollision || r == StopReason::kVisibility)
      failed.push_back(layout.wall_point[c]);
  }
  std::sort(failed.begin(), failed.end());
  failed.erase(std::unique(failed.begin(), failed.end()), failed.end());
  return failed;
}

}  // namespace

ExtrusionResult extrude_layers(const TriSurface& wall, const ExtrusionParams& params,
                               const std::function<void(int, int)>& progress) {
  const Stopwatch total;
  check_extrusion_params(params);
  check_wall(wall);
  WallTopology wall_topo = build_wall_topology(wall, params.symmetry);
  if (!(params.fan_angle_deg > 0.0)) {
    ColumnLayout layout = single_column_layout(wall);
    return march(wall, layout, std::move(wall_topo), params, progress);
  }
  // Fans; a fan point whose fan cannot grow its first layer falls back to one column,
  // and the extrusion is marched again (each attempt removes at least one fan point).
  const FanParams fp{params.fan_angle_deg, params.fan_max_sector_deg};
  std::vector<char> excluded = wall_topo.on_plane;
  int n_fallback = 0;
  for (int attempt = 0;; ++attempt) {
    const Stopwatch layout_time;
    const ColumnLayout layout = build_column_layout(wall, wall_topo.fans, fp, params.normal_method, excluded);
    const double t_layout = layout_time.seconds();
    ExtrusionResult res = march(wall, layout, build_column_topology(layout, params.symmetry), params, progress);
    const std::vector<int> failed = failed_fan_points(layout, res);
    if (failed.empty() || attempt + 1 >= kMaxFanAttempts) {
      FanSummary& f = res.report.fans;
      f.points = layout.n_fan_points;
      f.columns = 0;
      for (char x : layout.in_fan) f.columns += x;
      f.ridge_edges = layout.n_ridge_edges;
      f.corners = layout.n_corners;
      f.chains_skipped = layout.n_chains_skipped;
      f.fallback_points = n_fallback;
      f.failed_points = static_cast<int>(failed.size());
      f.attempts = attempt + 1;
      res.report.t_setup += t_layout;
      res.report.t_total = total.seconds();
      return res;
    }
    for (int w : failed) excluded[w] = 1;
    n_fallback += static_cast<int>(failed.size());
  }
}

}  // namespace blayer
