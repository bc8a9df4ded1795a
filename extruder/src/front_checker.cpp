#include "blayer/extruder/front_checker.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <climits>
#include <optional>

#include "blayer/core/assert.h"
#include "blayer/core/edge_topology.h"
#include "blayer/core/volume_mesh.h"
#include "blayer/extruder/layer_cells.h"
#include "blayer/quality/solver_acceptance.h"
#include "parallel.h"

namespace blayer {

namespace {

// The faces of triangle t's cell in one layer, each oriented out of the cell: [0] the
// bottom (the front triangle seen from below), [1] the top, then the side face over
// each wall edge (t0,t1), (t1,t2), (t2,t0) one of whose columns grows: (p_i, p_j,
// p_j', p_i') without the tops of columns that do not grow. `lo` holds the columns'
// points at the layer's base, `hi` their new points (read only where g is set). For a
// wall triangle whose right-hand normal points into the fluid, these are the faces of
// layer_cell's wedge, pyramid or tet.
struct LayerCellFaces {
  int n = 0;          // 0 when no column grows
  PolyFace face[5];
  int edge[5];        // wall edge of each face, -1 for the caps
};

LayerCellFaces layer_cell_faces(const Triangle& t, const std::vector<Vec3>& lo, const std::vector<Vec3>& hi,
                                const std::array<bool, 3>& g) {
  LayerCellFaces c;
  if (!g[0] && !g[1] && !g[2]) return c;
  auto up = [&](int i) -> const Vec3& { return g[i] ? hi[t[i]] : lo[t[i]]; };
  c.face[0] = {3, {lo[t[0]], lo[t[2]], lo[t[1]]}};
  c.face[1] = {3, {up(0), up(1), up(2)}};
  c.edge[0] = c.edge[1] = -1;
  c.n = 2;
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = (e + 1) % 3;
    if (!g[i] && !g[j]) continue;
    PolyFace& f = c.face[c.n];
    f.n = 0;
    f.p[f.n++] = lo[t[i]];
    f.p[f.n++] = lo[t[j]];
    if (g[j]) f.p[f.n++] = hi[t[j]];
    if (g[i]) f.p[f.n++] = hi[t[i]];
    c.edge[c.n++] = e;
  }
  return c;
}

Vec3 layer_cell_centre(const LayerCellFaces& c, FaceGeometry* geo) {
  for (int i = 0; i < c.n; ++i) geo[i] = face_geometry(c.face[i]);
  return cell_geometry(geo, c.n).centre;
}

// f(i) in parallel for the listed indices, or for every index in [0, n).
template <class F>
void for_listed_or_all(bool listed, const std::vector<int>& list, int n, F&& f) {
  if (listed)
    tbb::parallel_for(std::size_t(0), list.size(), [&](std::size_t k) { f(list[k]); });
  else
    tbb::parallel_for(0, n, f);
}

// Clears the flags of the listed indices, or all of them, and the list.
void clear_flags(bool listed, std::vector<int>* list, std::vector<char>* flags) {
  if (listed)
    for (int i : *list) (*flags)[i] = 0;
  else
    std::fill(flags->begin(), flags->end(), 0);
  list->clear();
}

// Whether every column of an element is a corner of one of its front triangles
// (fan_layout.h: a strip's two triangles, else the element's own): a moved column then
// always moves a triangle of each of its elements, and the elements of the moved
// triangles are all the moved ones.
bool elements_covered_by_their_triangles(const ColumnLayout& layout) {
  std::vector<unsigned char> covered(layout.elements.size(), 0);
  for (std::size_t f = 0; f < layout.front.triangles.size(); ++f) {
    const LayerElement& el = layout.elements[layout.element_of_triangle[f]];
    for (int c : layout.front.triangles[f])
      for (int i = 0; i < el.n_columns(); ++i)
        if (el.column[i] == c) covered[layout.element_of_triangle[f]] |= 1 << i;
  }
  for (std::size_t e = 0; e < layout.elements.size(); ++e)
    if (covered[e] != (1 << layout.elements[e].n_columns()) - 1) return false;
  return true;
}

}  // namespace

FrontChecker::FrontChecker(const TriSurface& wall, const WallTopology& topo, const ExtrusionParams& params)
    : FrontChecker(wall, std::make_shared<const ColumnLayout>(single_column_layout(wall)), topo, params) {}

