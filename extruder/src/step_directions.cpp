#include "blayer/extruder/step_directions.h"

#include <algorithm>
#include <optional>

#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/vertex_normal.h"
#include "parallel.h"

namespace blayer {

namespace {

Vec3 keep_in_plane(const WallTopology& topo, int v, const Vec3& d);

std::vector<Vec3> unit_face_normals(const TriSurface& s) {
  std::vector<Vec3> fn(s.triangles.size());
  tbb::parallel_for(0, static_cast<int>(s.triangles.size()),
                    [&](int t) { fn[t] = normalized(triangle_area_vector(s, s.triangles[t])); });
  return fn;
}

// One Jacobi smoothing pass over the ok directions (see compute_step_directions).
void smoothing_pass(const WallTopology& topo, const std::vector<double>& raw_visibility, double min_visibility,
                    const std::vector<char>& fixed, StepDirections* d) {
  const Csr& nbr = topo.vertex_neighbours;
  std::vector<Vec3> next = d->n;
  std::vector<double> next_vis = d->visibility;
  parallel_vertices(topo.n_points(), [&](int v) {
    if (!d->ok[v] || (!fixed.empty() && fixed[v])) return;
    Vec3 avg = d->n[v];
    for (const int* u = nbr.begin(v); u != nbr.end(v); ++u) {
      if (!d->ok[*u]) continue;
      avg += d->n[*u];
      // On the symmetry plane the mirrored model's neighbours count too: the sum is
      // then the full model's, symmetric, in the plane.
      if (topo.on_plane[v] && !topo.on_plane[*u]) avg += topo.plane->mirror_direction(d->n[*u]);
    }
    avg = normalized(avg);
    if (!(norm2(avg) > 0.0)) return;
    for (double t : {1.0, 0.5, 0.25}) {
      const Vec3 cand = keep_in_plane(topo, v, normalized((1.0 - t) * d->n[v] + t * avg));
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

// A column's warm start on a front, and whether its certificate held.
struct ColumnWarmStart {
  MostNormalWarmStart* state = nullptr;  // null: solve cold
  bool hit = false;
};

VertexNormal solve_fan(const FanGeometry& g, NormalMethod method, ColumnWarmStart* warm) {
  if (!warm || !warm->state) return compute_vertex_normal(g, method);
  return compute_vertex_normal(g, method, default_tolerances(), warm->state, &warm->hit);
}

// The normal of v's own fan on the front, ignoring a symmetry plane (the per-vertex
// kernel of compute_point_normals).
VertexNormal plain_fan_normal(const TriSurface& front, const WallTopology& topo, int v, NormalMethod method,
                              ColumnWarmStart* warm = nullptr) {
  const VertexFan& fan = topo.fans.fans[v];
  std::vector<Vec3> ring;
  ring.reserve(fan.ring.size());
  for (int r : fan.ring) ring.push_back(front.points[r]);
  FanGeometry g;
  build_fan_geometry(front.points[v], ring, fan.closed, default_tolerances(), &g);
  return solve_fan(g, method, warm);
}

// The point normal of the front at v alone.
VertexNormal front_normal(const TriSurface& front, const WallTopology& topo, int v, NormalMethod method,
                          ColumnWarmStart* warm = nullptr) {
  if (!topo.on_plane[v]) return plain_fan_normal(front, topo, v, method, warm);
  const VertexFan& fan = topo.fans.fans[v];
  std::vector<Vec3> ring;
  ring.reserve(2 * fan.ring.size());
  for (int r : fan.ring) ring.push_back(front.points[r]);
  FanGeometry g;
  // A point on the symmetry plane: its fan is half of the symmetric fan the mirrored
  // model would give; that fan's normal is symmetric, i.e. in the plane (rounding
  // aside, removed by the projection). Ring r_0 .. r_m (r_0, r_m on the plane), then
  // the mirror images of r_{m-1} .. r_1.
  const SymmetryPlane& plane = *topo.plane;
  for (int j = static_cast<int>(fan.ring.size()) - 2; j >= 1; --j) ring.push_back(plane.mirror(front.points[fan.ring[j]]));
  build_fan_geometry(front.points[v], ring, true, default_tolerances(), &g);
  VertexNormal n = solve_fan(g, method, warm);
  n.normal = normalized(plane.in_plane(n.normal));
  return n;
}

// The memo's entry for v's wall point when it holds v's fan geometry, bit for bit, or -1.
int memo_entry(const WallNormalMemo& memo, const TriSurface& front, const WallTopology& topo, int v) {
  const int e = memo.entry_of(topo.wall_point[v]);
  if (e < 0) return -1;
  const VertexFan& fan = topo.fans.fans[v];
  const Vec3* stored = memo.points.data() + memo.start[e];
  if (memo.start[e + 1] - memo.start[e] != fan.ring.size() + 1 || (memo.closed[e] != 0) != fan.closed) return -1;
  if (!same_bits(stored[0], front.points[v])) return -1;
  for (std::size_t i = 0; i < fan.ring.size(); ++i)
    if (!same_bits(stored[i + 1], front.points[fan.ring[i]])) return -1;
  return e;
}

// The warm starts of one front's solves: each column's state, and per column whether
// it came valid and whether its certificate held (summed into the run's counts by
// finish(), after the parallel pass, so the counts do not depend on the threads).
struct WarmTally {
  FrontWarmStarts* starts;
  std::vector<char> valid, hit;

  WarmTally(FrontWarmStarts* s, int n_columns) : starts(s), valid(n_columns, 0), hit(n_columns, 0) {
    if (starts->by_column.size() < static_cast<std::size_t>(n_columns)) starts->by_column.resize(n_columns);
  }
  ColumnWarmStart enter(int v) {
    valid[v] = starts->by_column[v].valid;
    return ColumnWarmStart{&starts->by_column[v], false};
  }
  // Only a visibility-constrained optimum is carried to the next front (see
  // FrontWarmStarts in step_directions.h).
  void leave(int v, const ColumnWarmStart& w, const VertexNormal& n) {
    hit[v] = w.hit;
    if (n.status != NormalStatus::kVisibilityConstrained) starts->by_column[v].valid = false;
  }
  void finish() {
    for (std::size_t v = 0; v < valid.size(); ++v) {
      starts->counts.warm += valid[v];
      starts->counts.hits += hit[v];
    }
  }
};

// The memo the points with `which` set leave: an entry per wall point that one of them
// alone stands on (several do at a fan's columns), whose fan the memo stores; the
// geometry and normals are filled in by the caller's parallel pass. *entry_of_point
// receives each point's entry, or -1.
WallNormalMemo memo_layout(const TriSurface& front, const WallTopology& topo, const std::vector<char>& which,
                           const WallNormalMemo& old, std::vector<int>* entry_of_point) {
  const int nv = static_cast<int>(front.points.size());
  int n_wall = 0;
  for (int v = 0; v < nv; ++v)
    if (which[v]) n_wall = std::max(n_wall, topo.wall_point[v] + 1);
  std::vector<int> owner(n_wall, -1);
  for (int v = 0; v < nv; ++v) {
    const int w = topo.wall_point[v];
    if (!which[v] || w < 0 || !old.stores(topo.fans.fans[v])) continue;
    owner[w] = owner[w] == -1 ? v : -2;
  }
  WallNormalMemo m;
  m.reused = old.reused;
  m.solved = old.solved;
  m.keep_cheap = old.keep_cheap;
  entry_of_point->assign(nv, -1);
  m.start.push_back(0);
  for (int w = 0; w < n_wall; ++w) {
    const int v = owner[w];
    if (v < 0) continue;
    (*entry_of_point)[v] = static_cast<int>(m.wall_point.size());
    m.wall_point.push_back(w);
    m.start.push_back(m.start.back() + topo.fans.fans[v].ring.size() + 1);
  }
  m.points.resize(m.start.back());
  m.closed.resize(m.wall_point.size());
  m.normal.resize(m.wall_point.size());
  return m;
}

void store_in_memo(const TriSurface& front, const WallTopology& topo, int v, const VertexNormal& n, int e,
                   WallNormalMemo* m) {
  const VertexFan& fan = topo.fans.fans[v];
  Vec3* out = m->points.data() + m->start[e];
  out[0] = front.points[v];
  for (std::size_t i = 0; i < fan.ring.size(); ++i) out[i + 1] = front.points[fan.ring[i]];
  m->closed[e] = fan.closed;
  m->normal[e] = n;
}

// plain_fan_normal for the points with `which` set (the others keep the status of an
// empty fan), through the memo when one is given.
std::vector<VertexNormal> plain_fan_normals(const TriSurface& front, const WallTopology& topo,
                                            const std::vector<char>& which, NormalMethod method, WallNormalMemo* memo,
                                            WarmTally* warm) {
  const int nv = static_cast<int>(front.points.size());
  std::vector<VertexNormal> out(nv);
  for (VertexNormal& n : out) n.status = NormalStatus::kDegenerateFan;
  std::vector<char> solved(nv, 0);
  std::vector<int> entry_of_point;
  WallNormalMemo next;
  if (memo) next = memo_layout(front, topo, which, *memo, &entry_of_point);
  parallel_vertices(nv, [&](int v) {
    if (!which[v]) return;
    const int e = memo ? memo_entry(*memo, front, topo, v) : -1;
    if (e >= 0) {
      out[v] = memo->normal[e];
    } else {
      // A column on the symmetry plane is warm-started on its mirrored fan only
      // (compute_step_directions), whose sites its warm start names.
      const bool warmed = warm && !topo.on_plane[v];
      ColumnWarmStart w = warmed ? warm->enter(v) : ColumnWarmStart{};
      out[v] = plain_fan_normal(front, topo, v, method, &w);
      if (warmed) warm->leave(v, w, out[v]);
      solved[v] = 1;
    }
    if (memo && entry_of_point[v] >= 0) store_in_memo(front, topo, v, out[v], entry_of_point[v], &next);
  });
  if (!memo) return out;
  for (int v = 0; v < nv; ++v) {
    if (!which[v]) continue;
    if (solved[v]) {
      ++next.solved;
    } else {
      ++next.reused;
    }
  }
  *memo = std::move(next);
  return out;
}

// Keeps a column on the symmetry plane in it.
Vec3 keep_in_plane(const WallTopology& topo, int v, const Vec3& d) {
  return topo.on_plane[v] ? normalized(topo.plane->in_plane(d)) : d;
}

// Turns column v from its kept direction towards the front normal n by the least blend
// t in (0, 1] whose visibility reaches `target` (bisection: visibility along the blend
// is not monotone in general, so the result is the smallest t found that reaches it,
// never a direction below the target).
bool turn_to_visible(const StepDirections& d, const WallTopology& topo, int v, const Vec3& kept, const Vec3& n,
                     double target, Vec3* out, double* out_vis) {
  const double vis_n = visibility_of(d, topo, v, n);
  if (vis_n < target) return false;
  double lo = 0.0, hi = 1.0;
  Vec3 best = n;
  double best_vis = vis_n;
  for (int it = 0; it < 24; ++it) {
    const double t = 0.5 * (lo + hi);
    const Vec3 c = normalized((1.0 - t) * kept + t * n);
    const double vis = norm2(c) > 0.0 ? visibility_of(d, topo, v, c) : -1.0;
    if (vis >= target) {
      hi = t;
      best = c;
      best_vis = vis;
    } else {
      lo = t;
    }
  }
  *out = best;
  *out_vis = best_vis;
  return true;
}

}  // namespace

int WallNormalMemo::entry_of(int w) const {
  const auto it = std::lower_bound(wall_point.begin(), wall_point.end(), w);
  return it != wall_point.end() && *it == w ? static_cast<int>(it - wall_point.begin()) : -1;
}

void WallNormalMemo::drop_cheap() {
  keep_cheap = false;
  WallNormalMemo kept;
  kept.start.push_back(0);
  for (std::size_t e = 0; e < wall_point.size(); ++e) {
    if (start[e + 1] - start[e] < kMemoMinValence + 1) continue;  // the point and its ring
    kept.wall_point.push_back(wall_point[e]);
    kept.points.insert(kept.points.end(), points.begin() + start[e], points.begin() + start[e + 1]);
    kept.start.push_back(kept.points.size());
    kept.closed.push_back(closed[e]);
    kept.normal.push_back(normal[e]);
  }
  wall_point = std::move(kept.wall_point);
  start = std::move(kept.start);
  points = std::move(kept.points);
  closed = std::move(kept.closed);
  normal = std::move(kept.normal);
}

VertexNormal surface_point_normal(const TriSurface& s, const WallTopology& topo, int v, NormalMethod method) {
  return front_normal(s, topo, v, method);
}

StepDirections update_step_directions(const TriSurface& front, const WallTopology& topo,
                                      const std::vector<char>& active, const ExtrusionParams& p,
                                      const StepDirections& previous, int* n_turned, FrontWarmStarts* warm) {
  *n_turned = 0;
  if (p.column_directions == ColumnDirections::kRecomputed)
    return compute_step_directions(front, topo, active, p, nullptr, nullptr, warm);
  const int nv = static_cast<int>(front.points.size());
  StepDirections d;
  d.face_normal = unit_face_normals(front);
  d.n = previous.n;
  d.visibility.assign(nv, 0.0);
  d.ok.assign(nv, 0);
  std::vector<char> turned(nv, 0);
  parallel_vertices(nv, [&](int v) {
    if (!active[v] || topo.vertex_triangles.count(v) == 0 || !previous.ok[v]) return;
    d.visibility[v] = visibility_of(d, topo, v, d.n[v]);
    if (d.visibility[v] >= p.min_visibility) {
      d.ok[v] = 1;
      return;
    }
    const VertexNormal fn = front_normal(front, topo, v, p.normal_method);
    if (fn.status == NormalStatus::kNoVisibleDirection || !(norm2(fn.normal) > 0.0) || !is_finite(fn.normal)) return;
    const double target = std::max(p.min_visibility, 0.5 * visibility_of(d, topo, v, fn.normal));
    Vec3 c;
    double vis = 0.0;
    if (!turn_to_visible(d, topo, v, previous.n[v], fn.normal, target, &c, &vis)) return;
    d.n[v] = c;
    d.visibility[v] = vis;
    d.ok[v] = 1;
    turned[v] = 1;
  });
  for (char t : turned) *n_turned += t;
  return d;
}

double visibility_of(const StepDirections& d, const WallTopology& topo, int v, const Vec3& n) {
  double m = 1.0;
  const Csr& vtri = topo.vertex_triangles;
  for (const int* t = vtri.begin(v); t != vtri.end(v); ++t) m = std::min(m, dot(n, d.face_normal[*t]));
  return m;
}

StepDirections compute_step_directions(const TriSurface& front, const WallTopology& topo,
                                       const std::vector<char>& active, const ExtrusionParams& p,
                                       const PrescribedDirections* prescribed, WallNormalMemo* memo,
                                       FrontWarmStarts* warm) {
  const int nv = static_cast<int>(front.points.size());
  std::optional<WarmTally> tally;
  if (warm) tally.emplace(warm, nv);
  std::vector<char> fixed;
  // With prescribed directions, the fan points' own fans on the wall are degenerate
  // (their columns coincide): only the other points get the front's normal, and those
  // on the symmetry plane get it below. Without, every point with a fan gets its fan's
  // normal, as compute_point_normals gives it.
  std::vector<char> which(nv, 0);
  if (prescribed) fixed.assign(nv, 0);
  parallel_vertices(nv, [&](int v) {
    if (prescribed) fixed[v] = norm2(prescribed->n[v]) > 0.0;
    which[v] = prescribed ? !fixed[v] && !topo.on_plane[v] && topo.vertex_triangles.count(v) > 0
                          : v < static_cast<int>(topo.fans.fans.size()) && !topo.fans.fans[v].triangles.empty();
  });
  const std::vector<VertexNormal> fan_normals =
      plain_fan_normals(front, topo, which, p.normal_method, memo, tally ? &*tally : nullptr);
  PointNormals pn;
  pn.normal.assign(nv, Vec3{0.0, 0.0, 0.0});
  pn.status.assign(nv, prescribed ? NormalStatus::kNoVisibleDirection : NormalStatus::kDegenerateFan);
  for (int v = 0; v < nv; ++v)
    if (which[v]) {
      pn.normal[v] = fan_normals[v].normal;
      pn.status[v] = fan_normals[v].status;
    }
  parallel_vertices(nv, [&](int v) {
    if (!topo.on_plane[v] || !active[v]) return;
    ColumnWarmStart w = tally ? tally->enter(v) : ColumnWarmStart{};
    const VertexNormal n = front_normal(front, topo, v, p.normal_method, &w);
    if (tally) tally->leave(v, w, n);
    pn.normal[v] = n.normal;
    pn.status[v] = n.status;
  });
  if (tally) tally->finish();
  StepDirections d;
  d.face_normal = unit_face_normals(front);
  d.n = pn.normal;
  d.visibility.assign(nv, 0.0);
  d.ok.assign(nv, 0);
  parallel_vertices(nv, [&](int v) {
    if (!active[v] || topo.vertex_triangles.count(v) == 0) return;
    if (!fixed.empty() && fixed[v]) {
      d.n[v] = prescribed->n[v];
      d.visibility[v] = prescribed->visibility[v];
      d.ok[v] = d.visibility[v] >= p.min_visibility;
      return;
    }
    if (pn.status[v] == NormalStatus::kNoVisibleDirection || !(norm2(d.n[v]) > 0.0) || !is_finite(d.n[v])) return;
    d.visibility[v] = visibility_of(d, topo, v, d.n[v]);
    d.ok[v] = d.visibility[v] >= p.min_visibility;
  });
  const std::vector<double> raw_visibility = d.visibility;
  for (int it = 0; it < p.normal_smoothing_iterations; ++it)
    smoothing_pass(topo, raw_visibility, p.min_visibility, fixed, &d);
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
    const Vec3 cand = keep_in_plane(topo, v, normalized(sum));
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
