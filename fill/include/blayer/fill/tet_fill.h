// Tetrahedral fill of the region bounded by the boundary-layer envelope, with TetGen 1.5.
//
// TetGen is licensed under the AGPL (v3). This module links it; a program that ships
// blayer_fill is subject to the AGPL. TetGen headers appear only in fill/src.
//
// Contract
//   envelope  closed, edge-manifold, consistently oriented triangle surface; each
//             triangle (a,b,c) has its right-hand normal (b-a)x(c-a) pointing INTO the
//             region to fill. Several closed components are allowed (several bodies, or a
//             pipe wall plus an inner body). Points used by no triangle are allowed and
//             stay unused in the output.
//   region    kOutside: external flow, fill between the envelope and a farfield. Every
//             envelope component must enclose positive volume (normals point away from
//             its body); each body gets a TetGen hole point.
//             kInside: internal flow, fill inside the envelope, no farfield. At least one
//             component must enclose negative volume (an outer wall whose normals point
//             into the pipe); components with positive volume are inner bodies and get
//             hole points.
//             Components are edge-connected (blayer/core/surface_components.h), so
//             bodies that touch at a point are separate bodies with a hole point each.
//
// PLC handed to TetGen: envelope triangles (facet marker 1) and farfield triangles
// (marker 2) as one-polygon facets, one hole point per body. A hole point sits behind
// a large triangle of the body (against its normal, at a small fraction of the
// triangle's size) and is accepted only when a ray-parity test against the whole
// envelope confirms it lies outside the fill region.
//
// TetGen switches: p (PLC), Y (no Steiner points on the boundary, so every envelope
// triangle is a tet face with the same point indices and the tets conform node for node
// to the layers' outer caps), q<quality_radius_edge> (radius-edge bound), m (point
// metric size field, below), Q (quiet), S<max_steiner_points> when that is positive.
//
// Size field: target edge length s(x) = min over envelope vertices v of
// h_v + (growth - 1) * |x - v|, where h_v is the mean length of the envelope edges at v
// (or envelope_size when positive). An edge length that grows by (growth - 1) per unit
// distance makes neighbouring tets differ in size by about the factor `growth`. TetGen's
// m switch bounds the circumradius of a tet by the metric at each of its vertices, so
// each input point gets metric = s(x) * sqrt(6)/4 (the circumradius of a regular tet of
// edge s); at an envelope vertex s <= h_v. TetGen interpolates the metric linearly over
// the current mesh for the Steiner points it inserts, so the grading in between is
// smooth and monotone but only approximately the formula.
//
// Quality: q holds for tets TetGen may split. Tets on boundary triangles cannot be
// improved under Y, so near poor envelope triangles (thin trailing edges) the radius-
// edge ratio exceeds the bound; q bounds no dihedral angle, so slivers of a few degrees
// remain. FillStats reports both figures.
//
// Farfield (kOutside): without a user surface, an axis-aligned box centred on the
// envelope's bounding box. Its side along axis k is farfield_scale times
// max(extent_k, extent_max / 2): "each side scaled", except that a thin body (a wing)
// is not given a farfield a fraction of a chord away. The box faces are structured
// triangle grids with spacing close to s(x) on the box (the minimum of s over the box),
// because Y forbids TetGen to split them. A user farfield (option farfield) is used
// as given: closed, edge-manifold, consistently oriented, enclosing the envelope and
// not touching it; its orientation is detected from its signed volume and its
// triangles are reported wound with normals into the domain (flipped when they face
// outward). Its triangles are not split either, so they should be sized for the far
// field.
//
// Crash safety: TetGen runs in a forked child process (see run_isolated.h). A
// self-intersection check (TetGen's d switch) runs first, in its own child. A child
// that crashes, aborts or exceeds timeout_seconds, and every TetGen error code, becomes
// an InputError; the calling process is never terminated.
//
// Output checks (always on, failure = InputError naming the problem): the first
// envelope.points.size() output points are bit-identical to the envelope's; the faces
// used by exactly one tet are exactly the envelope and farfield triangles (no boundary
// Steiner point, no missing or extra boundary face); no face is shared by more than two
// tets; the tet on each envelope triangle lies on the side its normal points to.
//
// Symmetry plane (option symmetry, a half model): the envelope is closed up to the plane
// (its boundary edges lie exactly on it); the farfield is the box the mirrored model
// would get, cut by the plane; the plane facet is the box's face on the plane outside
// the envelope's cut, triangulated by constrained Delaunay refinement (smallest angle
// 20.7 degrees, edges up to 1.5 times the size field and up to the box spacing, so that
// the tets next to the plane are as large as those crossing it in the mirrored model:
// src/half_domain.h) without splitting the box's or the cut's edges, marker 3; bodies
// cut by the plane need no hole point. Only the generated box, region outside and
// coordinate planes.
//
// Failure behaviour: throws blayer::InputError for bad input (open, non-manifold,
// inconsistently oriented, self-intersecting, degenerate or duplicate points, wrong
// region for the orientation, farfield not enclosing the envelope), for every TetGen
// failure, and when the output checks fail. Options out of range also throw InputError.
#pragma once