FrontChecker::FrontChecker(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo,
                           const ExtrusionParams& params, const WallTree* wall_tree)
    : FrontChecker(wall, std::make_shared<const ColumnLayout>(layout), topo, params, wall_tree) {}

FrontChecker::FrontChecker(const TriSurface& wall, std::shared_ptr<const ColumnLayout> layout_ptr,
                           const WallTopology& topo, const ExtrusionParams& params, const WallTree* wall_tree)
    : FrontChecker(wall, std::move(layout_ptr), topo, params.check_collisions, wall_tree) {
  const ColumnLayout& layout = *layout_;
  if (!params.solver_limits.any()) return;
  // The acceptance passes judge the cells of the wall triangles, which are the first
  // front triangles, on their columns (fan_layout.h's contract).
  for (int f = 0; f < nf_; ++f)
    BLAYER_ASSERT_MSG(layout.wall_face[f] == f && elements_[f].kind == ElementKind::kTriangle,
                      "a layout's front starts with the wall triangles");
  limits_ = params.solver_limits;
  acc_tris_.assign(front_.begin(), front_.begin() + nf_);
  build_edge_neighbours(wall, layout);
  centre_.resize(nf_);
  below_centre_.resize(nf_);
  cap_bad_.assign(nf_, 0);
  side_face_bad_.assign(3 * static_cast<std::size_t>(nf_), 0);
  side_geo_.resize(3 * static_cast<std::size_t>(nf_));
  acc_listed_.assign(nf_, 0);
}

// The wall triangle across each edge of a wall triangle's cell (core/edge_topology.h on
// the wall triangles over their columns): the other use of a manifold edge; -1 on an
// open wall edge; -2 where the cell across is not a wall triangle's (a fan strip beside
// a ridge edge), is not judged (a wall triangle split at a ridge end) or the edge is
// non-manifold or inconsistently oriented.
void FrontChecker::build_edge_neighbours(const TriSurface& wall, const ColumnLayout& layout) {
  const std::vector<Triangle>& tris = acc_tris_;
  auto slot_of = [&](int f, int lo, int hi) {
    for (int e = 0; e < 3; ++e) {
      const int a = tris[f][e], b = tris[f][(e + 1) % 3];
      if (std::min(a, b) == lo && std::max(a, b) == hi) return 3 * f + e;
    }
    return -1;
  };
  edge_neighbour_.assign(3 * static_cast<std::size_t>(nf_), -2);
  side_non_orth_limit_.assign(edge_neighbour_.size(), limits_.max_non_orthogonality_deg);
  side_slot_.resize(edge_neighbour_.size());
  for (std::size_t i = 0; i < side_slot_.size(); ++i) side_slot_[i] = static_cast<int>(i);
  skip_acceptance_.assign(nf_, 0);
  for (int f = 0; f < nf_; ++f) skip_acceptance_[f] = elements_[f].split_at >= 0;
  std::vector<char> open_wall_edge(3 * static_cast<std::size_t>(nf_), 0);
  const EdgeTopology wall_edges = build_edge_topology(wall);
  for (const SurfaceEdge& edge : wall_edges.edges)
    if (edge.kind == EdgeKind::kBoundary)
      for (int e = 0; e < 3; ++e) {
        const Triangle& t = wall.triangles[edge.triangle[0]];
        if (std::min(t[e], t[(e + 1) % 3]) == edge.lo && std::max(t[e], t[(e + 1) % 3]) == edge.hi)
          open_wall_edge[3 * edge.triangle[0] + e] = 1;
      }
  // Without fans the cells' triangles are the wall's, on the same point ids.
  std::optional<EdgeTopology> own;
  if (acc_tris_ != wall.triangles) own = build_edge_topology(TriSurface{layout.front.points, acc_tris_});
  const std::vector<SurfaceEdge>& edges = own ? own->edges : wall_edges.edges;
  // Each triangle's edge slot belongs to one edge: the edges write apart.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, edges.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const SurfaceEdge& edge = edges[i];
      const int f = edge.triangle[0], g = edge.triangle[1];
      const int sf = slot_of(f, edge.lo, edge.hi);
      if (edge.kind == EdgeKind::kBoundary && open_wall_edge[sf]) edge_neighbour_[sf] = -1;
      if (edge.kind != EdgeKind::kManifold || skip_acceptance_[f] || skip_acceptance_[g]) continue;
      const int sg = slot_of(g, edge.lo, edge.hi);
      edge_neighbour_[sf] = g;
      edge_neighbour_[sg] = f;
      side_slot_[sf] = side_slot_[sg] = std::min(sf, sg);  // the smaller triangle's
      if (!(limits_.max_non_orthogonality_deg > 0.0)) continue;
      // The angle is the same whichever triangle comes first (normal and centre line
      // flip together).
      auto corners = [&](int t) {
        const Triangle& w = wall.triangles[t];
        return std::array<Vec3, 3>{wall.points[w[0]], wall.points[w[1]], wall.points[w[2]]};
      };
      const double inherited = wall_edge_non_orthogonality_deg(corners(f), corners(g), layout.front.points[edge.lo],
                                                               layout.front.points[edge.hi]);
      side_non_orth_limit_[std::min(sf, sg)] =
          inherited_non_orthogonality_limit_deg(limits_.max_non_orthogonality_deg, inherited);
    }
  });
}

