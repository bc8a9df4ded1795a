#include "blayer/extruder/fan_layout.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

#include "blayer/core/assert.h"
#include "blayer/core/edge_topology.h"
#include "blayer/core/union_find.h"
#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/vertex_normal.h"

namespace blayer {

namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

using EdgeKey = std::pair<int, int>;
EdgeKey edge_key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Normalised linear blend towards the great-circle interpolation of unit a and b
// (slerp), at fraction t.
Vec3 slerp(const Vec3& a, const Vec3& b, double t) {
  const double w = angle_between(a, b);
  if (w < 1e-12) return a;
  const double s = std::sin(w);
  return normalized((std::sin((1.0 - t) * w) / s) * a + (std::sin(t * w) / s) * b);
}

struct Ridge {
  int a = 0, b = 0;        // a -> b as the first triangle t0 runs it
  int t0 = -1, t1 = -1;    // the triangles on either side
};

// Ridge edges by their end points: sorted keys, searched by bisection (every fan
// triangle of every fan point asks once).
class RidgeIndex {
 public:
  void build(const std::vector<Ridge>& ridges) {
    keys_.clear();
    for (int i = 0; i < static_cast<int>(ridges.size()); ++i) keys_.push_back({edge_key(ridges[i].a, ridges[i].b), i});
    std::sort(keys_.begin(), keys_.end());
  }
  // The ridge through a and b, or -1 (the last listed of repeated edges).
  int find(int a, int b) const {
    const EdgeKey key = edge_key(a, b);
    auto it = std::upper_bound(keys_.begin(), keys_.end(), std::make_pair(key, std::numeric_limits<int>::max()));
    return it != keys_.begin() && std::prev(it)->first == key ? std::prev(it)->second : -1;
  }

