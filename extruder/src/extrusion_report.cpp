#include "blayer/extruder/extrusion_report.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <utility>

namespace blayer {

namespace {

void line(std::string* out, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void line(std::string* out, const char* fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  *out += buf;
  *out += '\n';
}

// Running min / mean / max.
struct RangeAccumulator {
  RangeStats s{HUGE_VAL, 0.0, -HUGE_VAL};
  int n = 0;
  void add(double x) {
    s.min = std::min(s.min, x);
    s.max = std::max(s.max, x);
    s.mean += x;
    ++n;
  }
  RangeStats result() const {
    if (n == 0) return RangeStats{};
    RangeStats r = s;
    r.mean /= n;
    return r;
  }
};

void count_cells(const VolumeMesh& mesh, ExtrusionReport* r) {
  for (CellType t : mesh.cell_types) {
    switch (t) {
      case CellType::kWedge: ++r->n_wedges; break;
      case CellType::kPyramid: ++r->n_pyramids; break;
      case CellType::kTet: ++r->n_tets; break;
      case CellType::kHex: ++r->n_hexes; break;
    }
  }
  r->n_points = static_cast<std::int64_t>(mesh.points.size());
}

// Heights above the wall (min over each column's wall planes), achieved thickness
// fractions and stops per reason, over the columns that stand on wall triangles.
void summarise_heights(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo,
                       const WallPlanes& planes, const ColumnPlan& plan, const ColumnState& columns,
                       ExtrusionReport* r) {
  const int nc = topo.n_points();
  std::vector<double> column_area(nc, 0.0);
  for (std::size_t t = 0; t < layout.front.triangles.size(); ++t) {
    if (layout.wall_face[t] < 0) continue;
    const double a = 0.5 * norm(triangle_area_vector(wall, wall.triangles[layout.wall_face[t]])) / 3.0;
    for (int v : layout.front.triangles[t]) column_area[v] += a;
  }
  double total_area = 0.0;
  int n_used = 0;
  RangeAccumulator fh, th, tf;
  for (int v = 0; v < nc; ++v) {
    if (!topo.used[v] || layout.faceless[v]) continue;
    ++n_used;
    total_area += column_area[v];
    const double total = columns.layers[v] > 0 ? planes.height_above(v, columns.top[v]) : 0.0;
    th.add(total);
    tf.add(total / plan.target_total[v]);
    if (columns.layers[v] > 0) fh.add(planes.height_above(v, columns.first[v]));
    if (columns.layers[v] == r->growth.layers) ++r->n_complete_columns;
    else ++r->stopped_columns[static_cast<int>(columns.reason[v])];
    if (plan.limit[v] != StopReason::kNone) ++r->limited_columns[static_cast<int>(plan.limit[v])];
    if (total < kThicknessReachedFraction * plan.target_total[v]) {
      const int why = static_cast<int>(plan.limit[v] != StopReason::kNone ? plan.limit[v] : columns.reason[v]);
      r->thin.columns[why] += 1.0;
      r->thin.area[why] += column_area[v];
    }
  }
  for (int i = 0; i < kStopReasonCount; ++i) {
    r->thin.columns[i] = n_used > 0 ? r->thin.columns[i] / n_used : 0.0;
    r->thin.area[i] = total_area > 0.0 ? r->thin.area[i] / total_area : 0.0;
    r->thin.total_columns += r->thin.columns[i];
    r->thin.total_area += r->thin.area[i];
  }
  r->first_height = fh.result();
  r->total_thickness = th.result();
  r->thickness_fraction = tf.result();
}

void summarise_coverage(const TriSurface& wall, const ColumnLayout& layout, const ColumnState& columns,
                        ExtrusionReport* r) {
  const int n = r->growth.layers;
  double area = 0.0, area_full = 0.0;
  int n_full = 0;
  for (std::size_t f = 0; f < layout.front.triangles.size(); ++f) {
    if (layout.wall_face[f] < 0) continue;
    const Triangle& t = layout.front.triangles[f];
    const double a = 0.5 * norm(triangle_area_vector(wall, wall.triangles[layout.wall_face[f]]));
    area += a;
    if (columns.layers[t[0]] == n && columns.layers[t[1]] == n && columns.layers[t[2]] == n) {
      ++n_full;
      area_full += a;
    }
  }
  const int nf = static_cast<int>(wall.triangles.size());
  r->coverage = nf > 0 ? double(n_full) / nf : 0.0;
  r->area_coverage = area > 0.0 ? area_full / area : 0.0;
}

// One decimal from 1 % up, two significant digits below, so small shares do not read 0.0 %.
std::string percent(double x) {
  char buf[32];
  if (100.0 * x >= 1.0 || x == 0.0)
    std::snprintf(buf, sizeof buf, "%.1f %%", 100.0 * x);
  else
    std::snprintf(buf, sizeof buf, "%.2g %%", 100.0 * x);
  return buf;
}

}  // namespace

void summarise_extrusion(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo,
                         const WallPlanes& planes, const ColumnPlan& plan, const ColumnState& columns,
                         const VolumeMesh& mesh, ExtrusionReport* r) {
  count_cells(mesh, r);
  summarise_heights(wall, layout, topo, planes, plan, columns, r);
  summarise_coverage(wall, layout, columns, r);
  if (!r->growth.relative) {
    r->fidelity = measure_layer_fidelity(mesh, wall,
                                         {r->growth.first_height, r->growth.total_thickness, r->growth.layers});
    r->fidelity.columns.clear();
    r->has_fidelity = true;
  }
}

std::string thickness_warning(const ExtrusionReport& r) {
  if (r.complete()) return "";
  std::string s = percent(r.thin.total_area) + " of the wall (" + percent(r.thin.total_columns) +
                  " of the columns) got less than 90 % of the thickness:";
  std::vector<std::pair<double, int>> order;
  for (int i = 0; i < kStopReasonCount; ++i)
    if (r.thin.area[i] > 0.0 || r.thin.columns[i] > 0.0) order.push_back({r.thin.area[i], i});
  std::sort(order.rbegin(), order.rend());
  for (std::size_t j = 0; j < order.size(); ++j) {
    const int i = order[j].second;
    s += (j ? ", " : " ") + percent(r.thin.area[i]) + " " +
         (i == 0 ? std::string("other") : std::string(stop_reason_name(static_cast<StopReason>(i))));
  }
  return s;
}

std::string format_extrusion_report(const ExtrusionReport& r) {
  std::string s;
  line(&s, "growth law          %s", describe_growth_law(r.growth).c_str());
  line(&s, "wall                %d points, %d triangles", r.n_wall_points, r.n_wall_triangles);
  line(&s, "first height        min %.6g  mean %.6g  max %.6g", r.first_height.min, r.first_height.mean,
       r.first_height.max);
  line(&s, "total thickness     min %.6g  mean %.6g  max %.6g", r.total_thickness.min, r.total_thickness.mean,
       r.total_thickness.max);
  line(&s, "thickness / target  min %.4f  mean %.4f  max %.4f", r.thickness_fraction.min,
       r.thickness_fraction.mean, r.thickness_fraction.max);
  line(&s, "coverage            %.4f of triangles, %.4f of area carry all %d layers", r.coverage, r.area_coverage,
       r.growth.layers);
  std::string stopped, limited;
  for (int i = 1; i < kStopReasonCount; ++i) {
    const char* name = stop_reason_name(static_cast<StopReason>(i));
    if (r.stopped_columns[i]) stopped += std::string(" ") + name + " " + std::to_string(r.stopped_columns[i]);
    if (r.limited_columns[i]) limited += std::string(" ") + name + " " + std::to_string(r.limited_columns[i]);
  }
  line(&s, "columns             %d complete; stopped:%s", r.n_complete_columns, stopped.empty() ? " none" : stopped.c_str());
  line(&s, "limited columns    %s", limited.empty() ? " none" : limited.c_str());
  if (r.has_fidelity) {
    const LayerFidelity& f = r.fidelity;
    line(&s, "first height / h1   p1 %.4f  p50 %.4f  p99 %.4f above the wall planes; within 1 %%: %s of the columns",
         f.first_over_h1_planes.p1, f.first_over_h1_planes.p50, f.first_over_h1_planes.p99,
         percent(f.first_within_1pct_planes).c_str());
    line(&s, "                    p1 %.4f  p50 %.4f  p99 %.4f as distance to the wall; within 1 %%: %s",
         f.first_over_h1_distance.p1, f.first_over_h1_distance.p50, f.first_over_h1_distance.p99,
         percent(f.first_within_1pct_distance).c_str());
    line(&s, "thickness / T       p5 %.4f  p50 %.4f above the planes, p5 %.4f  p50 %.4f as distance; >= 0.9 T: %s / %s",
         f.top_over_T_planes.p5, f.top_over_T_planes.p50, f.top_over_T_distance.p5, f.top_over_T_distance.p50,
         percent(f.top_ge_90pct_planes).c_str(), percent(f.top_ge_90pct_distance).c_str());
  }
  if (r.fans.attempts > 0)
    line(&s, "fans                %d points on %d ridge edges (%d ridge ends, %d corners), %d columns, %lld cells; "
         "%d points fell back to one column",
         r.fans.points, r.fans.ridge_edges, r.fans.ridge_ends, r.fans.corners, r.fans.columns,
         static_cast<long long>(r.fans.cells), r.fans.fallback_points);
  if (r.n_symmetry_columns > 0)
    line(&s, "symmetry plane      %d columns on it, their points at most %.3g from it", r.n_symmetry_columns,
         r.max_symmetry_distance);
  std::string per_layer;
  for (int n : r.columns_per_layer) per_layer += " " + std::to_string(n);
  line(&s, "columns per layer  %s", per_layer.c_str());
  line(&s, "cells               %lld wedges, %lld pyramids, %lld tets%s; %lld points",
       static_cast<long long>(r.n_wedges), static_cast<long long>(r.n_pyramids), static_cast<long long>(r.n_tets),
       r.n_hexes > 0 ? (", " + std::to_string(r.n_hexes) + " hexes").c_str() : "",
       static_cast<long long>(r.n_points));
  if (r.n_warm_starts > 0)
    line(&s, "warm starts         %ld of the fronts' normals started from the front below; certificate held for "
         "%ld (%.1f %%)",
         r.n_warm_starts, r.n_warm_hits,
         100.0 * static_cast<double>(r.n_warm_hits) / static_cast<double>(r.n_warm_starts));
  line(&s, "min visibility      %.4f", r.min_visibility);
  line(&s, "time [s]            setup %.3f  normals %.3f  proximity %.3f  checks %.3f  assembly %.3f  report %.3f  "
       "total %.3f",
       r.t_setup, r.t_normals, r.t_proximity, r.t_checks, r.t_assembly, r.t_report, r.t_total);
  return s;
}

}  // namespace blayer

namespace blayer {

namespace {

nlohmann::json range_json(const RangeStats& r) { return {{"min", r.min}, {"mean", r.mean}, {"max", r.max}}; }

nlohmann::json by_reason(const std::array<double, kStopReasonCount>& a) {
  nlohmann::json j = nlohmann::json::object();
  for (int i = 0; i < kStopReasonCount; ++i)
    if (a[i] > 0.0) j[i == 0 ? "other" : stop_reason_name(static_cast<StopReason>(i))] = a[i];
  return j;
}

nlohmann::json counts_by_reason(const std::array<int, kStopReasonCount>& a) {
  nlohmann::json j = nlohmann::json::object();
  for (int i = 1; i < kStopReasonCount; ++i) j[stop_reason_name(static_cast<StopReason>(i))] = a[i];
  return j;
}

}  // namespace

nlohmann::json extrusion_report_to_json(const ExtrusionReport& r) {
  nlohmann::json j;
  j["growth_law"] = {{"layers", r.growth.layers},
                     {"first_height", r.growth.first_height},
                     {"last_height", r.growth.last_height},
                     {"total_thickness", r.growth.total_thickness},
                     {"growth_ratio", r.growth.growth_ratio},
                     {"relative", r.growth.relative}};
  j["wall"] = {{"points", r.n_wall_points}, {"triangles", r.n_wall_triangles}};
  j["achieved"] = {{"first_height", range_json(r.first_height)},
                   {"total_thickness", range_json(r.total_thickness)},
                   {"thickness_fraction", range_json(r.thickness_fraction)}};
  if (r.has_fidelity) j["fidelity"] = layer_fidelity_to_json(r.fidelity);
  j["coverage"] = r.coverage;
  j["area_coverage"] = r.area_coverage;
  j["symmetry"] = {{"columns", r.n_symmetry_columns}, {"max_distance", r.max_symmetry_distance}};
  j["columns"] = {{"complete", r.n_complete_columns},
                  {"stopped", counts_by_reason(r.stopped_columns)},
                  {"limited", counts_by_reason(r.limited_columns)},
                  {"turned_directions", r.n_turned_directions},
                  {"warm_starts", r.n_warm_starts},
                  {"warm_start_hits", r.n_warm_hits},
                  {"per_layer", r.columns_per_layer}};
  j["verdict"] = {{"outcome", r.complete() ? "complete" : "limited"},
                  {"thin_columns", r.thin.total_columns},
                  {"thin_area", r.thin.total_area},
                  {"thin_columns_by_reason", by_reason(r.thin.columns)},
                  {"thin_area_by_reason", by_reason(r.thin.area)}};
  j["cells"] = {{"wedges", r.n_wedges}, {"pyramids", r.n_pyramids}, {"tets", r.n_tets},
                {"hexes", r.n_hexes},   {"points", r.n_points}};
  j["fans"] = {{"points", r.fans.points},
               {"columns", r.fans.columns},
               {"ridge_edges", r.fans.ridge_edges},
               {"corners", r.fans.corners},
               {"ridge_ends", r.fans.ridge_ends},
               {"fallback_points", r.fans.fallback_points},
               {"failed_points", r.fans.failed_points},
               {"attempts", r.fans.attempts},
               {"cells", r.fans.cells}};
  j["min_visibility"] = r.min_visibility;
  j["time_seconds"] = {{"setup", r.t_setup},   {"normals", r.t_normals},   {"proximity", r.t_proximity},
                       {"checks", r.t_checks}, {"assembly", r.t_assembly}, {"report", r.t_report},
                       {"extrusion", r.t_total}};
  return j;
}

}  // namespace blayer
