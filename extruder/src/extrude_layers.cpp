#include "blayer/extruder/extrude_layers.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "blayer/core/assert.h"
#include "blayer/core/errors.h"
#include "blayer/core/stopwatch.h"
#include "blayer/extruder/column_heights.h"
#include "blayer/extruder/column_plan.h"
#include "blayer/extruder/column_state.h"
#include "blayer/extruder/front_checker.h"
#include "blayer/extruder/layer_assembly.h"
#include "blayer/extruder/layer_steps.h"
#include "blayer/extruder/proximity_rays.h"
#include "blayer/extruder/step_directions.h"
#include "blayer/extruder/wall_planes.h"
#include "blayer/extruder/wall_topology.h"
#include "blayer/quality/cell_validity.h"
#include "fan_precheck.h"

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

// Marching attempts with fans: the first, and reruns after fan points fell back to one
// column. A failed first layer at a fan point is rare (the fan's cells are as valid as
// the wall's own where the sectors are smooth), so two reruns cover what happens.
constexpr int kMaxFanAttempts = 3;
// Rounds of the straight-layer precheck before every remaining fan point falls back.
constexpr int kMaxPrecheckRounds = 3;

// Every cell of the layer mesh passes the exact validity test: what the per-layer checks
// guarantee, re-established from scratch (checked builds only; the caller's mesh check
// is the run's decision).
[[maybe_unused]] bool every_cell_valid(const VolumeMesh& m) {
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    Vec3 corners[8];
    const int n = corner_count(m.cell_types[c]);
    for (int i = 0; i < n; ++i) corners[i] = m.points[m.connectivity[m.offsets[c] + i]];
    if (!cell_is_valid(m.cell_types[c], corners)) return false;
  }
  return true;
}

std::vector<char> growing(const ColumnState& c) {
  std::vector<char> g(c.size());
  for (int v = 0; v < c.size(); ++v) g[v] = !c.stopped[v];
  return g;
}


// Wall directions: fan columns take their sector or sub-normal directions; a single
// column at a ridge end, whose fan on the front holds the strip ends' (still flat)
// triangles, takes the wall's own normal at its point.
StepDirections wall_directions(const TriSurface& wall, const WallTopology& wall_topo, const ColumnLayout& layout,
                               const WallTopology& topo, const WallPlanes& planes, const ExtrusionParams& params,
                               WallNormalMemo* memo, FrontWarmStarts* warm) {
  if (!layout.has_fans()) return compute_step_directions(layout.front, topo, topo.used, params, nullptr, memo, warm);
  PrescribedDirections fan{layout.direction, std::vector<double>(layout.n_columns(), 0.0)};
  for (const LayerElement& e : layout.elements) {
    if (e.kind != ElementKind::kStripEnd) continue;
    const int c = e.column[0];
    if (norm2(fan.n[c]) > 0.0) continue;
    const VertexNormal n = surface_point_normal(wall, wall_topo, layout.wall_point[c], params.normal_method);
    if (n.status != NormalStatus::kNoVisibleDirection && is_finite(n.normal)) fan.n[c] = n.normal;
  }
  for (int c = 0; c < layout.n_columns(); ++c)
    if (norm2(fan.n[c]) > 0.0) fan.visibility[c] = planes.visibility(c, fan.n[c]);
  return compute_step_directions(layout.front, topo, topo.used, params, &fan, memo, warm);
}

// Fan points none of whose columns grew a layer because a cell, a collision or the
// visibility stopped them: they fall back to one column in the next attempt. Known
// once layer 0 is committed (a column that grew no layer then never will).
std::vector<int> failed_fan_points(const ColumnLayout& layout, const std::vector<int>& layers,
                                   const std::vector<StopReason>& reason) {
  std::vector<int> failed;
  for (int c = 0; c < layout.n_columns(); ++c) {
    if (!layout.in_fan[c] || layers[c] > 0) continue;
    const StopReason r = reason[c];
    if (r == StopReason::kQuality || r == StopReason::kCollision || r == StopReason::kVisibility)
      failed.push_back(layout.wall_point[c]);
  }
  std::sort(failed.begin(), failed.end());
  failed.erase(std::unique(failed.begin(), failed.end()), failed.end());
  return failed;
}

// Fan points that fall back to one column, found by a marching run that then stops
// without a mesh: before marching, by the straight-layer precheck; after layer 0, those
// of failed_fan_points (only when asked to stop there, i.e. another attempt follows).
// last_precheck_round (set by the caller): a failing precheck sends every fan point
// back, so the precheck only needs to find one.
struct FanFailures {
  bool last_precheck_round = false;
  std::vector<int> precheck, first_layer;
};