 private:
  std::vector<std::pair<EdgeKey, int>> keys_;
};

// Convex ridge edges whose turning angle exceeds the threshold.
std::vector<Ridge> find_ridges(const TriSurface& wall, const std::vector<Vec3>& fn, double threshold) {
  std::vector<Ridge> ridges;
  const EdgeTopology edges = build_edge_topology(wall);
  for (const SurfaceEdge& e : edges.edges) {
    if (e.kind != EdgeKind::kManifold) continue;
    const int t0 = e.triangle[0], t1 = e.triangle[1];
    if (!(angle_between(fn[t0], fn[t1]) > threshold)) continue;
    int d = -1;
    for (int v : wall.triangles[t1])
      if (v != e.lo && v != e.hi) d = v;
    if (!(dot(fn[t0], wall.points[d] - wall.points[e.lo]) < 0.0)) continue;  // concave or flat
    Ridge r;
    r.t0 = t0;
    r.t1 = t1;
    r.a = e.forward[0] ? e.lo : e.hi;
    r.b = e.forward[0] ? e.hi : e.lo;
    ridges.push_back(r);
  }
  return ridges;
}

// Fan points: on two or more ridge edges, with a closed fan, not excluded. Keeps the
// ridges with at least one fan point (a ridge between two single columns is none).
std::vector<Ridge> ridges_with_fans(const std::vector<Ridge>& ridges, const VertexFans& fans,
                                    const std::vector<char>& excluded, std::vector<char>* is_fan) {
  const int nv = static_cast<int>(excluded.size());
  std::vector<int> degree(nv, 0);
  for (const Ridge& r : ridges) {
    ++degree[r.a];
    ++degree[r.b];
  }
  is_fan->assign(nv, 0);
  for (int v = 0; v < nv; ++v)
    (*is_fan)[v] = degree[v] >= 2 && !excluded[v] && v < static_cast<int>(fans.fans.size()) && fans.fans[v].closed;
  std::vector<Ridge> kept;
  for (const Ridge& r : ridges)
    if ((*is_fan)[r.a] || (*is_fan)[r.b]) kept.push_back(r);
  return kept;
}

// Ridge ends: the single-column points at the far end of a ridge from a fan point.
std::vector<char> ridge_end_points(const std::vector<Ridge>& ridges, const std::vector<char>& is_fan) {
  std::vector<char> end(is_fan.size(), 0);
  for (const Ridge& r : ridges)
    if (is_fan[r.a] != is_fan[r.b]) end[is_fan[r.a] ? r.b : r.a] = 1;
  return end;
}

// Two ridge-end points joined by a wall edge would split the faces over that edge from
// both ends: the fan points on ridges to them join no_fan. Returns whether any did.
bool drop_adjacent_ridge_ends(const TriSurface& wall, const std::vector<Ridge>& ridges,
                              const std::vector<char>& is_fan, std::vector<char>* no_fan) {
  const std::vector<char> end = ridge_end_points(ridges, is_fan);
  std::vector<char> clash(is_fan.size(), 0);
  for (const Triangle& t : wall.triangles)
    for (int i = 0; i < 3; ++i)
      if (end[t[i]] && end[t[(i + 1) % 3]]) clash[t[i]] = clash[t[(i + 1) % 3]] = 1;
  bool any = false;
  for (const Ridge& r : ridges)
    for (auto [x, y] : {std::pair{r.a, r.b}, std::pair{r.b, r.a}})
      if (clash[x] && is_fan[y] && !(*no_fan)[y]) {
        (*no_fan)[y] = 1;
        any = true;
      }
  return any;
}

// The sectors of a fan point: runs of its fan's triangles between ridge edges.
struct Sectors {
  std::vector<int> first;            // per sector: index of its first fan triangle
  std::vector<int> sector_of;        // per fan triangle
  std::vector<int> column;           // per sector: its column
};

Sectors sectors_of(const VertexFan& fan, int v, const RidgeIndex& ridge_index) {
  const int k = static_cast<int>(fan.triangles.size());
  // Fan triangle i whose leading edge (v, ring[i]) is a ridge; gathered in a per-thread
  // buffer and copied once (see sector_normal).
  thread_local std::vector<int> split;
  split.clear();
  for (int i = 0; i < k; ++i)
    if (ridge_index.find(v, fan.ring[i]) >= 0) split.push_back(i);
  Sectors s;
  s.first.assign(split.begin(), split.end());
  s.sector_of.assign(k, -1);
  for (std::size_t j = 0; j < split.size(); ++j) {
    const int end = j + 1 < split.size() ? split[j + 1] : split[0] + k;
    for (int i = split[j]; i < end; ++i) s.sector_of[i % k] = static_cast<int>(j);
  }
  return s;
}

// The sector's normal at v: the normal method on the sector's triangles alone (an open
// fan: its link is open, so the methods fall back to the most-visible direction of
// those faces; a flat sector gives its face normal). Solved for thousands of fan points
// in parallel, with the ring and the geometry in per-thread buffers: the run's malloc
// has one arena (app/huge_pages.h), and the threads' allocations here waited on each
// other (the perforated block's layout took 44-48 ms on two threads, 27 ms on one).
Vec3 sector_normal(const TriSurface& wall, const VertexFan& fan, int v, const Sectors& s, int sector,
                   NormalMethod method) {
  const int k = static_cast<int>(fan.triangles.size());
  const int begin = s.first[sector];
  const int end = sector + 1 < static_cast<int>(s.first.size()) ? s.first[sector + 1] : s.first[0] + k;
  thread_local std::vector<Vec3> ring;
  thread_local FanGeometry g;
  ring.clear();
  for (int i = begin; i <= end; ++i) ring.push_back(wall.points[fan.ring[i % k]]);
  build_fan_geometry(wall.points[v], ring, false, default_tolerances(), &g);
  return compute_vertex_normal(g, method).normal;
}

}  // namespace

ColumnLayout single_column_layout(const TriSurface& wall) {
  const int nv = static_cast<int>(wall.points.size());
  const int nf = static_cast<int>(wall.triangles.size());
  ColumnLayout out;
  out.front = wall;
  out.wall_point.resize(nv);
  for (int v = 0; v < nv; ++v) out.wall_point[v] = v;
  out.direction.assign(nv, Vec3{0.0, 0.0, 0.0});
  out.in_fan.assign(nv, 0);
  out.faceless.assign(nv, 0);
  out.wall_face.resize(nf);
  out.elements.resize(nf);
  out.element_of_triangle.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const Triangle& t = wall.triangles[f];
    out.wall_face[f] = f;
    out.elements[f] = {ElementKind::kTriangle, {t[0], t[1], t[2], -1}};
    out.element_of_triangle[f] = f;
  }
  return out;
}

namespace {

// The layout of one extrusion, built in the order of the header's description: ridges,
// the columns of single and fan points, the slices per ridge chain, then the front's
// wall triangles, strips and corner patches.
class LayoutBuilder {
 public:
  LayoutBuilder(const TriSurface& wall, const VertexFans& fans, const FanParams& p, NormalMethod method)
      : wall_(wall), fans_(fans), p_(p), method_(method), nv_(static_cast<int>(wall.points.size())) {}

