// The per-layer guard that keeps every cell valid while marching: the exact corner-tet
// test of each new cell, the solver-acceptance limits of its faces, and the exact
// intersection test of the new front against itself, the current front and the wall.
// It owns the three triangle trees (wall, current front, new front); the proximity rays
// borrow the first two.
//
// The fronts are the layout's front triangles over the columns (fan_layout.h; without
// fans, the wall's triangles over the wall points). All three surfaces live on one
// point array ("soup") so that shared points are seen as shared: wall point w -> w,
// current top of column c -> nv + c (its wall point while the column is still on the
// wall), new top c -> nv + nc + c (the current id where the column does not grow). A
// new triangle none of whose columns grows is the current (or wall) triangle itself,
// already checked, so it is neither tested nor a partner; likewise a current triangle
// that is still on the wall. A triangle that names one soup point twice (a fan strip
// whose fan points are still on the wall) is a segment of its neighbours' edges and is
// skipped. Cells are checked per layout element (layer_cells.h). Two new triangles that
// share only a growing column's new top are not tested when that column's star is
// certified (star_pairs_meet_only_at_centre): they then meet nowhere else.
//
// Incremental re-checks: within a layer, a cell or new triangle is re-tested in a
// later attempt only if one of its columns moved or changed growing state, or if it
// failed in the previous attempt; the others are bit-identical to what already passed,
// so every attempt ends with exactly the verdicts of a full re-check. A repair attempt
// moves a few hundred of the front's columns: it lists them and the triangles, cells
// and faces on them, and its passes (and the new front tree's refit) visit only those,
// where passes over the whole front took about 1 ms per attempt on a 23k-triangle CAD
// surface.
//
// Solver acceptance (ExtrusionParams::solver_limits, quality/solver_acceptance.h): a
// new cell that passes the exact test must also meet the limits on each of its faces,
// measured with the cell centres OpenFOAM computes:
//   bottom face (the current front triangle): against the cell below it (layer k-1), or
//     as a wall boundary face in layer 0;
//   side faces (the quads and triangles over the wall edges): against the new cell of
//     the edge's other triangle, or as boundary faces on open wall edges; where the
//     wall edge's own non-orthogonality exceeds acos(2 cos limit) (thin CAD triangles
//     at the default limit, many more at a low one), the face's limit is widened to
//     twice the wall's lean (below a limit of 60, by the limit's own cosine)
//     (inherited_non_orthogonality_limit_deg), so that no column is ended for the
//     wall's geometry, and never to checkMesh's error;
//   top face (the new front triangle): as a boundary face, the layers' envelope, until
//     a later layer covers it and judges it again as its bottom face.
// Every face of a layers-only mesh is thus judged with the final centres on both its
// sides, so the layer mesh meets the limits (up to the rounding of checkMesh's own
// sums, 1e-15 relative). Not judged: the faces between the envelope and a tetrahedral
// fill (their other side does not exist yet) and the fill's cells; in a fill the
// envelope faces are internal faces judged here as boundary faces, which bounds their
// skewness only approximately. A shared side face is judged once, from the triangle
// of smaller id, and fails both cells; faces of a cell that fails the exact test are
// not judged (the cell fails anyway). The cell below is known when begin_layer(k - 1)
// was called on this checker; otherwise the bottom face's two-cell measures are
// skipped (the cell-only ones are kept). Incremental re-checks extend to the
// acceptance verdicts: a face is re-judged when a column of either of its cells moved.
// With fans the limits judge the cells of the wall triangles (on their sector columns);
// a side face shared with a fan strip is judged from the wall triangle's side alone
// (FaceSide::kUnknown), and the fan cells (strips, corner patches, the wall triangles
// split at ridge ends) pass on the exact test alone.
//
// One tree layout, the front's, serves every front of the run (TriangleBvh::refit).
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/vertex_adjacency.h"
#include "blayer/extruder/extrusion_params.h"
#include "blayer/extruder/proximity_rays.h"
#include "blayer/extruder/triangle_bvh.h"
#include "blayer/extruder/triangle_intersections.h"
#include "blayer/extruder/wall_topology.h"
#include "blayer/quality/solver_acceptance.h"

