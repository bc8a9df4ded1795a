// What a finite-volume solver accepts: the face and cell measures of OpenFOAM's mesh
// checks (checkMesh, and snappyHexMesh's meshQualityControls), computed as OpenFOAM
// computes them, so that a cell judged here is judged the same way by the solver. The
// exact corner-tet test (cell_validity.h) says a cell is a valid polyhedron; these say
// whether the solver's own geometry -- face centres, area vectors, cell centres built
// from them -- is usable: two valid prisms can share a face so skewed or so
// non-orthogonal that checkMesh fails the mesh, or a twisted side quad that no diagonal
// decomposes for both of them.
//
// Geometry (OpenFOAM's definitions, reimplemented):
//   face centre and area vector: a triangle's centroid and half the cross product of
//     two edges; a quad is split into the fan of triangles about the mean of its
//     points, the centre is the area-weighted mean of the fan's centroids and the area
//     vector the sum of the fan's area vectors.
//   cell centre and volume: the mean of the face centres is a first estimate c0; the
//     cell is split into the pyramids from c0 to each face (3 x volume = S.(Cf - c0));
//     the centre is the volume-weighted mean of the pyramid centroids (3/4 Cf + 1/4 c0)
//     and the volume their sum (c0 when that sum is zero).
//
// Measures of one face f with centre Cf and area vector S, pointing out of the owner
// cell (centre Co) into the neighbour (centre Cn), or out of the domain:
//   face pyramid volume  S.(Cf - C) / 3 about the centre C of a cell the face points
//                  out of: positive in a cell checkMesh accepts ("face pyramids").
//   tet quality    signed volume / (8 / (9 sqrt 3) R^3) with R the circumradius: 1 for
//                  a regular tet, <= 0 for an inverted one.
//   face tets      checkMesh -allGeometry's decomposition check, two parts:
//                  face-centre tets: the tets (C, Cf, p_i, p_i+1) of the fan about the
//                    face centre, on each side (the decomposition behind the centres
//                    and volumes);
//                  base-point tets: the tets (C, base, p_i, p_i+1) of the fan from a
//                    face point, the best over base points of the worst tet, with the
//                    same base point on both sides of an internal face (the
//                    decomposition OpenFOAM's particle tracking and tet-based
//                    interpolation use).
//                  checkMesh fails a face when a tet of either part scores 1e-30 or
//                  less; the face_tets limit asks for more (kMinFaceTetQuality).
//   non-orthogonality  the angle between Cn - Co and S, degrees; internal faces only.
//                  checkMesh calls a face severe above 70 degrees and fails the mesh at
//                  90 (cosine below 1e-15).
//   skewness       the distance from Cf to where the line Co-Cn crosses the face's
//                  plane, over the face's extent in that direction (at least 0.2 |Cn -
//                  Co|). A boundary face is measured against the mirror of its cell:
//                  the line from Co along the face normal, the extent at least 0.4 x
//                  the distance from Co to the plane. checkMesh fails the mesh above 4,
//                  internal and boundary alike.
//   flatness       |S| over the summed areas of the fan about Cf: 1 for a plane face.
//                  checkMesh -allGeometry warns below 0.8, snappyHexMesh's default
//                  minFlatness is 0.5.
//   warp           not an OpenFOAM figure: the largest angle between the normals of the
//                  two triangles of a diagonal split of a quad, over both diagonals
//                  (cell_metrics.h twist_deg); 0 for a triangle. A unit square folded
//                  along a diagonal by 60, 93 and 136 degrees has flatness 0.93, 0.80
//                  and 0.50; a thin quad's split triangles are slivers, so a small
//                  twist of a boundary-layer side quad is a large warp.
//
// Every function is plain floating point (these are OpenFOAM's floating-point figures);
// none throws. Divisions carry OpenFOAM's own guards (1e-150 added to denominators), so
// degenerate input (zero areas, coincident centres) gives the figure OpenFOAM prints.
#pragma once

#include <array>

#include "blayer/core/vec3.h"
#include "blayer/core/volume_mesh.h"