FrontChecker::FrontChecker(const TriSurface& wall, const WallTopology& topo, bool check_collisions)
    : FrontChecker(wall, std::make_shared<const ColumnLayout>(single_column_layout(wall)), topo, check_collisions) {}

FrontChecker::FrontChecker(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo,
                           bool check_collisions, const WallTree* wall_tree)
    : FrontChecker(wall, std::make_shared<const ColumnLayout>(layout), topo, check_collisions, wall_tree) {}

FrontChecker::FrontChecker(const TriSurface& wall, std::shared_ptr<const ColumnLayout> layout_ptr,
                           const WallTopology& topo, bool check_collisions, const WallTree* wall_tree)
    : triangles_(&wall.triangles),
      layout_(std::move(layout_ptr)),
      front_(layout_->front.triangles),
      elements_(layout_->elements),
      element_of_triangle_(layout_->element_of_triangle),
      wall_point_(layout_->wall_point),
      plane_(topo.plane),
      on_plane_(topo.on_plane),
      wall_points_(&wall.points),
      nv_(static_cast<int>(wall.points.size())),
      nc_(layout_->n_columns()),
      nf_(static_cast<int>(wall.triangles.size())),
      nt_(static_cast<int>(layout_->front.triangles.size())),
      ne_(static_cast<int>(layout_->elements.size())),
      check_collisions_(check_collisions) {
  if (!wall_tree) {
    own_wall_ = std::make_unique<WallTree>(wall);
    wall_tree = own_wall_.get();
  }
  wall_ = wall_tree;
  if (nt_ == nf_ && front_ == wall.triangles) {
    cur_tree_ = wall_->tree;
  } else {
    const std::vector<Vec3>& P = layout_->front.points;
    auto corners = [&](int f, Vec3* c) {
      for (int i = 0; i < 3; ++i) c[i] = P[front_[f][i]];
    };
    if (front_starts_with_wall(wall)) {
      // The fans' strips and split triangles get a tree of their own under the wall's.
      TriangleBvh extra;
      extra.build_triangles(nt_ - nf_, [&](int i, Vec3* c) { corners(nf_ + i, c); });
      cur_tree_.join(wall_->tree, extra);
    } else {
      cur_tree_.build_triangles(nt_, corners);
    }
  }
  new_tree_ = cur_tree_;
  grows_.assign(nc_, 0);
  prev_grows_.assign(nc_, 0);
  prev_next_.resize(nc_);
  column_triangles_ = vertex_triangles(layout_->front);
  BLAYER_ASSERT_MSG(elements_covered_by_their_triangles(*layout_),
                    "every element's columns are those of its front triangles");
  for (auto* v : {&bad_cell_, &invalid_, &elem_moved_}) v->assign(ne_, 0);
  for (auto* v : {&collided_, &tri_moved_, &tri_grows_, &query_}) v->assign(nt_, 0);
  star_apart_.assign(nc_, 0);
  if (check_collisions_) order_star_rings();
  wall_tris_.resize(nf_);
  cur_tris_.resize(nt_);
  new_tris_.resize(nt_);
  cur_is_wall_.assign(nt_, 0);
  if (check_collisions_) {
    tree_index_ = new_tree_.layout_index();
    soup_.resize(static_cast<std::size_t>(nv_) + 2 * static_cast<std::size_t>(nc_));
    // Its tables hold 32-bit ids (SoupTriangle): refused like a mesh of as many points.
    require_indexable_points(soup_.size(), "the collision check's points (wall, current and next front)");
    std::copy(wall.points.begin(), wall.points.end(), soup_.begin());
    tbb::parallel_for(0, nf_, [&](int f) {
      const Triangle& t = wall.triangles[f];
      wall_tris_[f] = {t[0], t[1], t[2]};
    });
  }
}