// One marching run on a column layout (fan_layout.h). Returns without a mesh when fan
// points fail (*fan_failures): on straight columns before marching, or, with
// stop_at_failed_fans, in layer 0.
// wall_tree: the run's, built once for all attempts; freed here when the march
// delivers its mesh, before the output arrays that set the peak memory. precheck: the
// run's, which carries each round's verdicts to the next (fan_precheck.h). normal_memo:
// the run's wall normals of the earlier attempts (step_directions.h), the cheap ones
// dropped when the attempt marches, or null; gap_memo:
// the wall-gap rays of the previous precheck round (column_heights.h), dropped when the
// attempt marches, or null.
// shared_layout: the attempt's layout, which the checker reads without a copy.
ExtrusionResult march(const TriSurface& wall, const WallTopology& wall_topo,
                      const std::shared_ptr<const ColumnLayout>& shared_layout,
                      const WallTopology& topo, const ExtrusionParams& params,
                      const std::function<void(int, int)>& progress, bool stop_at_failed_fans,
                      std::unique_ptr<WallTree>* wall_tree, FanPrecheck* precheck, FanFailures* fan_failures,
                      WallNormalMemo* normal_memo, WallGapMemo* gap_memo) {
  const ColumnLayout& layout = *shared_layout;
  const Stopwatch total;
  ExtrusionResult res;
  ExtrusionReport& rep = res.report;
  rep.growth = resolve_growth_law(params.growth);
  rep.n_wall_points = static_cast<int>(wall.points.size());
  rep.n_wall_triangles = static_cast<int>(wall.triangles.size());

  // Setup: wall directions, column plan, and the checker once the fans passed the
  // precheck (a failing round needs no checker).
  Stopwatch phase;
  const WallPlanes planes(wall, layout, topo);
  const TriSurface& start = layout.front;
  // Recomputed directions: every front's normals start from the front below's,
  // the wall's included (this attempt's columns only: a layout's columns are its own).
  std::optional<FrontWarmStarts> warm;
  if (params.column_directions == ColumnDirections::kRecomputed) warm.emplace();
  FrontWarmStarts* const warm_starts = warm ? &*warm : nullptr;
  StepDirections dirs = wall_directions(wall, wall_topo, layout, topo, planes, params, normal_memo, warm_starts);
  ColumnPlan plan = plan_column_heights(
      wall, wall_topo, topo, rep.growth, params, dirs,
      wall_proximity_rays(wall.triangles, wall.points, **wall_tree, &start.triangles, &layout.wall_point, topo.plane,
                          &topo.on_plane),
      gap_memo);
  if (precheck) {
    if (layout.has_fans()) {
      fan_failures->precheck =
          precheck->failing_points(wall, layout, planes, dirs, plan, params, fan_failures->last_precheck_round);
      if (!fan_failures->precheck.empty()) return res;
    }
    precheck->release();  // this attempt marches: its records would only add to the peak
  }
  if (gap_memo) *gap_memo = WallGapMemo{};  // likewise
  if (normal_memo) normal_memo->drop_cheap();  // likewise, but for the costly fans
  FrontChecker checker(wall, shared_layout, topo, params, wall_tree->get());
  ColumnState columns = ColumnState::on_wall(start.points, topo.used, layout.wall_point);
  LayerAssembler assembler(wall, shared_layout, dirs);
  assembler.reserve_layers(rep.growth.layers);
  TriSurface front;
  front.triangles = start.triangles;
  std::vector<Vec3> next(start.points.size());
  RaySegments ray_tree;  // the proximity rays' segments, refitted from layer to layer
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
      dirs = update_step_directions(front, topo, active, params, dirs, &n_turned, warm_starts);
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
    limit_by_proximity(k, checker.front_rays(), topo, planes, dirs, params, &plan, &columns, &ray_tree);
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
    if (k == 0 && stop_at_failed_fans) {
      fan_failures->first_layer = failed_fan_points(layout, columns.layers, columns.reason);
      if (!fan_failures->first_layer.empty()) return res;
    }
  }
  // The marching state is no longer needed; freeing it here keeps it out of the peak
  // memory, which is reached while the output arrays are filled.
  checker.release();
  wall_tree->reset();
  ray_tree = RaySegments{};

  phase.restart();
  res.mesh = assembler.take_mesh();
  BLAYER_EXPENSIVE_ASSERT(every_cell_valid(res.mesh));
  res.envelope.points = columns.top;
  res.envelope.triangles = start.triangles;
  res.envelope_point_ids = columns.top_id;
  res.column_layers = columns.layers;
  res.stop_reason = columns.reason;
  res.column_wall_point = layout.wall_point;
  res.front_wall_face = layout.wall_face;
  rep.columns_per_layer = assembler.columns_per_layer();
  rep.fans.cells = assembler.fan_cells();
  rep.min_visibility = rep.columns_per_layer.empty() ? 0.0 : assembler.min_visibility();
  if (warm) {
    rep.n_warm_starts = warm->counts.warm;
    rep.n_warm_hits = warm->counts.hits;
  }
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
  phase.restart();
  assembler.attach_arrays(columns, &res.mesh);
  rep.t_assembly += phase.seconds();
  rep.t_total = total.seconds();
  return res;
}

}  // namespace

