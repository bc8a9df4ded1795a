#include "blayer/extruder/front_checker.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

#include "blayer/extruder/filtered_orient3d.h"
#include "blayer/extruder/layer_cells.h"
#include "blayer/quality/cell_validity.h"
#include "parallel.h"

namespace blayer {

namespace {

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

void unit_normals(const std::vector<Triangle>& tris, const std::vector<Vec3>& P, std::vector<Vec3>* out) {
  out->resize(tris.size());
  tbb::parallel_for(0, static_cast<int>(tris.size()), [&](int i) {
    const Triangle& t = tris[i];
    (*out)[i] = normalized(cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]]));
  });
}

}  // namespace

FrontChecker::FrontChecker(const TriSurface& wall, const WallTopology& topo, bool check_collisions)
    : FrontChecker(wall, single_column_layout(wall), topo, check_collisions) {}

FrontChecker::FrontChecker(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo,
                           bool check_collisions)
    : triangles_(&wall.triangles),
      front_(layout.front.triangles),
      elements_(layout.elements),
      element_of_triangle_(layout.element_of_triangle),
      wall_point_(layout.wall_point),
      plane_(topo.plane),
      on_plane_(topo.on_plane),
      wall_points_(&wall.points),
      nv_(static_cast<int>(wall.points.size())),
      nc_(layout.n_columns()),
      nf_(static_cast<int>(wall.triangles.size())),
      nt_(static_cast<int>(layout.front.triangles.size())),
      ne_(static_cast<int>(layout.elements.size())),
      check_collisions_(check_collisions) {
  std::vector<Box> wall_boxes(nf_);
  tbb::parallel_for(0, nf_, [&](int f) {
    const Triangle& t = wall.triangles[f];
    wall_boxes[f] = Box::of_triangle(wall.points[t[0]], wall.points[t[1]], wall.points[t[2]]);
  });
  wall_tree_.build(wall_boxes);
  unit_normals(wall.triangles, wall.points, &wall_normal_);
  if (nt_ == nf_ && front_ == wall.triangles) {
    cur_tree_ = wall_tree_;
  } else {
    std::vector<Box> front_boxes(nt_);
    const std::vector<Vec3>& P = layout.front.points;
    tbb::parallel_for(0, nt_, [&](int f) {
      const Triangle& t = front_[f];
      front_boxes[f] = Box::of_triangle(P[t[0]], P[t[1]], P[t[2]]);
    });
    cur_tree_.build(front_boxes);
  }
  new_tree_ = cur_tree_;
  cur_boxes_.resize(nt_);
  new_boxes_.resize(nt_);
  grows_.assign(nc_, 0);
  prev_grows_.assign(nc_, 0);
  moved_.assign(nc_, 0);
  prev_next_.resize(nc_);
  for (auto* v : {&bad_cell_, &elem_moved_}) v->assign(ne_, 0);
  for (auto* v : {&collided_, &tri_moved_, &tri_grows_, &query_}) v->assign(nt_, 0);
  wall_tris_.resize(nf_);
  cur_tris_.resize(nt_);
  new_tris_.resize(nt_);
  cur_is_wall_.assign(nt_, 0);
  if (check_collisions_) {
    soup_.resize(static_cast<std::size_t>(nv_) + 2 * static_cast<std::size_t>(nc_));
    std::copy(wall.points.begin(), wall.points.end(), soup_.begin());
    tbb::parallel_for(0, nf_, [&](int f) {
      const Triangle& t = wall.triangles[f];
      wall_tris_[f] = {t[0], t[1], t[2]};
    });
  }
}

ProximityRays FrontChecker::wall_rays() const {
  ProximityRays r;
  r.triangles = triangles_;
  r.front_triangles = &front_;
  r.wall_point = &wall_point_;
  r.wall_points = wall_points_;
  r.wall_tree = &wall_tree_;
  r.wall_normal = &wall_normal_;
  if (plane_) {
    r.plane = &*plane_;
    r.on_plane = &on_plane_;
  }
  return r;
}

ProximityRays FrontChecker::front_rays() const {
  ProximityRays r = wall_rays();
  if (k_ > 0) {
    r.front_points = cur_points_;
    r.front_tree = &cur_tree_;
    r.front_normal = &cur_normal_;
  }
  return r;
}