bool FrontChecker::front_starts_with_wall(const TriSurface& wall) const {
  if (nt_ < nf_) return false;
  const std::vector<Vec3>& P = layout_->front.points;
  std::atomic<bool> same{true};
  tbb::parallel_for(tbb::blocked_range<int>(0, nf_), [&](const tbb::blocked_range<int>& r) {
    for (int f = r.begin(); f != r.end() && same.load(std::memory_order_relaxed); ++f)
      for (int i = 0; i < 3; ++i)
        if (!same_bits(P[front_[f][i]], wall.points[wall.triangles[f][i]])) same = false;
  });
  return same;
}

ProximityRays FrontChecker::wall_rays() const {
  return wall_proximity_rays(*triangles_, *wall_points_, *wall_, &front_, &wall_point_, plane_, &on_plane_);
}

ProximityRays FrontChecker::front_rays() const {
  ProximityRays r = wall_rays();
  if (k_ > 0) {
    r.front_points = cur_points_;
    r.front_tree = &cur_tree_;
    r.front_normal = &cur_normal_;
    r.front_normal_boxes = &cur_normal_boxes_;
  }
  return r;
}

void FrontChecker::begin_layer(int k, const std::vector<Vec3>& top, const std::vector<int>& layers) {
  k_ = k;
  cur_points_ = &top;
  layers_ = &layers;
  if (k > 0) {
    // Layer k - 1's last attempt is normally what was committed: its new front's tree
    // (boxes and slabs) is then this layer's current front, copied rather than refitted.
    if (check_collisions_ && new_tree_layer_ == k - 1 && last_attempt_committed(k, top, layers))
      cur_tree_ = new_tree_;
    else
      cur_tree_.refit_triangles([&](int f, Vec3* c) {
        for (int i = 0; i < 3; ++i) c[i] = top[front_[f][i]];
      });
    unit_triangle_normals(front_, top, &cur_normal_);
    cur_tree_.node_value_boxes([&](int f) { return cur_normal_[f]; }, &cur_normal_boxes_);
  }
  if (check_collisions_) {
    std::copy(top.begin(), top.end(), soup_.begin() + nv_);
    if (k > 0) {
      tbb::parallel_for(0, nt_, [&](int f) {
        const Triangle& t = front_[f];
        cur_tris_[f] = {soup_id(cur_id(t[0])), soup_id(cur_id(t[1])), soup_id(cur_id(t[2]))};
        cur_is_wall_[f] = (layers[t[0]] == 0 && layers[t[1]] == 0 && layers[t[2]] == 0) ||
                          names_a_point_twice(cur_tris_[f]);
      });
    }
  }
  std::fill(bad_cell_.begin(), bad_cell_.end(), 0);
  std::fill(invalid_.begin(), invalid_.end(), 0);
  std::fill(collided_.begin(), collided_.end(), 0);
  collided_list_.clear();
  if (limits_.any()) {
    below_known_ = k > 0 && previous_layer_ == k - 1;
    if (below_known_) cells_below(k, top, layers);
    previous_bottom_ = top;
    previous_layer_ = k;
  }
}

bool FrontChecker::last_attempt_committed(int k, const std::vector<Vec3>& top, const std::vector<int>& layers) const {
  for (int v = 0; v < nc_; ++v) {
    const bool grew = layers[v] >= k;
    if (grew != bool(prev_grows_[v]) || (grew && !(top[v] == prev_next_[v]))) return false;
  }
  return true;
}

// Centres of the cells of layer k - 1: from the front at its start to `top`, grown
// where a column has k layers.
void FrontChecker::cells_below(int k, const std::vector<Vec3>& top, const std::vector<int>& layers) {
  // The last attempt of layer k - 1 is normally what was committed; its centres are
  // then the ones wanted.
  if (last_attempt_committed(k, top, layers)) {
    below_centre_.swap(centre_);
    return;
  }
  const std::vector<Triangle>& tris = acc_tris_;
  tbb::parallel_for(0, nf_, [&](int f) {
    const Triangle& t = tris[f];
    const std::array<bool, 3> g = {layers[t[0]] >= k, layers[t[1]] >= k, layers[t[2]] >= k};
    const LayerCellFaces c = layer_cell_faces(t, previous_bottom_, top, g);
    FaceGeometry geo[5];
    if (c.n) below_centre_[f] = layer_cell_centre(c, geo);
  });
}

