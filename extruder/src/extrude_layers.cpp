#include "blayer/extruder/extrude_layers.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "blayer/core/errors.h"
#include "blayer/core/vertex_fans.h"
#include "blayer/extruder/filtered_orient3d.h"
#include "blayer/extruder/layer_cells.h"
#include "blayer/quality/cell_metrics.h"
#include "blayer/extruder/triangle_bvh.h"
#include "blayer/extruder/triangle_intersections.h"
#include "blayer/quality/cell_validity.h"

namespace blayer {

const char* stop_reason_name(StopReason r) {
  switch (r) {
    case StopReason::kNone: return "none";
    case StopReason::kCollision: return "collision";
    case StopReason::kQuality: return "quality";
    case StopReason::kProximity: return "proximity";
    case StopReason::kVisibility: return "visibility";
  }
  return "unknown";
}

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Compressed adjacency lists: items of v are items[start[v] .. start[v+1]).
struct Csr {
  std::vector<int> start;
  std::vector<int> items;
  const int* begin(int v) const { return items.data() + start[v]; }
  const int* end(int v) const { return items.data() + start[v + 1]; }
};

Csr vertex_triangles(const TriSurface& s) {
  const int nv = static_cast<int>(s.points.size());
  Csr c;
  c.start.assign(nv + 1, 0);
  for (const Triangle& t : s.triangles)
    for (int v : t) ++c.start[v + 1];
  for (int v = 0; v < nv; ++v) c.start[v + 1] += c.start[v];
  c.items.resize(c.start[nv]);
  std::vector<int> fill(c.start.begin(), c.start.end() - 1);
  for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f)
    for (int v : s.triangles[f]) c.items[fill[v]++] = f;
  return c;
}

Csr vertex_neighbours(const TriSurface& s, const Csr& vtri) {
  const int nv = static_cast<int>(s.points.size());
  std::vector<std::vector<int>> nb(nv);
  tbb::parallel_for(0, nv, [&](int v) {
    for (const int* f = vtri.begin(v); f != vtri.end(v); ++f)
      for (int u : s.triangles[*f])
        if (u != v) nb[v].push_back(u);
    std::sort(nb[v].begin(), nb[v].end());
    nb[v].erase(std::unique(nb[v].begin(), nb[v].end()), nb[v].end());
  });
  Csr c;
  c.start.assign(nv + 1, 0);
  for (int v = 0; v < nv; ++v) c.start[v + 1] = c.start[v] + static_cast<int>(nb[v].size());
  c.items.reserve(c.start[nv]);
  for (int v = 0; v < nv; ++v) c.items.insert(c.items.end(), nb[v].begin(), nb[v].end());
  return c;
}

template <class F>
void parallel_vertices(int n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& r) {
    for (int v = r.begin(); v != r.end(); ++v) f(v);
  });
}

void check_params(const ExtrusionParams& p) {
  auto fail = [](const std::string& m) { throw InputError("extrusion parameters: " + m); };
  if (p.normal_smoothing_iterations < 0) fail("normal_smoothing_iterations must be >= 0");
  if (p.height_smoothing_rings < 0) fail("height_smoothing_rings must be >= 0");
  if (p.direction_repair_passes < 0) fail("direction_repair_passes must be >= 0");
  if (!(p.proximity_safety > 0.0 && p.proximity_safety <= 0.5))
    fail("proximity_safety must be in (0, 0.5] (two fronts growing towards each other meet in the middle)");
  if (!(p.max_height_to_edge_ratio >= 0.0) || !std::isfinite(p.max_height_to_edge_ratio))
    fail("max_height_to_edge_ratio must be >= 0 (0 disables the cap)");
  if (!(p.min_visibility > 0.0 && p.min_visibility < 1.0)) fail("min_visibility must be in (0, 1)");
  if (!(p.max_step_stretch >= 1.0) || !std::isfinite(p.max_step_stretch)) fail("max_step_stretch must be >= 1");
  if (!(p.min_layer_fraction > 0.0 && p.min_layer_fraction <= 1.0)) fail("min_layer_fraction must be in (0, 1]");
}

// Lowers f so that it rises by at most 1/(rings+1) per ring away from a low spot: after
// `rings` Jacobi passes f[v] <= f[u] + d(u,v)/(rings+1) for every u within `rings` rings,
// so a limited column ramps back to full height without a step. Only vertices with
// mask set take part. Never raises a value. The reason of the value that lowered a
// vertex travels with it.
void smooth_downward(const Csr& nbr, const std::vector<char>& mask, int rings, std::vector<double>* f,
                     std::vector<StopReason>* reason) {
  if (rings <= 0) return;
  const double slope = 1.0 / (rings + 1);
  const int n = static_cast<int>(f->size());
  std::vector<double> g(*f);
  std::vector<StopReason> rg(*reason);
  for (int r = 0; r < rings; ++r) {
    parallel_vertices(n, [&](int v) {
      if (!mask[v]) return;
      double m = (*f)[v];
      StopReason why = (*reason)[v];
      for (const int* u = nbr.begin(v); u != nbr.end(v); ++u)
        if (mask[*u] && (*f)[*u] + slope < m) {
          m = (*f)[*u] + slope;
          why = (*reason)[*u];
        }
      g[v] = m;
      rg[v] = why;
    });
    f->swap(g);
    reason->swap(rg);
    g = *f;
    rg = *reason;
  }
}

