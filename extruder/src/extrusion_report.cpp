#include <cstdarg>
#include <cstdio>
#include <string>

#include "blayer/extruder/extrude_layers.h"

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

}  // namespace

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
  line(&s, "columns             %d complete; stopped: collision %d, quality %d, proximity %d, visibility %d",
       r.n_complete_columns, r.stopped_columns[1], r.stopped_columns[2], r.stopped_columns[3],
       r.stopped_columns[4]);
  line(&s, "limited columns     %d by max_height_to_edge_ratio, %d by the wall gap", r.n_height_capped_columns,
       r.n_gap_limited_columns);
  std::string per_layer;
  for (int n : r.columns_per_layer) per_layer += " " + std::to_string(n);
  line(&s, "columns per layer  %s", per_layer.c_str());
  line(&s, "cells               %lld wedges, %lld pyramids, %lld tets; %lld points",
       static_cast<long long>(r.n_wedges), static_cast<long long>(r.n_pyramids), static_cast<long long>(r.n_tets),
       static_cast<long long>(r.n_points));
  line(&s, "validity            %lld invalid cells (exact corner-tet check)", static_cast<long long>(r.n_invalid_cells));
  line(&s, "min scaled jacobian %.4f", r.min_scaled_jacobian);
  line(&s, "min visibility      %.4f", r.min_visibility);
  line(&s, "time [s]            setup %.3f  normals %.3f  proximity %.3f  checks %.3f  assembly %.3f  report %.3f  "
       "total %.3f",
       r.t_setup, r.t_normals, r.t_proximity, r.t_checks, r.t_assembly, r.t_report, r.t_total);
  return s;
}

}  // namespace blayer