void FrontChecker::check_cells(const std::vector<Vec3>& top, const std::vector<Vec3>& next) {
  const std::int64_t n_cur = static_cast<std::int64_t>(nv_) + nc_;
  auto position = [&](std::int64_t id) -> const Vec3& {
    if (id < nv_) return (*wall_points_)[id];
    if (id < n_cur) return top[id - nv_];
    return next[id - n_cur];
  };
  for_listed_or_all(listed_, elem_list_, ne_, [&](int e) {
    if (!elem_moved_[e]) return;
    LayerCell cells[2];
    invalid_[e] = 0;
    const int n_cells = element_layer_cells(
        elements_[e], [&](int c) { return cur_id(c); }, [&](int c) { return n_cur + c; },
        [&](int c) { return grows_[c] != 0; }, cells);
    for (int i_c = 0; i_c < n_cells; ++i_c) {
      Vec3 corners[8];
      for (int i = 0; i < corner_count(cells[i_c].type); ++i) corners[i] = position(cells[i_c].nodes[i]);
      if (!layer_cell_accepted(elements_[e], cells[i_c], corners)) invalid_[e] = 1;
    }
  });
  if (limits_.any()) {
    check_acceptance(top, next);
    return;
  }
  if (!listed_) {
    std::copy(invalid_.begin(), invalid_.end(), bad_cell_.begin());
    return;
  }
  for (int e : elem_list_) bad_cell_[e] = invalid_[e];
}

// The solver-acceptance verdicts (see the header), in three passes: the centre of every
// moved cell and the verdict on its caps; the side faces, each by its owner, re-judged
// when a column of either cell moved; each cell's verdict from its caps, its side faces
// and the exact test.
void FrontChecker::check_acceptance(const std::vector<Vec3>& top, const std::vector<Vec3>& next) {
  const std::vector<Triangle>& tris = acc_tris_;
  auto growing = [&](const Triangle& t) -> std::array<bool, 3> {
    return {bool(grows_[t[0]]), bool(grows_[t[1]]), bool(grows_[t[2]])};
  };
  const FaceSide bottom_side = k_ == 0 ? FaceSide::kBoundary : below_known_ ? FaceSide::kInternal : FaceSide::kUnknown;
  for_listed_or_all(listed_, tri_list_, nf_, [&](int f) {
    if (f >= nf_ || !tri_moved_[f]) return;
    const Triangle& t = tris[f];
    const LayerCellFaces c = layer_cell_faces(t, top, next, growing(t));
    cap_bad_[f] = 0;
    if (!c.n || skip_acceptance_[f]) return;
    FaceGeometry geo[5];
    centre_[f] = layer_cell_centre(c, geo);
    for (int i = 2; i < c.n; ++i) side_geo_[3 * f + c.edge[i]] = geo[i];
    if (invalid_[f]) return;
    cap_bad_[f] =
        judge_face(c.face[0], geo[0], centre_[f], bottom_side, below_centre_[f], limits_) != AcceptanceFailure::kNone ||
        judge_face(c.face[1], geo[1], centre_[f], FaceSide::kBoundary, centre_[f], limits_) != AcceptanceFailure::kNone;
  });
  if (listed_) list_acceptance_triangles();
  for_listed_or_all(listed_, acc_list_, nf_, [&](int f) {
    const int* nb = &edge_neighbour_[3 * f];
    bool dirty = tri_moved_[f];
    for (int e = 0; e < 3; ++e) dirty = dirty || (nb[e] >= 0 && tri_moved_[nb[e]]);
    if (!dirty || skip_acceptance_[f]) return;
    const Triangle& t = tris[f];
    const LayerCellFaces c = layer_cell_faces(t, top, next, growing(t));
    for (int e = 0; e < 3; ++e) {
      const int slot = 3 * f + e, g = nb[e];
      if (side_slot_[slot] != slot || !(tri_moved_[f] || (g >= 0 && tri_moved_[g]))) continue;
      side_face_bad_[slot] = 0;
      int i = 2;
      while (i < c.n && c.edge[i] != e) ++i;
      if (i >= c.n || invalid_[f] || (g >= 0 && invalid_[g])) continue;
      const FaceGeometry& geo = side_geo_[slot];
      const FaceSide side = g == -1 ? FaceSide::kBoundary : g == -2 ? FaceSide::kUnknown : FaceSide::kInternal;
      const Vec3& other = g >= 0 ? centre_[g] : centre_[f];
      AcceptanceLimits limits = limits_;
      limits.max_non_orthogonality_deg = side_non_orth_limit_[slot];
      side_face_bad_[slot] = judge_face(c.face[i], geo, centre_[f], side, other, limits) != AcceptanceFailure::kNone;
    }
  });
  for_listed_or_all(listed_, acc_list_, nf_, [&](int f) {
    const int* slot = &side_slot_[3 * f];
    bad_cell_[f] = invalid_[f] || cap_bad_[f] || side_face_bad_[slot[0]] || side_face_bad_[slot[1]] ||
                   side_face_bad_[slot[2]];
  });
  // Fan strips and corner patches: the exact test only.
  if (!listed_) {
    std::copy(invalid_.begin() + nf_, invalid_.end(), bad_cell_.begin() + nf_);
    return;
  }
  for (int e : elem_list_)
    if (e >= nf_) bad_cell_[e] = invalid_[e];
  for (int f : acc_list_) acc_listed_[f] = 0;
}