namespace {

bool names_a_point_twice(const IndexedTriangle& t) { return t[0] == t[1] || t[1] == t[2] || t[2] == t[0]; }

}  // namespace

void FrontChecker::begin_layer(int k, const std::vector<Vec3>& top, const std::vector<int>& layers) {
  k_ = k;
  cur_points_ = &top;
  layers_ = &layers;
  if (k > 0) {
    tbb::parallel_for(0, nt_, [&](int f) {
      const Triangle& t = front_[f];
      cur_boxes_[f] = Box::of_triangle(top[t[0]], top[t[1]], top[t[2]]);
    });
    cur_tree_.refit(cur_boxes_);
    unit_normals(front_, top, &cur_normal_);
  }
  if (check_collisions_) {
    std::copy(top.begin(), top.end(), soup_.begin() + nv_);
    if (k > 0) {
      tbb::parallel_for(0, nt_, [&](int f) {
        const Triangle& t = front_[f];
        cur_tris_[f] = {cur_id(t[0]), cur_id(t[1]), cur_id(t[2])};
        cur_is_wall_[f] = (layers[t[0]] == 0 && layers[t[1]] == 0 && layers[t[2]] == 0) ||
                          names_a_point_twice(cur_tris_[f]);
      });
    }
  }
  std::fill(bad_cell_.begin(), bad_cell_.end(), 0);
  std::fill(collided_.begin(), collided_.end(), 0);
}

Box FrontChecker::soup_box(const IndexedTriangle& t) const {
  return Box::of_triangle(soup_[t[0]], soup_[t[1]], soup_[t[2]]);
}

void FrontChecker::check_cells(const std::vector<Vec3>& top, const std::vector<Vec3>& next) {
  const std::int64_t n_cur = static_cast<std::int64_t>(nv_) + nc_;
  auto position = [&](std::int64_t id) -> const Vec3& {
    if (id < nv_) return (*wall_points_)[id];
    if (id < n_cur) return top[id - nv_];
    return next[id - n_cur];
  };
  tbb::parallel_for(0, ne_, [&](int e) {
    if (!elem_moved_[e]) return;
    const LayerElement& el = elements_[e];
    const int n = el.kind == ElementKind::kStrip ? 4 : 3;
    std::array<std::int64_t, 4> bottom{}, up{};
    std::array<bool, 4> g{};
    for (int i = 0; i < n; ++i) {
      const int c = el.column[i];
      bottom[i] = cur_id(c);
      up[i] = n_cur + c;
      g[i] = grows_[c];
    }
    LayerCell cells[2];
    bad_cell_[e] = 0;
    const int n_cells = element_layer_cells(el, bottom, up, g, cells);
    for (int i_c = 0; i_c < n_cells; ++i_c) {
      Vec3 corners[8];
      for (int i = 0; i < corner_count(cells[i_c].type); ++i) corners[i] = position(cells[i_c].nodes[i]);
      if (!cell_is_valid(cells[i_c].type, corners)) bad_cell_[e] = 1;
    }
  });
}

void FrontChecker::check_intersections(const std::vector<Vec3>& next) {
  const std::int64_t n_cur = static_cast<std::int64_t>(nv_) + nc_;
  auto new_id = [&](int c) -> std::int64_t { return grows_[c] ? n_cur + c : cur_id(c); };
  std::copy(next.begin(), next.end(), soup_.begin() + n_cur);
  tbb::parallel_for(0, nt_, [&](int f) {
    const Triangle& t = front_[f];
    new_tris_[f] = {new_id(t[0]), new_id(t[1]), new_id(t[2])};
    new_boxes_[f] = soup_box(new_tris_[f]);
    // A triangle naming a point twice is no triangle: it is neither tested nor a partner.
    if (names_a_point_twice(new_tris_[f])) tri_grows_[f] = 0;
    query_[f] = tri_grows_[f] && (tri_moved_[f] || collided_[f]);
    if (query_[f] || !tri_grows_[f]) collided_[f] = 0;
  });
  new_tree_.refit(new_boxes_);
  for (auto& l : partner_hits_) l.clear();
  tbb::parallel_for(tbb::blocked_range<int>(0, nt_), [&](const tbb::blocked_range<int>& r) {
    std::vector<int>& partners = partner_hits_.local();
    for (int f = r.begin(); f != r.end(); ++f) {
      if (!query_[f]) continue;
      const IndexedTriangle& s = new_tris_[f];
      const Box& b = new_boxes_[f];
      bool hit = false;
      wall_tree_.for_each_overlap(b, [&](int j) {
        if (!hit && soup_triangles_intersect(soup_, s, wall_tris_[j])) hit = true;
      });
      if (k_ > 0)
        cur_tree_.for_each_overlap(b, [&](int j) {
          if (!hit && !cur_is_wall_[j] && soup_triangles_intersect(soup_, s, cur_tris_[j])) hit = true;
        });
      // A pair of new triangles is tested once: from the smaller id if both are tested
      // in this attempt, else from the one that is.
      new_tree_.for_each_overlap(b, [&](int j) {
        if (j == f || !tri_grows_[j] || (query_[j] && j < f)) return;
        if (soup_triangles_intersect(soup_, s, new_tris_[j])) {
          hit = true;
          partners.push_back(j);
        }
      });
      if (hit) collided_[f] = 1;
    }
  });
  for (const auto& l : partner_hits_)
    for (int j : l) collided_[j] = 1;
}