ExtrusionResult extrude_layers(const TriSurface& wall, const ExtrusionParams& params,
                               const std::function<void(int, int)>& progress) {
  const Stopwatch total;
  check_extrusion_params(params);
  check_wall(wall);
  // The topology's tables are built serially: the tree (for every attempt of the run)
  // is built beside them.
  WallTopology topology;
  std::unique_ptr<WallTree> wall_tree;
  tbb::parallel_invoke([&] { topology = build_wall_topology(wall, params.symmetry); },
                       [&] { wall_tree = std::make_unique<WallTree>(wall); });
  const WallTopology& wall_topo = topology;
  if (!(params.fan_angle_deg > 0.0)) {
    FanFailures none;
    const double t_before = total.seconds();
    ExtrusionResult res =
        march(wall, wall_topo, std::make_shared<const ColumnLayout>(single_column_layout(wall)), wall_topo, params,
              progress, false, &wall_tree, nullptr, &none, nullptr, nullptr);
    res.report.t_setup += t_before;
    res.report.t_total = total.seconds();
    return res;
  }
  // Fans; a fan point whose fan cannot grow its first layer falls back to one column,
  // and the extrusion is marched again (each attempt removes at least one fan point).
  const FanParams fp{params.fan_angle_deg, params.fan_max_sector_deg};
  std::vector<char> excluded = wall_topo.on_plane;
  int n_fallback = 0, precheck_rounds = 0;
  FanPrecheck fan_precheck;
  WallNormalMemo normal_memo;
  WallGapMemo gap_memo;
  for (int attempt = 0;; ++attempt) {
    // Shared with the march's checker, which reads it to the end.
    const auto shared_layout = std::make_shared<const ColumnLayout>(
        build_column_layout(wall, wall_topo.fans, fp, params.normal_method, excluded));
    const ColumnLayout& layout = *shared_layout;
    const WallTopology column_topo = build_column_topology(layout, params.symmetry);
    // Setup counts everything before the march that delivers: the wall tables, the
    // layouts and the attempts whose fan points fell back.
    const double t_before = total.seconds();
    FanFailures failures;
    failures.last_precheck_round = precheck_rounds + 1 >= kMaxPrecheckRounds;
    const bool last_attempt = attempt + 1 >= kMaxFanAttempts;
    ExtrusionResult res =
        march(wall, wall_topo, shared_layout, column_topo, params, progress, !last_attempt, &wall_tree,
              &fan_precheck, &failures, &normal_memo, &gap_memo);
    std::vector<int>& precheck = failures.precheck;
    if (!precheck.empty()) {
      // Each round rebuilds the layout and its directions: when most fans fail, or
      // after a few rounds, every remaining fan point falls back at once.
      if (2 * static_cast<int>(precheck.size()) > layout.n_fan_points || ++precheck_rounds >= kMaxPrecheckRounds) {
        precheck.clear();
        for (int c = 0; c < layout.n_columns(); ++c)
          if (layout.in_fan[c]) precheck.push_back(layout.wall_point[c]);
        std::sort(precheck.begin(), precheck.end());
        precheck.erase(std::unique(precheck.begin(), precheck.end()), precheck.end());
      }
      for (int w : precheck) excluded[w] = 1;
      n_fallback += static_cast<int>(precheck.size());
      --attempt;  // no marching happened
      continue;
    }
    // Not last: march stopped after layer 0 if fan points failed there. Last: it
    // marched to the end, and the fan points that failed are reported.
    const std::vector<int> failed =
        last_attempt ? failed_fan_points(layout, res.column_layers, res.stop_reason) : failures.first_layer;
    if (failed.empty() || last_attempt) {
      FanSummary& f = res.report.fans;
      f.points = layout.n_fan_points;
      f.columns = 0;
      for (char x : layout.in_fan) f.columns += x;
      f.ridge_edges = layout.n_ridge_edges;
      f.corners = layout.n_corners;
      f.ridge_ends = layout.n_ridge_ends;
      f.fallback_points = n_fallback;
      f.failed_points = static_cast<int>(failed.size());
      f.attempts = attempt + 1;
      res.report.t_setup += t_before;
      res.report.t_total = total.seconds();
      return res;
    }
    for (int w : failed) excluded[w] = 1;
    n_fallback += static_cast<int>(failed.size());
  }
}

}  // namespace blayer
