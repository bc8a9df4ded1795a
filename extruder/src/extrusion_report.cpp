#include "blayer/extruder/extrusion_report.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

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
      case CellType::kHex: break;
    }
  }
  r->n_points = static_cast<std::int64_t>(mesh.points.size());
}

// Heights above the wall (min over incident wall face planes), achieved thickness
// fractions and stops per reason.
void summarise_heights(const TriSurface& wall, const WallTopology& topo, const ColumnHeights& heights,
                       const ColumnState& columns, const VolumeMesh& mesh, const std::vector<int>& point_column,
                       ExtrusionReport* r) {
  const int nv = topo.n_points(), nf = static_cast<int>(wall.triangles.size());
  const std::int64_t np = static_cast<std::int64_t>(mesh.points.size());
  std::vector<Vec3> wall_fn(nf);
  tbb::parallel_for(0, nf, [&](int f) { wall_fn[f] = normalized(triangle_area_vector(wall, wall.triangles[f])); });
  std::vector<std::int64_t> first_id(nv, -1);
  for (std::int64_t p = nv; p < np; ++p)
    if (first_id[point_column[p]] < 0) first_id[point_column[p]] = p;
  const Csr& vtri = topo.vertex_triangles;
  auto height_above = [&](int v, const Vec3& q) {
    double m = HUGE_VAL;
    for (const int* f = vtri.begin(v); f != vtri.end(v); ++f) m = std::min(m, dot(q - wall.points[v], wall_fn[*f]));
    return m;
  };
  RangeAccumulator fh, th, tf;
  for (int v = 0; v < nv; ++v) {
    if (!topo.used[v]) continue;
    const double total = columns.layers[v] > 0 ? height_above(v, columns.top[v]) : 0.0;
    th.add(total);
    tf.add(total / (heights.base[v] * r->growth.total_thickness));
    if (columns.layers[v] > 0) fh.add(height_above(v, mesh.points[first_id[v]]));
    if (columns.layers[v] == r->growth.layers) ++r->n_complete_columns;
    else ++r->stopped_columns[static_cast<int>(columns.reason[v])];
  }
  r->first_height = fh.result();
  r->total_thickness = th.result();
  r->thickness_fraction = tf.result();
}

void summarise_coverage(const TriSurface& wall, const ColumnState& columns, ExtrusionReport* r) {
  const int n = r->growth.layers;
  double area = 0.0, area_full = 0.0;
  int n_full = 0;
  for (const Triangle& t : wall.triangles) {
    const double a = 0.5 * norm(triangle_area_vector(wall, t));
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

}  // namespace

void summarise_extrusion(const TriSurface& wall, const WallTopology& topo, const ColumnHeights& heights,
                         const ColumnState& columns, const VolumeMesh& mesh, const std::vector<int>& point_column,
                         ExtrusionReport* r) {
  count_cells(mesh, r);
  summarise_heights(wall, topo, heights, columns, mesh, point_column, r);
  summarise_coverage(wall, columns, r);
  for (int v = 0; v < topo.n_points(); ++v) {
    r->n_height_capped_columns += heights.capped[v];
    r->n_gap_limited_columns += heights.gap_limited[v];
  }
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
  line(&s, "min visibility      %.4f", r.min_visibility);
  line(&s, "time [s]            setup %.3f  normals %.3f  proximity %.3f  checks %.3f  assembly %.3f  report %.3f  "
       "total %.3f",
       r.t_setup, r.t_normals, r.t_proximity, r.t_checks, r.t_assembly, r.t_report, r.t_total);
  return s;
}

}  // namespace blayer