// A side face's verdict changes only when a column of either of its cells moved, a
// cap's or cell's only when its own did (wall triangle f's cell is element f, on the
// same columns).
void FrontChecker::list_acceptance_triangles() {
  acc_list_.clear();
  auto add = [&](int f) {
    if (acc_listed_[f]) return;
    acc_listed_[f] = 1;
    acc_list_.push_back(f);
  };
  for (int f : tri_list_) {
    if (f >= nf_) continue;
    add(f);
    for (int e = 0; e < 3; ++e)
      if (edge_neighbour_[3 * f + e] >= 0) add(edge_neighbour_[3 * f + e]);
  }
}

// Inline: as a call from the pair traversal's loop it made the perforated block's checks
// without fans 19 % slower than with no certificate at all.
inline bool FrontChecker::shares_only_a_certified_centre(const SoupTriangle& s, const SoupTriangle& t,
                                                         std::int64_t n_cur) const {
  int n_shared = 0;
  std::int64_t shared = -1;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s[i] == t[j]) {
        ++n_shared;
        shared = s[i];
      }
  return n_shared == 1 && shared >= n_cur && star_apart_[shared - n_cur];
}

void FrontChecker::check_intersections(const std::vector<Vec3>& next) {
  const std::int64_t n_cur = static_cast<std::int64_t>(nv_) + nc_;
  auto new_id = [&](int c) -> std::int64_t { return grows_[c] ? n_cur + c : cur_id(c); };
  if (listed_) {
    for (int v : moved_list_) soup_[n_cur + v] = next[v];
  } else {
    std::copy(next.begin(), next.end(), soup_.begin() + n_cur);
  }
  for_listed_or_all(listed_, tri_list_, nt_, [&](int f) {
    const Triangle& t = front_[f];
    new_tris_[f] = {soup_id(new_id(t[0])), soup_id(new_id(t[1])), soup_id(new_id(t[2]))};
    // A triangle naming a point twice is no triangle: it is neither tested nor a partner.
    if (names_a_point_twice(new_tris_[f])) tri_grows_[f] = 0;
  });
  // The queried triangles: those that grow and moved or crossed in the attempt before.
  // The crossings are then cleared (every crossed triangle is either queried or no
  // longer grows) and found again.
  auto queried = [&](int f) {
    const bool q = tri_grows_[f] && (tri_moved_[f] || collided_[f]);
    if (q || !tri_grows_[f]) collided_[f] = 0;
    return q;
  };
  if (listed_) {
    clear_flags(query_listed_, &query_list_, &query_);
    auto list_query = [&](int f) {
      if (query_[f] || !queried(f)) return;
      query_[f] = 1;
      query_list_.push_back(f);
    };
    for (int f : tri_list_) list_query(f);
    for (int f : collided_list_) list_query(f);
  } else {
    tbb::parallel_for(0, nt_, [&](int f) { query_[f] = queried(f); });
  }
  query_listed_ = listed_;
  collided_list_.clear();
  certify_stars(n_cur);
  // With the slabs: the trees skip the pairs whose slabs are apart (diagonal_slabs.h).
  // Only the triangles that moved since the layer's previous attempt (all in its first).
  auto corners = [&](int f, Vec3* c) {
    for (int i = 0; i < 3; ++i) c[i] = soup_[new_tris_[f][i]];
  };
  if (listed_ && new_tree_layer_ == k_)
    new_tree_.refit_triangles_listed(tri_list_, tree_index_, corners);
  else
    new_tree_.refit_triangles_where(new_tree_layer_ == k_ ? &tri_moved_ : nullptr, corners);
  new_tree_layer_ = k_;
  for (auto& l : crossing_) l.clear();
  // Every pair is found by descending two trees together (TriangleBvh): the new front
  // against the wall and the current front for the queried triangles, and against
  // itself for the pairs with a queried triangle, each pair once. The current front's
  // tree has the new one's layout (both are the first front's tree, copied or refitted),
  // so one descent finds its pairs and the new front's own.
  new_tree_.mark_nodes(query_, &query_nodes_);
  auto hit = [&](int f) { crossing_.local().push_back(f); };
  new_tree_.for_each_overlapping_pair(query_, query_nodes_, wall_->tree, [&](int f, int j) {
    if (compact_soup_triangles_intersect(soup_, new_tris_[f], wall_tris_[j])) hit(f);
  });
  auto new_pair = [&](int f, int j) {
    if (!tri_grows_[f] || !tri_grows_[j]) return;
    if (shares_only_a_certified_centre(new_tris_[f], new_tris_[j], n_cur)) return;
    if (compact_soup_triangles_intersect(soup_, new_tris_[f], new_tris_[j])) {
      hit(f);
      hit(j);
    }
  };
  if (k_ > 0)
    new_tree_.for_each_overlapping_pair_with_twin(query_, query_nodes_, cur_tree_, new_pair, [&](int f, int j) {
      if (!cur_is_wall_[j] && compact_soup_triangles_intersect(soup_, new_tris_[f], cur_tris_[j])) hit(f);
    });
  else
    new_tree_.for_each_overlapping_pair(query_, query_nodes_, new_pair);
  for (const auto& l : crossing_)
    for (int f : l)
      if (!collided_[f]) {
        collided_[f] = 1;
        collided_list_.push_back(f);
      }
}