  // False when no ridge gets a fan (the layout is then single_column_layout's).
  bool select_ridges(const std::vector<char>& excluded) {
    const int nf = static_cast<int>(wall_.triangles.size());
    std::vector<Vec3> fn(nf);
    for (int f = 0; f < nf; ++f) fn[f] = normalized(triangle_area_vector(wall_, wall_.triangles[f]));
    is_fan_.assign(nv_, 0);
    if (p_.fan_angle_deg > 0.0) {
      const double ridge_turn = p_.fan_angle_deg * (1.0 + kFanAngleSlack) * kDegToRad;
      const std::vector<Ridge> candidates = find_ridges(wall_, fn, ridge_turn);
      std::vector<char> no_fan = excluded;
      do ridges_ = ridges_with_fans(candidates, fans_, no_fan, &is_fan_);
      while (drop_adjacent_ridge_ends(wall_, ridges_, is_fan_, &no_fan));
    }
    degree_.assign(nv_, 0);
    ridge_index_.build(ridges_);
    for (int i = 0; i < static_cast<int>(ridges_.size()); ++i) {
      const Ridge& r = ridges_[i];
      ++degree_[r.a];
      ++degree_[r.b];
      out_.n_ridge_ends += is_fan_[r.a] != is_fan_[r.b];
    }
    out_.n_ridge_edges = static_cast<int>(ridges_.size());
    return !ridges_.empty();
  }

  // Columns of single points and sector columns of fan points.
  void add_point_columns() {
    plain_column_.assign(nv_, -1);
    sectors_.resize(nv_);
    sector_dir_.resize(nv_);
    // The sectors' normals are independent solves, most of the layout's time where a
    // CAD surface has thousands of fan points: solved in parallel, then the columns are
    // numbered in point order as before.
    tbb::parallel_for(0, nv_, [&](int v) {
      if (!is_fan_[v]) return;
      const VertexFan& fan = fans_.fans[v];
      sectors_[v] = sectors_of(fan, v, ridge_index_);
      sector_dir_[v].reserve(sectors_[v].first.size());
      for (std::size_t s = 0; s < sectors_[v].first.size(); ++s)
        sector_dir_[v].push_back(sector_normal(wall_, fan, v, sectors_[v], static_cast<int>(s), method_));
    });
    for (int v = 0; v < nv_; ++v) {
      if (!is_fan_[v]) {
        plain_column_[v] = add_column(v, Vec3{0.0, 0.0, 0.0}, false, false);
        continue;
      }
      ++out_.n_fan_points;
      for (const Vec3& n : sector_dir_[v]) sectors_[v].column.push_back(add_column(v, n, true, false));
    }
  }

  // Slices per ridge chain: the ridge edges joined through fan points on exactly two
  // of them (both edges then share the point's one fan, so their slices must match);
  // a corner or a ridge end separates chains, whose fans there are distinct. m is the
  // largest any fan of the chain needs, so a 90-degree rim keeps its 3 slices beside a
  // 165-degree trailing edge's 6.
  void count_slices() {
    const int nr = static_cast<int>(ridges_.size());
    chains_ = UnionFind(nr);
    chain_m_.assign(nr, 0);
    fan_lists_.assign(nv_, {});
    std::vector<int> first_ridge_at(nv_, -1);
    for (int i = 0; i < nr; ++i)
      for (int x : {ridges_[i].a, ridges_[i].b}) {
        if (!is_fan_[x] || degree_[x] != 2) continue;
        if (first_ridge_at[x] < 0)
          first_ridge_at[x] = i;
        else
          chains_.unite(first_ridge_at[x], i);
      }
    const double max_sector = std::max(p_.max_sector_deg, 1.0) * kDegToRad;
    for (int i = 0; i < nr; ++i) {
      const Ridge& r = ridges_[i];
      int& m = chain_m_[chains_.find(i)];  // 0 until a ridge of the chain sets it
      m = std::max(m, 1);
      for (int x : {r.a, r.b}) {
        if (!is_fan_[x]) continue;
        const double gap = angle_between(sector_dir_[x][sector_at(x, r.t0)], sector_dir_[x][sector_at(x, r.t1)]);
        m = std::max(m, static_cast<int>(std::ceil(gap / max_sector - kFanAngleSlack)));
      }
    }
  }