// Same verdict as cell_validity(type, corners) == Validity::kValid (every validity tet
// strictly positive), with the inlined filtered predicate.
bool cell_is_valid(CellType type, const Vec3* corners) {
  std::size_t n = 0;
  const std::array<int, 4>* tets = validity_tets(type, &n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<int, 4>& t = tets[i];
    if (detail::orient3d_filtered(corners[t[0]], corners[t[1]], corners[t[2]], corners[t[3]]) <= 0) return false;
  }
  return true;
}

// Step directions on a front: point normals, optionally smoothed without losing
// visibility, and their visibility against the incident front faces.
struct Directions {
  std::vector<Vec3> face_normal;  // unit normals of the front's triangles
  std::vector<Vec3> n;
  std::vector<double> visibility;
  std::vector<char> ok;  // a usable (visible, non-degenerate) direction exists
};

Directions compute_directions(const TriSurface& front, const VertexFans& fans, const Csr& vtri, const Csr& nbr,
                              const std::vector<char>& active, const ExtrusionParams& p) {
  const int nv = static_cast<int>(front.points.size());
  const int nf = static_cast<int>(front.triangles.size());
  std::vector<Vec3> fn(nf);
  tbb::parallel_for(0, nf, [&](int t) { fn[t] = normalized(triangle_area_vector(front, front.triangles[t])); });
  auto visibility = [&](int v, const Vec3& n) {
    double m = 1.0;
    for (const int* t = vtri.begin(v); t != vtri.end(v); ++t) m = std::min(m, dot(n, fn[*t]));
    return m;
  };

  const PointNormals pn = compute_point_normals(front, fans, p.normal_method);
  Directions d;
  d.face_normal = fn;
  d.n = pn.normal;
  d.visibility.assign(nv, 0.0);
  d.ok.assign(nv, 0);
  parallel_vertices(nv, [&](int v) {
    if (!active[v] || vtri.begin(v) == vtri.end(v)) return;
    if (pn.status[v] == NormalStatus::kNoVisibleDirection || !(norm2(d.n[v]) > 0.0) || !is_finite(d.n[v])) return;
    d.visibility[v] = visibility(v, d.n[v]);
    d.ok[v] = d.visibility[v] >= p.min_visibility;
  });

  // Smoothing: blend towards the neighbour average, fully, half or a quarter, and keep
  // the first blend whose visibility is not below the unsmoothed direction's.
  const std::vector<double> raw_visibility = d.visibility;
  for (int it = 0; it < p.normal_smoothing_iterations; ++it) {
    std::vector<Vec3> next = d.n;
    std::vector<double> next_vis = d.visibility;
    parallel_vertices(nv, [&](int v) {
      if (!d.ok[v]) return;
      Vec3 avg = d.n[v];
      for (const int* u = nbr.begin(v); u != nbr.end(v); ++u)
        if (d.ok[*u]) avg += d.n[*u];
      avg = normalized(avg);
      if (!(norm2(avg) > 0.0)) return;
      for (double t : {1.0, 0.5, 0.25}) {
        const Vec3 cand = normalized((1.0 - t) * d.n[v] + t * avg);
        const double vis = visibility(v, cand);
        if (vis >= raw_visibility[v] && vis >= p.min_visibility) {
          next[v] = cand;
          next_vis[v] = vis;
          break;
        }
      }
    });
    d.n.swap(next);
    d.visibility.swap(next_vis);
  }
  return d;
}

double visibility_of(const Directions& d, const Csr& vtri, int v, const Vec3& n) {
  double m = 1.0;
  for (const int* t = vtri.begin(v); t != vtri.end(v); ++t) m = std::min(m, dot(n, d.face_normal[*t]));
  return m;
}

// Distance along the unit direction dir from o to the triangle (a,b,c), or +inf when
// the ray misses it within t_max. Floating point (Moller-Trumbore): the proximity
// limiter is a heuristic; exact predicates decide validity elsewhere.
double ray_triangle(const Vec3& o, const Vec3& dir, const Vec3& a, const Vec3& b, const Vec3& c, double t_max) {
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 pv = cross(dir, e2);
  const double det = dot(e1, pv);
  if (det == 0.0) return HUGE_VAL;
  const double inv = 1.0 / det;
  const Vec3 tv = o - a;
  const double u = dot(tv, pv) * inv;
  if (u < 0.0 || u > 1.0) return HUGE_VAL;
  const Vec3 qv = cross(tv, e1);
  const double w = dot(dir, qv) * inv;
  if (w < 0.0 || u + w > 1.0) return HUGE_VAL;
  const double t = dot(e2, qv) * inv;
  return (t >= 0.0 && t <= t_max) ? t : HUGE_VAL;
}