void FrontChecker::check(int attempt, const std::vector<Vec3>& top, const std::vector<Vec3>& next,
                         const std::vector<char>& grows, FrontVerdict* out) {
  grows_ = grows;
  parallel_vertices(nc_, [&](int v) {
    moved_[v] = attempt == 0 || grows_[v] != prev_grows_[v] || !(next[v] == prev_next_[v]);
  });
  prev_next_ = next;
  prev_grows_ = grows_;
  tbb::parallel_for(0, nt_, [&](int f) {
    const Triangle& t = front_[f];
    tri_moved_[f] = moved_[t[0]] || moved_[t[1]] || moved_[t[2]];
    tri_grows_[f] = grows_[t[0]] || grows_[t[1]] || grows_[t[2]];
  });
  tbb::parallel_for(0, ne_, [&](int e) {
    const LayerElement& el = elements_[e];
    const int n = el.kind == ElementKind::kStrip ? 4 : 3;
    bool m = false;
    for (int i = 0; i < n; ++i) m = m || moved_[el.column[i]];
    elem_moved_[e] = m;
  });
  check_cells(top, next);
  if (check_collisions_) check_intersections(next);
  if (plane_) check_symmetry_side(next);

  out->bad.assign(nc_, 0);
  out->reason.assign(nc_, StopReason::kNone);
  out->bad_triangle.assign(nt_, 0);
  out->any_bad = false;
  for (int e = 0; e < ne_; ++e) {
    if (!bad_cell_[e]) continue;
    const LayerElement& el = elements_[e];
    for (int i = 0; i < (el.kind == ElementKind::kStrip ? 4 : 3); ++i) {
      const int v = el.column[i];
      if (grows_[v]) {
        out->bad[v] = 1;
        out->reason[v] = StopReason::kQuality;
      }
    }
  }
  for (int f = 0; f < nt_; ++f) {
    const bool crossing = collided_[f] || (!side_bad_.empty() && side_bad_[f]);
    out->bad_triangle[f] = bad_cell_[element_of_triangle_[f]] || crossing;
    if (crossing)
      for (int v : front_[f])
        if (grows_[v]) {
          out->bad[v] = 1;
          if (out->reason[v] == StopReason::kNone) out->reason[v] = StopReason::kCollision;
        }
  }
  out->any_bad = std::find(out->bad.begin(), out->bad.end(), 1) != out->bad.end();
}

void FrontChecker::check_symmetry_side(const std::vector<Vec3>& next) {
  // A triangle whose points all lie on the model's side (or in the plane, for the
  // columns on it) lies there too: the half space is convex.
  side_bad_.assign(nt_, 0);
  tbb::parallel_for(0, nt_, [&](int f) {
    if (!tri_grows_[f]) return;
    for (int v : front_[f])
      if (grows_[v] && !on_plane_[v] && !(plane_->signed_distance(next[v]) > 0.0)) side_bad_[f] = 1;
  });
}

void FrontChecker::release() {
  auto release = [](auto& x) { x = std::decay_t<decltype(x)>(); };
  release(soup_);
  release(wall_tris_);
  release(cur_tris_);
  release(new_tris_);
  release(cur_boxes_);
  release(new_boxes_);
  release(cur_normal_);
  release(wall_tree_);
  release(cur_tree_);
  release(new_tree_);
  release(prev_next_);
}

}  // namespace blayer