std::array<int, 2> FrontChecker::ring_side(int c, const Triangle& t) {
  const int p = t[0] == c ? 0 : t[1] == c ? 1 : 2;
  return {t[(p + 1) % 3], t[(p + 2) % 3]};
}

void FrontChecker::order_star_rings() {
  star_ring_.assign(nc_, StarRing::kNone);
  tbb::parallel_for(0, nc_, [&](int c) {
    thread_local std::vector<std::array<std::int32_t, 2>> sides;
    thread_local std::vector<std::int32_t> ring;
    thread_local std::vector<std::pair<int, int>> by_first;  // (the side's first corner, the triangle)
    sides.clear();
    by_first.clear();
    for (const int* f = column_triangles_.begin(c); f != column_triangles_.end(c); ++f) {
      const std::array<int, 2> side = ring_side(c, front_[*f]);
      sides.push_back({side[0], side[1]});
      by_first.push_back({side[0], *f});
    }
    bool closed = false;
    // A column without a ring keeps kNone: its star is never certified.
    if (!order_star_ring(c, sides.data(), static_cast<int>(sides.size()), &ring, &closed)) return;
    // Its triangles in ring order, in place: the table's other readers take them in any
    // order. The ring's points are the triangles' first corners (and, when open, the last
    // one's second).
    std::sort(by_first.begin(), by_first.end());
    int* out = column_triangles_.items.data() + column_triangles_.start[c];
    for (std::size_t t = 0; t < by_first.size(); ++t)
      out[t] = std::lower_bound(by_first.begin(), by_first.end(), std::pair<int, int>{ring[t], INT_MIN})->second;
    star_ring_[c] = closed ? StarRing::kClosed : StarRing::kOpen;
  });
}

void FrontChecker::certify_star(int c, std::int64_t n_cur) {
  star_apart_[c] = 0;
  if (!grows_[c] || star_ring_[c] == StarRing::kNone) return;
  auto soup_of = [&](int column) { return soup_id(grows_[column] ? n_cur + column : cur_id(column)); };
  thread_local std::vector<std::int32_t> ids;
  ids.clear();
  for (const int* f = column_triangles_.begin(c); f != column_triangles_.end(c); ++f)
    ids.push_back(soup_of(ring_side(c, front_[*f])[0]));
  const bool closed = star_ring_[c] == StarRing::kClosed;
  if (!closed) ids.push_back(soup_of(ring_side(c, front_[*(column_triangles_.end(c) - 1)])[1]));
  star_apart_[c] =
      star_pairs_meet_only_at_centre(soup_, soup_id(n_cur + c), ids.data(), static_cast<int>(ids.size()), closed);
}