// Unit normals of the triangles of a surface with the wall's connectivity.
void unit_normals(const std::vector<Triangle>& tris, const std::vector<Vec3>& P, std::vector<Vec3>* out) {
  out->resize(tris.size());
  tbb::parallel_for(0, static_cast<int>(tris.size()), [&](int i) {
    const Triangle& t = tris[i];
    (*out)[i] = normalized(cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]]));
  });
}

// The wall and optionally the current front (the wall's triangles on the column tops),
// each with a tree over its triangles' boxes, for the proximity rays.
struct ProximitySet {
  const std::vector<Triangle>* tris = nullptr;
  const std::vector<Vec3>* wall_points = nullptr;
  const TriangleBvh* wall_bvh = nullptr;
  const std::vector<Vec3>* wall_normal = nullptr;
  const std::vector<Vec3>* front_points = nullptr;  // null: wall only
  const TriangleBvh* front_bvh = nullptr;
  const std::vector<Vec3>* front_normal = nullptr;

  // Distance to the first front-facing triangle not incident to column v along dir,
  // within t_max; +inf if none.
  double first_hit(int v, const Vec3& o, const Vec3& dir, double t_max) const {
    double best = HUGE_VAL;
    auto search = [&](const TriangleBvh& bvh, const std::vector<Vec3>& P, const std::vector<Vec3>& normal) {
      bvh.for_each_on_segment(o, dir, std::min(t_max, best), [&](int i, double* tm) {
        const Triangle& t = (*tris)[i];
        if (t[0] == v || t[1] == v || t[2] == v) return;
        if (!(dot(dir, normal[i]) < 0.0)) return;
        const double d = ray_triangle(o, dir, P[t[0]], P[t[1]], P[t[2]], *tm);
        if (d < best) {
          best = d;
          *tm = d;
        }
      });
    };
    search(*wall_bvh, *wall_points, *wall_normal);
    if (front_points) search(*front_bvh, *front_points, *front_normal);
    return best;
  }
};

}  // namespace