#include <cstdint>
#include <vector>

#include <optional>

#include "blayer/core/surface.h"
#include "blayer/core/symmetry_plane.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

struct FillOptions {
  enum class Region { kOutside, kInside };
  // kOutside: between envelope and farfield (external flow). kInside: inside the
  // envelope (internal flow, `--side inward`), no farfield.
  Region region = Region::kOutside;

  // Farfield box size factor (kOutside without a user farfield), see above. Must be > 1.
  double farfield_scale = 10.0;

  // User farfield surface (kOutside only; an error with kInside). Not owned; must
  // outlive the call. nullptr: the box above.
  const TriSurface* farfield = nullptr;

  // Growth of the target edge length away from the envelope: neighbouring tets differ
  // in size by about this factor. Must be >= 1.
  double growth = 1.3;

  // TetGen's radius-edge bound (q switch). TetGen needs > 1 to terminate; 1.4 is
  // already good; larger values give fewer tets.
  double quality_radius_edge = 1.4;

  // Target edge length at the envelope, same length unit as the points. 0: per
  // envelope vertex, the mean length of its edges.
  double envelope_size = 0.0;

  // Upper bound on Steiner points (TetGen S switch); 0: no bound. When the bound is
  // reached TetGen stops refining and the quality bound may not hold.
  int max_steiner_points = 0;

  // Wall-clock limit for each TetGen child process, seconds; 0: none.
  double timeout_seconds = 600.0;

  // A half model's symmetry plane (a coordinate plane; region outside, generated box):
  // the envelope may be open along it, the farfield is the box cut by it, and the
  // plane facet between the box and the envelope's cut closes the domain (marker
  // kSymmetryMarker). See "Symmetry plane" above.
  std::optional<SymmetryPlane> symmetry;
};

struct FillStats {
  std::int64_t n_envelope_points = 0;  // envelope.points.size()
  std::int64_t n_farfield_points = 0;
  std::int64_t n_steiner_points = 0;  // inserted by TetGen, all strictly inside the domain
  std::int64_t n_tets = 0;
  std::int64_t n_holes = 0;        // hole points handed to TetGen (bodies)
  double min_envelope_size = 0.0;  // min / max over envelope vertices of h_v
  double max_envelope_size = 0.0;
  double farfield_size = 0.0;     // box: its grid spacing; user farfield: max s at its points
  double min_dihedral_deg = 0.0;  // over all tets
  // Over tets with no boundary point: what q achieves where Y does not hold it back.
  double min_dihedral_deg_interior = 0.0;
  double max_radius_edge = 0.0;  // max circumradius / shortest edge over all tets
  double min_tet_volume = 0.0;   // smallest (positive) tet volume
  double seconds_check = 0.0;    // self-intersection child
  double seconds_tetgen = 0.0;   // meshing child, including transfer
  double seconds_total = 0.0;
};

struct FillResult {
  // points[0, envelope.points.size()) == envelope.points (same order, bit-identical),
  // then the farfield points, then TetGen's Steiner points. Cells all CellType::kTet in
  // VTK order, positive volume: (p1-p0)x(p2-p0) . (p3-p0) > 0.
  VolumeMesh tets;
  // Envelope triangles (as given) followed by the farfield triangles, indexing
  // tets.points; every triangle's normal points into the filled domain.
  TriSurface boundary;
  // Per boundary triangle: 1 = envelope (the layers' outer caps), 2 = farfield.
  std::vector<int> boundary_marker;
  FillStats stats;
};

inline constexpr int kEnvelopeMarker = 1;
inline constexpr int kFarfieldMarker = 2;
inline constexpr int kSymmetryMarker = 3;

// Fills the region selected by opt.region with tetrahedra; see the file comment for
// contract, switches and failure behaviour. blayer/fill/hybrid_mesh.h joins the result
// to the layer mesh and builds the marked boundary of the whole mesh.
FillResult fill_with_tets(const TriSurface& envelope, const FillOptions& opt);

}  // namespace blayer
