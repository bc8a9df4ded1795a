#include "blayer/extruder/step_directions.h"

#include <algorithm>

#include "parallel.h"

namespace blayer {

namespace {

std::vector<Vec3> unit_face_normals(const TriSurface& s) {
  std::vector<Vec3> fn(s.triangles.size());
  tbb::parallel_for(0, static_cast<int>(s.triangles.size()),
                    [&](int t) { fn[t] = normalized(triangle_area_vector(s, s.triangles[t])); });
  return fn;
}

// One Jacobi smoothing pass over the ok directions (see compute_step_directions).
void smoothing_pass(const WallTopology& topo, const std::vector<double>& raw_visibility, double min_visibility,
                    StepDirections* d) {
  const Csr& nbr = topo.vertex_neighbours;
  std::vector<Vec3> next = d->n;
  std::vector<double> next_vis = d->visibility;
  parallel_vertices(topo.n_points(), [&](int v) {
    if (!d->ok[v]) return;
    Vec3 avg = d->n[v];
    for (const int* u = nbr.begin(v); u != nbr.end(v); ++u)
      if (d->ok[*u]) avg += d->n[*u];
    avg = normalized(avg);
    if (!(norm2(avg) > 0.0)) return;
    for (double t : {1.0, 0.5, 0.25}) {
      const Vec3 cand = normalized((1.0 - t) * d->n[v] + t * avg);
      const double vis = visibility_of(*d, topo, v, cand);
      if (vis >= raw_visibility[v] && vis >= min_visibility) {
        next[v] = cand;
        next_vis[v] = vis;
        break;
      }
    }
  });
  d->n.swap(next);
  d->visibility.swap(next_vis);
}

}  // namespace

double visibility_of(const StepDirections& d, const WallTopology& topo, int v, const Vec3& n) {
  double m = 1.0;
  const Csr& vtri = topo.vertex_triangles;
  for (const int* t = vtri.begin(v); t != vtri.end(v); ++t) m = std::min(m, dot(n, d.face_normal[*t]));
  return m;
}

StepDirections compute_step_directions(const TriSurface& front, const WallTopology& topo,
                                       const std::vector<char>& active, const ExtrusionParams& p) {
  const int nv = static_cast<int>(front.points.size());
  const PointNormals pn = compute_point_normals(front, topo.fans, p.normal_method);
  StepDirections d;
  d.face_normal = unit_face_normals(front);
  d.n = pn.normal;
  d.visibility.assign(nv, 0.0);
  d.ok.assign(nv, 0);
  parallel_vertices(nv, [&](int v) {
    if (!active[v] || topo.vertex_triangles.size(v) == 0) return;
    if (pn.status[v] == NormalStatus::kNoVisibleDirection || !(norm2(d.n[v]) > 0.0) || !is_finite(d.n[v])) return;
    d.visibility[v] = visibility_of(d, topo, v, d.n[v]);
    d.ok[v] = d.visibility[v] >= p.min_visibility;
  });
  const std::vector<double> raw_visibility = d.visibility;
  for (int it = 0; it < p.normal_smoothing_iterations; ++it) smoothing_pass(topo, raw_visibility, p.min_visibility, &d);
  return d;
}

std::vector<char> turn_failing_columns(const std::vector<Triangle>& triangles, const WallTopology& topo,
                                       const std::vector<char>& bad, const std::vector<char>& bad_triangle,
                                       const std::vector<char>& grows, double min_visibility, StepDirections* d) {
  const int nv = topo.n_points();
  const Csr& vtri = topo.vertex_triangles;
  std::vector<char> turned(nv, 0);
  std::vector<Vec3> new_n = d->n;
  std::vector<double> new_vis = d->visibility;
  parallel_vertices(nv, [&](int v) {
    if (!bad[v]) return;
    Vec3 sum{0.0, 0.0, 0.0};
    for (const int* f = vtri.begin(v); f != vtri.end(v); ++f)
      if (bad_triangle[*f])
        for (int u : triangles[*f])
          if (grows[u]) sum += d->n[u];
    const Vec3 cand = normalized(sum);
    if (!(norm2(cand) > 0.0)) return;
    const double vis = visibility_of(*d, topo, v, cand);
    if (vis >= min_visibility && vis >= 0.5 * d->visibility[v] && dot(cand, d->n[v]) < 1.0) {
      new_n[v] = cand;
      new_vis[v] = vis;
      turned[v] = 1;
    }
  });
  d->n.swap(new_n);
  d->visibility.swap(new_vis);
  return turned;
}

}  // namespace blayer