namespace blayer {

// What one attempt found, per column and per wall triangle.
struct FrontVerdict {
  std::vector<char> bad;               // column of a failing cell or colliding triangle
  std::vector<StopReason> reason;      // kQuality (a failing cell) before kCollision
  std::vector<char> bad_triangle;      // failing cell or colliding new triangle
  bool any_bad = false;
};

class FrontChecker {
 public:
  // check_collisions false: cells are still checked, the intersection test is skipped.
  // topo.plane (a half model's symmetry plane): a new point of a column off the plane
  // must lie strictly on the model's side of it (a collision otherwise); points of the
  // columns on it lie in it by construction. No solver-acceptance limits.
  FrontChecker(const TriSurface& wall, const WallTopology& topo, bool check_collisions);
  // The columns of a layout (topo = build_column_topology(layout)). wall_tree: the
  // run's, borrowed and to outlive the checker (null: the checker builds its own).
  FrontChecker(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo, bool check_collisions,
               const WallTree* wall_tree = nullptr);
  // The same on a layout the checker shares instead of copying (the march's: a copy of
  // a fanned layout's front and elements was 2.5 MB of a small run's peak).
  FrontChecker(const TriSurface& wall, std::shared_ptr<const ColumnLayout> layout, const WallTopology& topo,
               bool check_collisions, const WallTree* wall_tree = nullptr);
  // params.check_collisions and params.solver_limits. With fans the limits judge the
  // wall triangles' cells; fan strips, corner patches and the cells split at ridge ends
  // are checked exactly only (see the header comment).
  FrontChecker(const TriSurface& wall, const WallTopology& topo, const ExtrusionParams& params);
  FrontChecker(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo,
               const ExtrusionParams& params, const WallTree* wall_tree = nullptr);
  FrontChecker(const TriSurface& wall, std::shared_ptr<const ColumnLayout> layout, const WallTopology& topo,
               const ExtrusionParams& params, const WallTree* wall_tree = nullptr);

  // The wall alone, for the wall-gap cap before marching.
  ProximityRays wall_rays() const;
  // The wall and the current front (after begin_layer with k > 0).
  ProximityRays front_rays() const;

  // Starts layer k (0-based) from the current column tops and layer counts.
  void begin_layer(int k, const std::vector<Vec3>& top, const std::vector<int>& layers);

  // Checks the layer from `top` to `next` for the columns with grows set (attempt 0
  // first in each layer, then 1, 2, ... with the repaired positions).
  void check(int attempt, const std::vector<Vec3>& top, const std::vector<Vec3>& next, const std::vector<char>& grows,
             FrontVerdict* out);

  // Frees the trees it owns and the point soup (the marching state is not needed for
  // output); a borrowed wall tree is its owner's to free.
  void release();

 private:
  void check_cells(const std::vector<Vec3>& top, const std::vector<Vec3>& next);
  void check_acceptance(const std::vector<Vec3>& top, const std::vector<Vec3>& next);
  void cells_below(int k, const std::vector<Vec3>& top, const std::vector<int>& layers);
  // Whether the last check (of layer k - 1) had the grown columns and positions that
  // the layer starts from (top, layers): the attempt that was committed.
  bool last_attempt_committed(int k, const std::vector<Vec3>& top, const std::vector<int>& layers) const;
  void check_intersections(const std::vector<Vec3>& next);
  // The new front's stars (star_pairs_meet_only_at_centre) around the new points of the
  // growing columns: all in a layer's first attempt, those holding a moved triangle in a
  // repair attempt. n_cur: the first new point's soup id.
  void certify_stars(std::int64_t n_cur);
  // Each column's ring in the front (order_star_ring), once, as the order of its
  // triangles in column_triangles_: the front's triangles do not change, only the soup
  // ids of their corners.
  void order_star_rings();
  // The corners after column c in front triangle t, in its winding.
  static std::array<int, 2> ring_side(int c, const Triangle& t);
  void certify_star(int c, std::int64_t n_cur);
  // Whether new front triangles s and t share one soup point alone, the new point of a
  // column whose star is certified: they then meet nowhere else, untested.
  bool shares_only_a_certified_centre(const SoupTriangle& s, const SoupTriangle& t, std::int64_t n_cur) const;
  void build_edge_neighbours(const TriSurface& wall, const ColumnLayout& layout);
  // Whether the first nf_ front triangles are the wall's, corner by corner on bitwise
  // the same points (the layout's contract, checked rather than assumed: the first
  // front's tree reuses the wall's for them).
  bool front_starts_with_wall(const TriSurface& wall) const;

  void check_symmetry_side(const std::vector<Vec3>& next);
  // The attempt's flags of moved triangles and elements: all set in a layer's first
  // attempt; in a repair attempt set from the columns that moved or changed growing
  // state since the attempt before, and listed, so that the passes below visit only
  // them (listed_).
  void flag_every_column_moved(const std::vector<Vec3>& next);
  void list_changes(const std::vector<Vec3>& next);
  // The wall triangles whose acceptance verdicts a repair attempt re-judges: the moved
  // ones and their edge neighbours.
  void list_acceptance_triangles();
  std::int64_t cur_id(int c) const { return (*layers_)[c] == 0 ? wall_point_[c] : nv_ + c; }
  // A soup id as the 32-bit tables hold it (the constructor refuses larger soups).
  static std::int32_t soup_id(std::int64_t id) { return static_cast<std::int32_t>(id); }