  // Front: wall triangles on their sector columns; a corner at a ridge end splits.
  void add_wall_triangles() {
    const std::vector<char> ridge_end = ridge_end_points(ridges_, is_fan_);
    for (int f = 0; f < static_cast<int>(wall_.triangles.size()); ++f) {
      const Triangle& t = wall_.triangles[f];
      const Triangle c{column_at(t[0], f), column_at(t[1], f), column_at(t[2], f)};
      LayerElement e{ElementKind::kTriangle, {c[0], c[1], c[2], -1}};
      for (int i = 0; i < 3; ++i)
        if (ridge_end[t[i]]) e.split_at = i;
      out_.elements.push_back(e);
      add_triangle(c, f);
    }
  }

  // Strips along the ridges: quads (L_a[j], L_a[j+1], L_b[j+1], L_b[j]); at a ridge end
  // (one side a single column P) the quad is the triangle (P, X, Y), X Y consecutive in
  // the fan.
  void add_strips() {
    for (int i = 0; i < static_cast<int>(ridges_.size()); ++i) {
      const Ridge& r = ridges_[i];
      const int m = slices_of_ridge(i);
      const std::vector<int> la = fan_across(r.a, r.t0, r.t1, m);
      const std::vector<int> lb = fan_across(r.b, r.t0, r.t1, m);
      for (int j = 0; j < m; ++j) {
        const std::array<int, 4> q{la[j], la[j + 1], lb[j + 1], lb[j]};
        // The corner patches ask for the edges between two columns of their own point.
        if (is_corner(r.a)) corner_edges_.push_back({q[0], q[1]});
        if (is_corner(r.b)) corner_edges_.push_back({q[2], q[3]});
        if (is_fan_[r.a] && is_fan_[r.b]) {
          out_.elements.push_back({ElementKind::kStrip, q});
          add_triangle({q[0], q[1], q[2]}, -1);
          add_triangle({q[0], q[2], q[3]}, -1);
          continue;
        }
        LayerElement e;
        e.kind = ElementKind::kStripEnd;
        if (is_fan_[r.a])  // triangle (P, la[j], la[j+1])
          e.column = {lb[0], la[j], la[j + 1], -1};
        else  // triangle (P, lb[j+1], lb[j])
          e.column = {la[0], lb[j + 1], lb[j], -1};
        out_.elements.push_back(e);
        add_triangle({e.column[0], e.column[1], e.column[2]}, -1);
      }
    }
  }

  // Corner patches: the loop of directions around the corner, closed around a centre.
  void add_corner_patches() {
    std::sort(corner_edges_.begin(), corner_edges_.end());
    for (int v = 0; v < nv_; ++v) {
      if (!is_corner(v)) continue;
      ++out_.n_corners;
      const int n_sectors = static_cast<int>(sectors_[v].first.size());
      std::vector<int> loop;
      const VertexFan& fan = fans_.fans[v];
      const int k = static_cast<int>(fan.triangles.size());
      for (int s = 0; s < n_sectors; ++s) {
        // The ridge between sector s and the next: the leading edge of the next one's
        // first triangle, between that triangle and the one before it (sector s).
        const int i = sectors_[v].first[(s + 1) % n_sectors];
        const int ridge = ridge_index_.find(v, fan.ring[i]);
        BLAYER_ASSERT(ridge >= 0);
        const int m = slices_of_ridge(ridge);
        const std::vector<int> l = fan_across(v, fan.triangles[(i + k - 1) % k], fan.triangles[i], m);
        loop.insert(loop.end(), l.begin(), l.end() - 1);
      }
      Vec3 sum{0.0, 0.0, 0.0};
      for (int c : loop) sum += out_.direction[c];
      const int centre = add_column(v, normalized(sum), true, true);
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const int x = loop[i], y = loop[(i + 1) % loop.size()];
        const bool strip_edge = std::binary_search(corner_edges_.begin(), corner_edges_.end(), std::make_pair(x, y));
        const Triangle t = strip_edge ? Triangle{centre, y, x} : Triangle{centre, x, y};
        out_.elements.push_back({ElementKind::kTriangle, {t[0], t[1], t[2], -1}});
        add_triangle(t, -1);
      }
    }
  }