namespace blayer {

// A face: 3 or 4 points in order; its right-hand normal is its orientation.
struct PolyFace {
  int n = 0;
  std::array<Vec3, 4> p{};
};

struct FaceGeometry {
  Vec3 centre{};
  Vec3 area{};  // right-hand normal times the area
};

struct CellGeometry {
  Vec3 centre{};
  double volume = 0.0;
};

FaceGeometry face_geometry(const PolyFace& f);

// The same points in the opposite order (the face seen from the other side).
PolyFace reversed(const PolyFace& f);

// faces: the geometry of each face of the cell, every one oriented out of the cell.
CellGeometry cell_geometry(const FaceGeometry* faces, int n_faces);

// The faces of a VTK linear cell (cell_validity.h node orders), oriented out of the
// cell; returns their number (4 to 6).
int cell_poly_faces(CellType type, const Vec3* corners, PolyFace out[6]);

// S.(Cf - cell_centre) / 3 for a face oriented out of the cell.
double face_pyramid_volume(const FaceGeometry& g, const Vec3& cell_centre);

// Signed volume over that of the regular tet with the same circumradius.
double tet_quality(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// The base-point tet quality of f, oriented out of the cell centred at `own`; `nei` is
// the centre of the cell on the other side (nullptr: a boundary face).
double face_tet_quality(const PolyFace& f, const Vec3& own, const Vec3* nei);

// The worst face-centre tet of f about the centre of a cell that f is oriented out of.
double face_centre_tet_quality(const PolyFace& f, const FaceGeometry& g, const Vec3& centre);

double face_non_orthogonality_deg(const FaceGeometry& g, const Vec3& own, const Vec3& nei);
double face_skewness(const PolyFace& f, const FaceGeometry& g, const Vec3& own, const Vec3& nei);
double boundary_face_skewness(const PolyFace& f, const FaceGeometry& g, const Vec3& own);
double face_flatness(const PolyFace& f, const FaceGeometry& g);
double face_warp_deg(const PolyFace& f);

// The non-orthogonality a face over the wall edge (a, b) inherits from the wall: wall
// triangles f (the owner, corners f[0..2]) and g on either side of the edge. It is the
// limit, as the layer height goes to zero, of the face between the two cells of a
// straight layer along the mean of the triangles' normals: the angle between the line
// of the triangles' centroids and the normal of the plane through the edge and that
// mean normal, oriented out of f. No column direction changes it; on the thin triangles
// of a CAD-tessellated wall (one triangle across a wing's span) it is within 0.012
// degree of 90 at an aspect ratio of 1e4 (for a split w x L rectangle its cosine is
// 2 w L / (w^2 + L^2)).
double wall_edge_non_orthogonality_deg(const std::array<Vec3, 3>& f, const std::array<Vec3, 3>& g, const Vec3& a,
                                       const Vec3& b);

// The non-orthogonality limit for a face whose wall edge inherits `inherited_deg`: the
// larger of the user's limit L and the angle whose cosine is the inherited one times
// max(1/2, cos L) (from L = 60 degrees on, the face may lean twice as far towards its
// plane as the wall's own; below, as far as L allows on top of the wall's lean), so that
// a column is never ended for the wall's geometry and can still turn; but never an
// angle whose cosine is kMinNonOrthogonalityCosine or less. From 60 degrees on it widens
// L where the wall's own angle exceeds acos(2 cos L): 89.98 degrees for the default
// 89.99, 46.8 for 70; below 60, wherever the wall edge is not flat, by an amount that
// vanishes with the wall's angle. A limit of 0 stays off.
double inherited_non_orthogonality_limit_deg(double limit_deg, double inherited_deg);

// checkMesh fails a face whose non-orthogonality cosine is 1e-15 or less; a cosine is
// computed here with a rounding error of about 1e-16 (unit vectors), and OpenFOAM's
// centres differ from these by another summation order: 1e-12 keeps a margin of 1000.
constexpr double kMinNonOrthogonalityCosine = 1e-12;

// The limits a cell must meet; 0 disables a limit.
struct AcceptanceLimits {
  double max_non_orthogonality_deg = 0.0;  // internal faces
  double max_skewness = 0.0;               // internal faces
  double max_boundary_skewness = 0.0;      // boundary faces
  double max_face_warp_deg = 0.0;          // quads
  bool face_pyramids = false;              // every face pyramid positive
  bool face_tets = false;                  // every face tet above kMinFaceTetQuality
  bool any() const {
    return max_non_orthogonality_deg > 0.0 || max_skewness > 0.0 || max_boundary_skewness > 0.0 ||
           max_face_warp_deg > 0.0 || face_pyramids || face_tets;
  }
};

// The smallest face-tet quality accepted by the face_tets limit. checkMesh
// accepts anything above 1e-30 (sqr(SMALL)). A tet quality computed from coordinates of
// extent L carries a rounding error of about 1e-16 x (L / R)^3 <= 1e-15, and OpenFOAM's
// cell centres differ from these by the rounding of another summation order, which
// moves the quality by as much again: 1e-12 keeps a margin of 300 over both, so a tet
// accepted here is positive for checkMesh too. It is not a shape limit: the thin
// side-quad fans at the ONERA M6 tip score 5e-10, and a limit of 1e-9 ended 116
// columns there, 6.2 % of the wall area.
constexpr double kMinFaceTetQuality = 1e-12;

// Where the other side of a face is.
enum class FaceSide {
  kBoundary,  // the face bounds the mesh: boundary skewness
  kInternal,  // the cell centred at `other` is on the other side
  kUnknown,   // not known yet: only the measures of this cell alone
};

// The first limit a face breaks, in this order.
enum class AcceptanceFailure {
  kNone = 0,
  kFacePyramid,
  kFaceTets,
  kFaceWarp,
  kNonOrthogonality,
  kSkewness,
  kBoundarySkewness,
};
const char* acceptance_failure_name(AcceptanceFailure f);

// Judges face f (oriented out of the cell centred at `own`) against the limits; with
// kUnknown only this side's pyramid and face tets and the warp. A face it accepts has
// every face tet of checkMesh positive (for a triangle only the base tet is computed:
// its centre-fan tets are its thirds, positive when it scores above 1e-12).
AcceptanceFailure judge_face(const PolyFace& f, const FaceGeometry& g, const Vec3& own, FaceSide side,
                             const Vec3& other, const AcceptanceLimits& limits);

// Judges a cell alone in a mesh: every face is a boundary face.
AcceptanceFailure judge_lone_cell(CellType type, const Vec3* corners, const AcceptanceLimits& limits);

}  // namespace blayer