  const std::vector<Triangle>* triangles_;  // the wall's
  // The layout, shared (or the checker's own copy), and the parts of it the checks read:
  // the front's triangles over the columns, the elements and their maps.
  std::shared_ptr<const ColumnLayout> layout_;
  const std::vector<Triangle>& front_;
  const std::vector<LayerElement>& elements_;
  const std::vector<int>& element_of_triangle_;
  const std::vector<int>& wall_point_;
  std::optional<SymmetryPlane> plane_;
  std::vector<char> on_plane_;
  const std::vector<Vec3>* wall_points_;
  int nv_ = 0, nc_ = 0, nf_ = 0, nt_ = 0, ne_ = 0, k_ = 0;
  bool check_collisions_ = true;

  std::unique_ptr<WallTree> own_wall_;
  const WallTree* wall_ = nullptr;  // own_wall_ or the run's
  TriangleBvh cur_tree_, new_tree_;
  int new_tree_layer_ = -1;  // the layer new_tree_ was last refitted for
  std::vector<Vec3> cur_normal_;
  std::vector<UnitVectorBox> cur_normal_boxes_;  // per node of cur_tree_ (ProximityRays)
  const std::vector<Vec3>* cur_points_ = nullptr;

  std::vector<Vec3> soup_;
  std::vector<SoupTriangle> wall_tris_, cur_tris_, new_tris_;
  std::vector<char> cur_is_wall_;
  const std::vector<int>* layers_ = nullptr;

  // Solver acceptance: the limits; per triangle and edge, the triangle across the edge
  // (-1 on an open edge, -2 on a non-manifold one) and the slot (3 x triangle + edge)
  // that holds the shared side face's verdict (its owner's); the centres of the new
  // cells and of the cells below; the front at the start of the previous layer.
  AcceptanceLimits limits_;
  std::vector<Triangle> acc_tris_;  // the wall triangles on their columns (front's first)
  std::vector<int> edge_neighbour_, side_slot_;
  // Per slot: the non-orthogonality limit of its side face, widened where the wall
  // edge's own angle is near it (inherited_non_orthogonality_limit_deg).
  std::vector<double> side_non_orth_limit_;
  std::vector<char> skip_acceptance_;  // wall triangles split at a ridge end
  std::vector<Vec3> centre_, below_centre_, previous_bottom_;
  std::vector<FaceGeometry> side_geo_;  // per slot: the side face seen from its triangle
  int previous_layer_ = -1;
  bool below_known_ = false;
  std::vector<char> invalid_, cap_bad_, side_face_bad_;

  // Attempt state.
  std::vector<char> grows_, prev_grows_;
  std::vector<Vec3> prev_next_;
  // Repair attempts: the front triangles on each column; the lists of the attempt's
  // moved columns, triangles and elements, of its queried triangles, of the triangles
  // found crossing and of the wall triangles re-judged; the new front tree's layout, for
  // refits of the moved triangles alone.
  CsrTable column_triangles_;
  std::vector<int> moved_list_, tri_list_, elem_list_, query_list_, collided_list_, acc_list_;
  std::vector<char> acc_listed_;
  bool listed_ = false;          // this attempt's flags come from the lists
  bool query_listed_ = false;    // query_ was set from query_list_
  TriangleBvh::LayoutIndex tree_index_;
  std::vector<char> bad_cell_, elem_moved_;                     // per element
  std::vector<char> collided_, tri_moved_, tri_grows_, query_;  // per front triangle
  // Per column: its new front star is certified (certify_stars); the columns whose stars
  // a repair attempt certifies again.
  std::vector<char> star_apart_;
  std::vector<int> star_list_;
  // Per column: whether its front triangles form a ring (order_star_ring), open or
  // closed; column_triangles_ then lists them in ring order.
  enum class StarRing : char { kNone, kOpen, kClosed };
  std::vector<StarRing> star_ring_;
  std::vector<char> side_bad_;  // a point of the new triangle off the model's side of the plane
  tbb::enumerable_thread_specific<std::vector<int>> crossing_;  // new front triangles found crossing
  std::vector<char> query_nodes_;                                   // new_tree_ nodes holding a queried triangle
};

}  // namespace blayer