ExtrusionResult extrude_layers(const TriSurface& wall, const ExtrusionParams& params,
                               const std::function<void(int, int)>& progress) {
  const auto t_start = Clock::now();
  check_params(params);
  ExtrusionResult res;
  ExtrusionReport& rep = res.report;
  rep.growth = resolve_growth_law(params.growth);
  const int n_layers = rep.growth.layers;
  const int nv = static_cast<int>(wall.points.size());
  const int nf = static_cast<int>(wall.triangles.size());
  rep.n_wall_points = nv;
  rep.n_wall_triangles = nf;
  for (const Triangle& t : wall.triangles)
    for (int v : t)
      if (v < 0 || v >= nv) throw InputError("extrude_layers: a wall triangle refers to a missing point");

  // ---- setup: topology, edge scales, per-column height scale ----
  auto t0 = Clock::now();
  const VertexFans fans = build_vertex_fans(wall);
  const Csr vtri = vertex_triangles(wall);
  const Csr nbr = vertex_neighbours(wall, vtri);
  std::vector<char> used(nv, 0);
  for (int v = 0; v < nv; ++v) used[v] = vtri.begin(v) != vtri.end(v);

  // Mean and shortest length of the wall edges at v. Relative heights use the mean (the
  // vertex's size); the height cap uses the shortest, because on stretched triangles the
  // short side is the distance over which neighbouring columns must not overtake each
  // other sideways.
  std::vector<double> edge(nv, 0.0), short_edge(nv, 0.0);
  parallel_vertices(nv, [&](int v) {
    const int k = static_cast<int>(nbr.end(v) - nbr.begin(v));
    if (k == 0) return;
    double s = 0.0, m = HUGE_VAL;
    for (const int* u = nbr.begin(v); u != nbr.end(v); ++u) {
      const double l = norm(wall.points[*u] - wall.points[v]);
      s += l;
      m = std::min(m, l);
    }
    edge[v] = s / k;
    short_edge[v] = m;
  });
  // base[v] * heights[k] is the target height of layer k in column v.
  std::vector<double> base(nv, 1.0);
  if (rep.growth.relative) base = edge;
  std::vector<double> scale(nv, 1.0);
  std::vector<StopReason> scale_reason(nv, StopReason::kNone);
  std::vector<char> capped(nv, 0), gap_limited(nv, 0);
  if (params.max_height_to_edge_ratio > 0.0) {
    parallel_vertices(nv, [&](int v) {
      double length = short_edge[v];
      if (params.height_cap_length == HeightCapLength::kMeanEdge) {
        length = edge[v];
      } else if (params.height_cap_length == HeightCapLength::kFaceSize) {
        double area = 0.0;
        for (const int* f = vtri.begin(v); f != vtri.end(v); ++f)
          area += 0.5 * norm(triangle_area_vector(wall, wall.triangles[*f]));
        const int n = static_cast<int>(vtri.end(v) - vtri.begin(v));
        length = n > 0 ? std::sqrt(2.0 * area / n) : 0.0;
      }
      const double target = base[v] * rep.growth.total_thickness;
      const double cap = params.max_height_to_edge_ratio * length;
      if (used[v] && target > cap) {
        scale[v] = cap / target;
        capped[v] = 1;
      }
    });
  }

  std::vector<char> active(nv, 0);
  for (int v = 0; v < nv; ++v) active[v] = used[v];
  Directions dirs = compute_directions(wall, fans, vtri, nbr, active, params);

  // Wall-gap cap: the whole column (about total / V long) may span at most
  // proximity_safety of the distance to the wall part it faces.
  // One tree layout, the wall's, serves every surface of the run (TriangleBvh::refit).
  TriangleBvh wall_bvh;
  std::vector<Vec3> wall_normal;
  {
    std::vector<Box> wall_boxes(nf);
    tbb::parallel_for(0, nf, [&](int f) {
      const Triangle& t = wall.triangles[f];
      wall_boxes[f] = Box::of_triangle(wall.points[t[0]], wall.points[t[1]], wall.points[t[2]]);
    });
    wall_bvh.build(wall_boxes);
    unit_normals(wall.triangles, wall.points, &wall_normal);
  }
  {
    ProximitySet ps;
    ps.tris = &wall.triangles;
    ps.wall_points = &wall.points;
    ps.wall_bvh = &wall_bvh;
    ps.wall_normal = &wall_normal;
    parallel_vertices(nv, [&](int v) {
      if (!dirs.ok[v]) return;
      const double extent = base[v] * scale[v] * rep.growth.total_thickness /
                            std::max(dirs.visibility[v], 1.0 / params.max_step_stretch);
      const double d = ps.first_hit(v, wall.points[v], dirs.n[v], extent / params.proximity_safety);
      if (d < HUGE_VAL && extent > params.proximity_safety * d) {
        scale[v] *= params.proximity_safety * d / extent;
        gap_limited[v] = 1;
      }
    });
    smooth_downward(nbr, used, params.height_smoothing_rings, &scale, &scale_reason);
  }
  for (int v = 0; v < nv; ++v) {
    rep.n_height_capped_columns += capped[v];
    rep.n_gap_limited_columns += gap_limited[v];
  }
  rep.t_setup = seconds_since(t0);

  // ---- column state ----
  VolumeMesh& mesh = res.mesh;
  mesh.points = wall.points;
  std::vector<Vec3> point_normal(nv, Vec3{0.0, 0.0, 0.0});
  std::vector<int> point_column(nv);
  for (int v = 0; v < nv; ++v) {
    point_column[v] = v;
    if (dirs.ok[v]) point_normal[v] = dirs.n[v];
  }
  std::vector<std::int64_t> top_id(nv);
  for (int v = 0; v < nv; ++v) top_id[v] = v;
  std::vector<Vec3> top = wall.points;
  std::vector<int> layers(nv, 0);
  std::vector<char> stopped(nv, 0);
  std::vector<StopReason> reason(nv, StopReason::kNone);
  std::vector<double> path(nv, 0.0);
  std::vector<int> cell_layer;
  for (int v = 0; v < nv; ++v) stopped[v] = !used[v];
  auto stop = [&](int v, StopReason why) {
    if (stopped[v]) return;
    stopped[v] = 1;
    reason[v] = why;
  };
  rep.min_visibility = 1.0;

  TriSurface front;
  front.triangles = wall.triangles;
  std::vector<double> step(nv), phi(nv), layer_h(nv);
  std::vector<StopReason> phi_reason(nv);
  std::vector<char> grows(nv), bad(nv);
  std::vector<Vec3> next(nv);
  std::vector<Vec3> prev_next(nv);
  std::vector<char> prev_grows(nv), moved(nv);
  std::vector<char> bad_tri(nf), bad_cell(nf), collided(nf), tri_moved(nf), tri_grows(nf), query(nf);

  // Exact-check state. Wall triangles and their tree are fixed; the current front's are
  // built once per layer, the new front's once per attempt.
  // The current front's tree serves the proximity rays too.
  std::vector<Vec3> soup_points;
  std::vector<IndexedTriangle> wall_tris(nf), cur_tris(nf), new_tris(nf);
  std::vector<Box> cur_boxes(nf), new_boxes(nf);
  std::vector<Vec3> cur_normal;
  std::vector<char> cur_is_wall(nf);
  TriangleBvh cur_bvh = wall_bvh, new_bvh = wall_bvh;
  tbb::enumerable_thread_specific<std::vector<int>> partner_hits;
  auto tri_box = [&](const IndexedTriangle& t) {
    return Box::of_triangle(soup_points[t[0]], soup_points[t[1]], soup_points[t[2]]);
  };
  auto cur_id = [&](int v) -> std::int64_t { return layers[v] == 0 ? v : nv + v; };
  auto new_id = [&](int v) -> std::int64_t { return grows[v] ? 2 * nv + v : cur_id(v); };
  if (params.check_collisions) {
    soup_points.resize(3 * static_cast<std::size_t>(nv));
    std::copy(wall.points.begin(), wall.points.end(), soup_points.begin());
    tbb::parallel_for(0, nf, [&](int f) {
      const Triangle& t = wall.triangles[f];
      wall_tris[f] = {t[0], t[1], t[2]};
    });
  }

  for (int k = 0; k < n_layers; ++k) {
    for (int v = 0; v < nv; ++v) active[v] = !stopped[v];
    if (std::find(active.begin(), active.end(), 1) == active.end()) break;

    // ---- directions on the current front ----
    t0 = Clock::now();
    if (k > 0) {
      front.points = top;
      dirs = compute_directions(front, fans, vtri, nbr, active, params);
    }
    for (int v = 0; v < nv; ++v)
      if (active[v] && !dirs.ok[v]) stop(v, StopReason::kVisibility);
    for (int v = 0; v < nv; ++v) active[v] = !stopped[v];
    parallel_vertices(nv, [&](int v) {
      if (!active[v]) return;
      layer_h[v] = base[v] * scale[v] * rep.growth.heights[k];
      step[v] = layer_h[v] / std::max(dirs.visibility[v], 1.0 / params.max_step_stretch);
      phi[v] = 1.0;
      phi_reason[v] = StopReason::kProximity;
    });
    rep.t_normals += seconds_since(t0);

    // ---- proximity: gap ahead along the step ----
    t0 = Clock::now();
    if (k > 0) {
      tbb::parallel_for(0, nf, [&](int f) {
        const Triangle& t = wall.triangles[f];
        cur_boxes[f] = Box::of_triangle(top[t[0]], top[t[1]], top[t[2]]);
      });
      cur_bvh.refit(cur_boxes);
      unit_normals(wall.triangles, top, &cur_normal);
    }
    {
      ProximitySet ps;
      ps.tris = &wall.triangles;
      ps.wall_points = &wall.points;
      ps.wall_bvh = &wall_bvh;
      ps.wall_normal = &wall_normal;
      if (k > 0) {
        ps.front_points = &top;
        ps.front_bvh = &cur_bvh;
        ps.front_normal = &cur_normal;
      }
      parallel_vertices(nv, [&](int v) {
        if (!active[v]) return;
        const double d = ps.first_hit(v, top[v], dirs.n[v], step[v] / params.proximity_safety);
        if (d < HUGE_VAL) phi[v] = std::min(1.0, params.proximity_safety * d / step[v]);
      });
    }
    smooth_downward(nbr, active, params.height_smoothing_rings, &phi, &phi_reason);
    for (int v = 0; v < nv; ++v)
      if (active[v] && phi[v] < params.min_layer_fraction) stop(v, phi_reason[v]);
    rep.t_proximity += seconds_since(t0);

    // ---- exact checks with local height reduction ----
    // A cell or new front triangle is re-tested in a later attempt only if one of its
    // columns moved or changed growing state, or if it failed in the previous attempt:
    // the others are bit-identical to what already passed, so every attempt ends with
    // exactly the verdicts of a full re-check, at a fraction of its cost.
    t0 = Clock::now();
    for (int v = 0; v < nv; ++v) grows[v] = !stopped[v];
    if (params.check_collisions) {
      std::copy(top.begin(), top.end(), soup_points.begin() + nv);
      if (k > 0) {
        tbb::parallel_for(0, nf, [&](int f) {
          const Triangle& t = wall.triangles[f];
          cur_tris[f] = {cur_id(t[0]), cur_id(t[1]), cur_id(t[2])};
          cur_is_wall[f] = layers[t[0]] == 0 && layers[t[1]] == 0 && layers[t[2]] == 0;
        });
      }
    }
    std::fill(bad_cell.begin(), bad_cell.end(), 0);
    std::fill(collided.begin(), collided.end(), 0);
    for (int attempt = 0;; ++attempt) {
      parallel_vertices(nv, [&](int v) {
        next[v] = grows[v] ? top[v] + (phi[v] * step[v]) * dirs.n[v] : top[v];
        moved[v] = attempt == 0 || grows[v] != prev_grows[v] || !(next[v] == prev_next[v]);
      });
      prev_next = next;
      prev_grows = grows;
      tbb::parallel_for(0, nf, [&](int f) {
        const Triangle& t = wall.triangles[f];
        tri_moved[f] = moved[t[0]] || moved[t[1]] || moved[t[2]];
        tri_grows[f] = grows[t[0]] || grows[t[1]] || grows[t[2]];
      });
      std::vector<StopReason> bad_reason(nv, StopReason::kNone);
      std::fill(bad.begin(), bad.end(), 0);

      // Cells of this layer: exact corner-tet test.
      tbb::parallel_for(0, nf, [&](int f) {
        if (!tri_moved[f]) return;
        const Triangle& t = wall.triangles[f];
        const std::array<bool, 3> g = {bool(grows[t[0]]), bool(grows[t[1]]), bool(grows[t[2]])};
        LayerCell cell;
        bad_cell[f] = 0;
        // Local ids: 0..2 the bottoms, 3..5 the tops of the triangle's columns.
        if (!layer_cell({0, 1, 2}, {3, 4, 5}, g, &cell)) return;
        Vec3 c[6];
        for (int i = 0; i < corner_count(cell.type); ++i) {
          const int id = static_cast<int>(cell.nodes[i]);
          c[i] = id < 3 ? top[t[id]] : next[t[id - 3]];
        }
        bad_cell[f] = !cell_is_valid(cell.type, c);
      });
      for (int f = 0; f < nf; ++f)
        if (bad_cell[f])
          for (int v : wall.triangles[f])
            if (grows[v]) {
              bad[v] = 1;
              bad_reason[v] = StopReason::kQuality;
            }

      // New front against itself, the current front and the wall, on one point array
      // so that shared vertices are seen as such: wall v -> v, current top v -> nv + v
      // (v itself while still on the wall), new top v -> 2 nv + v (the current id where
      // the column does not grow). A new triangle none of whose columns grows is the
      // current (or wall) triangle itself, already checked, so it is neither tested nor
      // a partner; likewise a current triangle that is still the wall triangle.
      if (params.check_collisions) {
        std::copy(next.begin(), next.end(), soup_points.begin() + 2 * static_cast<std::size_t>(nv));
        tbb::parallel_for(0, nf, [&](int f) {
          const Triangle& t = wall.triangles[f];
          new_tris[f] = {new_id(t[0]), new_id(t[1]), new_id(t[2])};
          new_boxes[f] = tri_box(new_tris[f]);
          query[f] = tri_grows[f] && (tri_moved[f] || collided[f]);
          if (query[f] || !tri_grows[f]) collided[f] = 0;
        });
        new_bvh.refit(new_boxes);
        for (auto& l : partner_hits) l.clear();
        tbb::parallel_for(tbb::blocked_range<int>(0, nf), [&](const tbb::blocked_range<int>& r) {
          std::vector<int>& partners = partner_hits.local();
          for (int f = r.begin(); f != r.end(); ++f) {
            if (!query[f]) continue;
            const IndexedTriangle& s = new_tris[f];
            const Box& b = new_boxes[f];
            bool hit = false;
            wall_bvh.for_each_overlap(b, [&](int j) {
              if (!hit && soup_triangles_intersect(soup_points, s, wall_tris[j])) hit = true;
            });
            if (k > 0)
              cur_bvh.for_each_overlap(b, [&](int j) {
                if (!hit && !cur_is_wall[j] && soup_triangles_intersect(soup_points, s, cur_tris[j])) hit = true;
              });
            // A pair of new triangles is tested once: from the smaller id if both are
            // tested in this attempt, else from the one that is.
            new_bvh.for_each_overlap(b, [&](int j) {
              if (j == f || !tri_grows[j] || (query[j] && j < f)) return;
              if (soup_triangles_intersect(soup_points, s, new_tris[j])) {
                hit = true;
                partners.push_back(j);
              }
            });
            if (hit) collided[f] = 1;
          }
        });
        for (const auto& l : partner_hits)
          for (int j : l) collided[j] = 1;
      }
      for (int f = 0; f < nf; ++f) {
        bad_tri[f] = bad_cell[f] || collided[f];
        if (collided[f])
          for (int v : wall.triangles[f])
            if (grows[v]) {
              bad[v] = 1;
              if (bad_reason[v] == StopReason::kNone) bad_reason[v] = StopReason::kCollision;
            }
      }

      if (std::find(bad.begin(), bad.end(), 1) == bad.end()) break;

      // First repair: failing cells and colliding triangles mostly come from neighbouring
      // columns that diverge sideways by more than a short edge (thin triangles, mild
      // concavity). Turning each such column towards the mean direction of the failing
      // triangles around it removes that shear at full height, where halving the step
      // would only scale it. A turned direction must keep half of the column's
      // visibility (and min_visibility), so the step stays well above the front.
      if (attempt < params.direction_repair_passes) {
        std::vector<char> turned(nv, 0);
        std::vector<Vec3> new_n = dirs.n;
        std::vector<double> new_vis = dirs.visibility;
        parallel_vertices(nv, [&](int v) {
          if (!bad[v]) return;
          Vec3 sum{0.0, 0.0, 0.0};
          for (const int* f = vtri.begin(v); f != vtri.end(v); ++f)
            if (bad_tri[*f])
              for (int u : wall.triangles[*f])
                if (grows[u]) sum += dirs.n[u];
          const Vec3 cand = normalized(sum);
          if (!(norm2(cand) > 0.0)) return;
          const double vis = visibility_of(dirs, vtri, v, cand);
          if (vis >= params.min_visibility && vis >= 0.5 * dirs.visibility[v] && dot(cand, dirs.n[v]) < 1.0) {
            new_n[v] = cand;
            new_vis[v] = vis;
            turned[v] = 1;
          }
        });
        if (std::find(turned.begin(), turned.end(), 1) != turned.end()) {
          dirs.n.swap(new_n);
          dirs.visibility.swap(new_vis);
          for (int v = 0; v < nv; ++v)
            if (turned[v]) step[v] = layer_h[v] / std::max(dirs.visibility[v], 1.0 / params.max_step_stretch);
          continue;
        }
      }
      for (int v = 0; v < nv; ++v)
        if (bad[v]) {
          phi[v] *= 0.5;
          phi_reason[v] = bad_reason[v];
        }
      smooth_downward(nbr, grows, params.height_smoothing_rings, &phi, &phi_reason);
      for (int v = 0; v < nv; ++v)
        if (grows[v] && phi[v] < params.min_layer_fraction) {
          grows[v] = 0;
          stop(v, phi_reason[v]);
        }
    }
    rep.t_checks += seconds_since(t0);

    // ---- commit the layer ----
    t0 = Clock::now();
    std::vector<std::int64_t> new_id(nv, -1);
    int n_grown = 0;
    for (int v = 0; v < nv; ++v) {
      if (!grows[v]) continue;
      new_id[v] = static_cast<std::int64_t>(mesh.points.size());
      mesh.points.push_back(next[v]);
      point_normal[top_id[v]] = dirs.n[v];
      point_normal.push_back(dirs.n[v]);
      point_column.push_back(v);
      rep.min_visibility = std::min(rep.min_visibility, dirs.visibility[v]);
      ++n_grown;
    }
    rep.columns_per_layer.push_back(n_grown);
    for (const Triangle& t : wall.triangles) {
      const std::array<bool, 3> g = {bool(grows[t[0]]), bool(grows[t[1]]), bool(grows[t[2]])};
      LayerCell cell;
      if (!layer_cell({top_id[t[0]], top_id[t[1]], top_id[t[2]]},
                      {new_id[t[0]], new_id[t[1]], new_id[t[2]]}, g, &cell))
        continue;
      mesh.add_cell(cell.type, cell.nodes.data());
      cell_layer.push_back(k);
    }
    for (int v = 0; v < nv; ++v) {
      if (!grows[v]) continue;
      path[v] += norm(next[v] - top[v]);
      top[v] = next[v];
      top_id[v] = new_id[v];
      ++layers[v];
    }
    rep.t_assembly += seconds_since(t0);
    if (progress) progress(k + 1, n_layers);
  }

  // The marching state is no longer needed; freeing it here keeps it out of the peak
  // memory, which is reached while the output arrays are filled.
  auto release = [](auto& x) { x = std::decay_t<decltype(x)>(); };
  release(soup_points);
  release(wall_tris);
  release(cur_tris);
  release(new_tris);
  release(cur_boxes);
  release(new_boxes);
  release(cur_normal);
  release(wall_bvh);
  release(cur_bvh);
  release(new_bvh);
  release(prev_next);
  release(next);

  // ---- output arrays, envelope ----
  t0 = Clock::now();
  const std::int64_t np = static_cast<std::int64_t>(mesh.points.size());
  const std::int64_t nc = static_cast<std::int64_t>(mesh.n_cells());
  DataArray a_normal{"normal", 3, false, std::vector<double>(3 * np)};
  DataArray a_height{"column_height", 1, false, std::vector<double>(np)};
  DataArray a_reason{"stop_reason", 1, true, std::vector<double>(np)};
  DataArray a_layers{"layers", 1, true, std::vector<double>(np)};
  for (std::int64_t p = 0; p < np; ++p) {
    const int v = point_column[p];
    for (int i = 0; i < 3; ++i) a_normal.values[3 * p + i] = point_normal[p][i];
    a_height.values[p] = path[v];
    a_reason.values[p] = static_cast<int>(reason[v]);
    a_layers.values[p] = layers[v];
  }
  mesh.point_data = {std::move(a_normal), std::move(a_height), std::move(a_reason), std::move(a_layers)};
  DataArray c_layer{"layer", 1, true, std::vector<double>(cell_layer.begin(), cell_layer.end())};
  DataArray c_jac{"min_corner_jacobian", 1, false, std::vector<double>(nc)};
  tbb::parallel_for(std::int64_t(0), nc, [&](std::int64_t c) {
    Vec3 corners[8];
    const std::int64_t o = mesh.offsets[c];
    const int n = corner_count(mesh.cell_types[c]);
    for (int i = 0; i < n; ++i) corners[i] = mesh.points[mesh.connectivity[o + i]];
    c_jac.values[c] = compute_cell_metrics(mesh.cell_types[c], corners).scaled_jacobian;
  });
  mesh.cell_data = {std::move(c_layer), std::move(c_jac)};

  res.envelope.points = top;
  res.envelope.triangles = wall.triangles;
  res.envelope_point_ids = top_id;
  res.column_layers = layers;
  res.stop_reason = reason;
  rep.t_assembly += seconds_since(t0);

  // ---- report: independent exact re-check and statistics ----
  t0 = Clock::now();
  std::atomic<std::int64_t> n_invalid{0};
  tbb::parallel_for(std::int64_t(0), nc, [&](std::int64_t c) {
    Vec3 corners[8];
    const std::int64_t o = mesh.offsets[c];
    const int n = corner_count(mesh.cell_types[c]);
    for (int i = 0; i < n; ++i) corners[i] = mesh.points[mesh.connectivity[o + i]];
    if (cell_validity(mesh.cell_types[c], corners) != Validity::kValid) ++n_invalid;
  });
  rep.n_invalid_cells = n_invalid.load();
  rep.n_points = np;
  rep.min_scaled_jacobian = nc > 0 ? 1.0 : 0.0;
  const DataArray& jac = mesh.cell_data[1];
  for (std::int64_t c = 0; c < nc; ++c) {
    switch (mesh.cell_types[c]) {
      case CellType::kWedge: ++rep.n_wedges; break;
      case CellType::kPyramid: ++rep.n_pyramids; break;
      case CellType::kTet: ++rep.n_tets; break;
      case CellType::kHex: break;
    }
    rep.min_scaled_jacobian = std::min(rep.min_scaled_jacobian, jac.values[c]);
  }
  if (rep.min_visibility == 1.0 && rep.columns_per_layer.empty()) rep.min_visibility = 0.0;

  // Heights above the wall: min over incident wall face planes.
  std::vector<Vec3> wall_fn(nf);
  tbb::parallel_for(0, nf, [&](int f) { wall_fn[f] = normalized(triangle_area_vector(wall, wall.triangles[f])); });
  std::vector<std::int64_t> first_id(nv, -1);
  for (std::int64_t p = nv; p < np; ++p)
    if (first_id[point_column[p]] < 0) first_id[point_column[p]] = p;
  auto height_above = [&](int v, const Vec3& q) {
    double m = HUGE_VAL;
    for (const int* f = vtri.begin(v); f != vtri.end(v); ++f) m = std::min(m, dot(q - wall.points[v], wall_fn[*f]));
    return m;
  };
  RangeStats fh{HUGE_VAL, 0.0, -HUGE_VAL}, th{HUGE_VAL, 0.0, -HUGE_VAL}, tf{HUGE_VAL, 0.0, -HUGE_VAL};
  int n_fh = 0, n_cols = 0;
  auto add = [](RangeStats& s, double x) {
    s.min = std::min(s.min, x);
    s.max = std::max(s.max, x);
    s.mean += x;
  };
  for (int v = 0; v < nv; ++v) {
    if (!used[v]) continue;
    ++n_cols;
    const double total = layers[v] > 0 ? height_above(v, top[v]) : 0.0;
    add(th, total);
    add(tf, total / (base[v] * rep.growth.total_thickness));
    if (layers[v] > 0) {
      add(fh, height_above(v, mesh.points[first_id[v]]));
      ++n_fh;
    }
    if (layers[v] == n_layers) ++rep.n_complete_columns;
    else ++rep.stopped_columns[static_cast<int>(reason[v])];
  }
  auto finish = [](RangeStats& s, int n) {
    if (n == 0) s = RangeStats{};
    else s.mean /= n;
  };
  finish(fh, n_fh);
  finish(th, n_cols);
  finish(tf, n_cols);
  rep.first_height = fh;
  rep.total_thickness = th;
  rep.thickness_fraction = tf;
  double area = 0.0, area_full = 0.0;
  int n_full = 0;
  for (const Triangle& t : wall.triangles) {
    const double a = 0.5 * norm(triangle_area_vector(wall, t));
    area += a;
    if (layers[t[0]] == n_layers && layers[t[1]] == n_layers && layers[t[2]] == n_layers) {
      ++n_full;
      area_full += a;
    }
  }
  rep.coverage = nf > 0 ? double(n_full) / nf : 0.0;
  rep.area_coverage = area > 0.0 ? area_full / area : 0.0;
  rep.t_report = seconds_since(t0);
  rep.t_total = seconds_since(t_start);
  return res;
}

std::vector<std::pair<int, int>> find_envelope_intersections(const TriSurface& wall, const ExtrusionResult& result,
                                                             std::size_t max_pairs) {
  std::vector<IndexedTriangle> tris;
  tris.reserve(2 * wall.triangles.size());
  for (const Triangle& t : wall.triangles) tris.push_back({t[0], t[1], t[2]});
  for (const Triangle& t : result.envelope.triangles)
    tris.push_back({result.envelope_point_ids[t[0]], result.envelope_point_ids[t[1]], result.envelope_point_ids[t[2]]});
  return find_triangle_intersections(result.mesh.points, tris, nullptr, max_pairs);
}

}  // namespace blayer