void FrontChecker::certify_stars(std::int64_t n_cur) {
  if (!listed_) {
    tbb::parallel_for(0, nc_, [&](int c) { certify_star(c, n_cur); });
    return;
  }
  // A repair attempt: the stars that hold a moved triangle (a column's growing state
  // changes only where it moved, and so do its triangles).
  star_list_.clear();
  for (int f : tri_list_)
    for (int c : front_[f]) star_list_.push_back(c);
  std::sort(star_list_.begin(), star_list_.end());
  star_list_.erase(std::unique(star_list_.begin(), star_list_.end()), star_list_.end());
  for (int c : star_list_) certify_star(c, n_cur);
}

void FrontChecker::check(int attempt, const std::vector<Vec3>& top, const std::vector<Vec3>& next,
                         const std::vector<char>& grows, FrontVerdict* out) {
  grows_ = grows;
  if (attempt == 0)
    flag_every_column_moved(next);
  else
    list_changes(next);
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
    for (int i = 0; i < el.n_columns(); ++i) {
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

void FrontChecker::flag_every_column_moved(const std::vector<Vec3>& next) {
  prev_next_ = next;
  prev_grows_ = grows_;
  std::fill(tri_moved_.begin(), tri_moved_.end(), 1);
  std::fill(elem_moved_.begin(), elem_moved_.end(), 1);
  tbb::parallel_for(0, nt_, [&](int f) {
    const Triangle& t = front_[f];
    tri_grows_[f] = grows_[t[0]] || grows_[t[1]] || grows_[t[2]];
  });
  listed_ = false;
}

void FrontChecker::list_changes(const std::vector<Vec3>& next) {
  clear_flags(listed_, &tri_list_, &tri_moved_);
  clear_flags(listed_, &elem_list_, &elem_moved_);
  moved_list_.clear();
  for (int v = 0; v < nc_; ++v)
    if (grows_[v] != prev_grows_[v] || !(next[v] == prev_next_[v])) {
      moved_list_.push_back(v);
      prev_grows_[v] = grows_[v];
      prev_next_[v] = next[v];
    }
  for (int v : moved_list_)
    for (const int* f = column_triangles_.begin(v); f != column_triangles_.end(v); ++f)
      if (!tri_moved_[*f]) {
        tri_moved_[*f] = 1;
        tri_list_.push_back(*f);
      }
  for (int f : tri_list_) {
    // Only a moved column can have changed growing state.
    const Triangle& t = front_[f];
    tri_grows_[f] = grows_[t[0]] || grows_[t[1]] || grows_[t[2]];
    const int e = element_of_triangle_[f];
    if (!elem_moved_[e]) {
      elem_moved_[e] = 1;
      elem_list_.push_back(e);
    }
  }
  listed_ = true;
}

void FrontChecker::check_symmetry_side(const std::vector<Vec3>& next) {
  // A triangle whose points all lie on the model's side (or in the plane, for the
  // columns on it) lies there too: the half space is convex. A repair attempt re-tests
  // the moved triangles.
  const bool listed = listed_ && static_cast<int>(side_bad_.size()) == nt_;
  if (!listed) side_bad_.assign(nt_, 0);
  for_listed_or_all(listed, tri_list_, nt_, [&](int f) {
    side_bad_[f] = 0;
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
  release(cur_normal_);
  release(cur_normal_boxes_);
  own_wall_.reset();
  wall_ = nullptr;
  release(cur_tree_);
  release(new_tree_);
  release(prev_next_);
  release(edge_neighbour_);
  release(side_slot_);
  release(centre_);
  release(below_centre_);
  release(previous_bottom_);
  release(side_face_bad_);
  release(side_geo_);
  release(column_triangles_);
  release(tree_index_);
  release(star_apart_);
  release(star_ring_);
  for (std::vector<int>* list :
       {&moved_list_, &tri_list_, &elem_list_, &query_list_, &collided_list_, &acc_list_, &star_list_})
    release(*list);
}

}  // namespace blayer