  // The arrays grew by doubling; a layout lives through the whole march, where up to
  // half of each array would be idle capacity in the run's peak memory.
  ColumnLayout take() {
    out_.front.points.shrink_to_fit();
    out_.front.triangles.shrink_to_fit();
    out_.wall_point.shrink_to_fit();
    out_.wall_face.shrink_to_fit();
    out_.elements.shrink_to_fit();
    out_.element_of_triangle.shrink_to_fit();
    out_.direction.shrink_to_fit();
    out_.in_fan.shrink_to_fit();
    out_.faceless.shrink_to_fit();
    return std::move(out_);
  }

 private:
  int add_column(int v, const Vec3& d, bool fan, bool faceless) {
    out_.wall_point.push_back(v);
    out_.front.points.push_back(wall_.points[v]);
    out_.direction.push_back(d);
    out_.in_fan.push_back(fan);
    out_.faceless.push_back(faceless);
    return out_.n_columns() - 1;
  }

  void add_triangle(const Triangle& t, int wall_face) {
    out_.front.triangles.push_back(t);
    out_.wall_face.push_back(wall_face);
    out_.element_of_triangle.push_back(static_cast<int>(out_.elements.size()) - 1);
  }

  bool is_corner(int v) const { return is_fan_[v] && degree_[v] >= 3; }

  int slices_of_ridge(int ridge) { return chain_m_[chains_.find(ridge)]; }

  // The sector of triangle f at fan point v.
  int sector_at(int v, int f) const {
    const VertexFan& fan = fans_.fans[v];
    const auto it = std::find(fan.triangles.begin(), fan.triangles.end(), f);
    BLAYER_ASSERT(it != fan.triangles.end());
    return sectors_[v].sector_of[it - fan.triangles.begin()];
  }
  int column_at(int v, int f) const { return is_fan_[v] ? sectors_[v].column[sector_at(v, f)] : plain_column_[v]; }

  // The fan of point x across a ridge between sectors s0 and s1: [column(s0), the
  // interpolated ones, column(s1)]; shared by both ridge edges of a chain point. A
  // single point's "fan" is its one column, m + 1 times.
  std::vector<int> fan_across(int x, int f0, int f1, int m) {
    if (!is_fan_[x]) return std::vector<int>(m + 1, plain_column_[x]);
    const int s0 = sector_at(x, f0), s1 = sector_at(x, f1);
    const int lo = std::min(s0, s1), hi = std::max(s0, s1);
    std::vector<FanList>& lists = fan_lists_[x];
    auto it = std::find_if(lists.begin(), lists.end(), [&](const FanList& f) { return f.lo == lo && f.hi == hi; });
    if (it == lists.end()) {
      std::vector<int> list{sectors_[x].column[lo]};
      for (int j = 1; j < m; ++j)
        list.push_back(add_column(x, slerp(sector_dir_[x][lo], sector_dir_[x][hi], double(j) / m), true, true));
      list.push_back(sectors_[x].column[hi]);
      lists.push_back({lo, hi, std::move(list)});
      it = std::prev(lists.end());
    }
    std::vector<int> l = it->columns;
    if (s0 > s1) std::reverse(l.begin(), l.end());
    return l;
  }

  const TriSurface& wall_;
  const VertexFans& fans_;
  const FanParams p_;
  const NormalMethod method_;
  const int nv_;
  ColumnLayout out_;
  std::vector<Ridge> ridges_;
  RidgeIndex ridge_index_;  // ridge edge -> index in ridges_
  std::vector<char> is_fan_;
  std::vector<int> degree_, plain_column_;
  std::vector<Sectors> sectors_;
  std::vector<std::vector<Vec3>> sector_dir_;
  UnionFind chains_{0};                       // of ridge indices
  std::vector<int> chain_m_;                  // per chain root (a ridge index): its slices
  // Per point, the fans across its ridges (sectors lo < hi): a handful per point.
  struct FanList {
    int lo, hi;
    std::vector<int> columns;
  };
  std::vector<std::vector<FanList>> fan_lists_;
  // Directed edges of the strips between two columns of a corner point, sorted once the
  // strips are all in: the only strip edges the corner patches ask for.
  std::vector<std::pair<int, int>> corner_edges_;
};

}  // namespace

ColumnLayout build_column_layout(const TriSurface& wall, const VertexFans& fans, const FanParams& p,
                                 NormalMethod method, const std::vector<char>& excluded) {
  LayoutBuilder b(wall, fans, p, method);
  if (!b.select_ridges(excluded)) return single_column_layout(wall);
  b.add_point_columns();
  b.count_slices();
  b.add_wall_triangles();
  b.add_strips();
  b.add_corner_patches();
  return b.take();
}

}  // namespace blayer
