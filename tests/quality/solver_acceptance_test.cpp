// The solver-acceptance measures on hand-computed cells: each expected figure is derived
// in the test from the cell's construction (OpenFOAM's definitions, see the header).
#include "blayer/quality/solver_acceptance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "blayer/quality/cell_validity.h"
#include "lcg.h"
#include "test_cells.h"

namespace blayer {
namespace {

// A few dozen flops on coordinates of order 1: 1e-12 absolute is far above the rounding
// and far below any formula error.
constexpr double kTol = 1e-12;
constexpr double kPi = 3.14159265358979323846;

struct Lone {
  std::vector<PolyFace> faces;
  std::vector<FaceGeometry> geo;
  CellGeometry cell;
};

Lone lone(CellType t, const std::vector<Vec3>& corners) {
  PolyFace f[6];
  const int n = cell_poly_faces(t, corners.data(), f);
  Lone l;
  for (int i = 0; i < n; ++i) {
    l.faces.push_back(f[i]);
    l.geo.push_back(face_geometry(f[i]));
  }
  l.cell = cell_geometry(l.geo.data(), n);
  return l;
}

void expect_near(const Vec3& a, const Vec3& b, double tol = kTol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

// The right prism of test_cells.h with its top cap moved by `shift`.
std::vector<Vec3> sheared_prism(double h, const Vec3& shift) {
  std::vector<Vec3> p = test::right_prism(h);
  for (int i = 3; i < 6; ++i) p[i] += shift;
  return p;
}

// The prism whose bottom is the wall triangle of test::right_prism moved by `bottom`
// and whose top is it moved by `top`.
std::vector<Vec3> prism_between(const Vec3& bottom, const Vec3& top) {
  std::vector<Vec3> p = test::right_prism(0.0);
  for (int i = 0; i < 3; ++i) p[i] += bottom;
  for (int i = 3; i < 6; ++i) p[i] += top;
  return p;
}

Vec3 vertex_mean(const std::vector<Vec3>& p) {
  Vec3 m{0, 0, 0};
  for (const Vec3& q : p) m += q;
  return m / double(p.size());
}

AcceptanceLimits only_boundary_skewness(double x) {
  AcceptanceLimits l;
  l.max_boundary_skewness = x;
  return l;
}

TEST(SolverAcceptance, UnitCubeHasCentredFacesAndCentreAndNoSkewness) {
  const Lone c = lone(CellType::kHex, test::unit_hex());
  ASSERT_EQ(c.faces.size(), 6u);
  expect_near(c.cell.centre, {0.5, 0.5, 0.5});
  EXPECT_NEAR(c.cell.volume, 1.0, kTol);
  // Every face: area 1, centre at its middle, outward, a pyramid of 1 x 0.5 / 3.
  for (std::size_t i = 0; i < c.faces.size(); ++i) {
    EXPECT_NEAR(norm(c.geo[i].area), 1.0, kTol);
    EXPECT_NEAR(norm(c.geo[i].centre - c.cell.centre), 0.5, kTol);
    EXPECT_NEAR(face_pyramid_volume(c.geo[i], c.cell.centre), 1.0 / 6.0, kTol);
    EXPECT_NEAR(boundary_face_skewness(c.faces[i], c.geo[i], c.cell.centre), 0.0, kTol);
    EXPECT_NEAR(face_flatness(c.faces[i], c.geo[i]), 1.0, kTol);
    EXPECT_NEAR(face_warp_deg(c.faces[i]), 0.0, kTol);
    // Fan tet (centre, three corners of a face): volume 1/12, circumradius 3/4 (the
    // circumcentre lies 1/4 outside the face, on the face's axis), so the quality is
    // (1/12) / (8 / (9 sqrt 3) x 27/64) = 2 / (3 sqrt 3).
    EXPECT_NEAR(face_tet_quality(c.faces[i], c.cell.centre, nullptr), 2.0 / (3.0 * std::sqrt(3.0)), kTol);
  }
  AcceptanceLimits all{70.0, 4.0, 4.0, 10.0, true, true};
  EXPECT_EQ(judge_lone_cell(CellType::kHex, test::unit_hex().data(), all), AcceptanceFailure::kNone);
}

TEST(SolverAcceptance, RegularTetScoresOneAndItsMirrorMinusOne) {
  const Vec3 a{1, 1, 1}, b{1, -1, -1}, c{-1, 1, -1}, d{-1, -1, 1};
  const double q = tet_quality(a, b, c, d);
  EXPECT_NEAR(std::abs(q), 1.0, kTol);
  EXPECT_NEAR(tet_quality(a, c, b, d), -q, kTol);
}

TEST(SolverAcceptance, StackedCubesAreOrthogonalAndUnskewed) {
  const Lone lower = lone(CellType::kHex, test::unit_hex());
  std::vector<Vec3> up = test::unit_hex();
  for (Vec3& p : up) p[2] += 1.0;
  const Lone upper = lone(CellType::kHex, up);
  const int top = 1;  // face (4,5,6,7) of the lower cube, normal +z
  EXPECT_NEAR(face_non_orthogonality_deg(lower.geo[top], lower.cell.centre, upper.cell.centre), 0.0, 1e-6);
  EXPECT_NEAR(face_skewness(lower.faces[top], lower.geo[top], lower.cell.centre, upper.cell.centre), 0.0, kTol);
}

TEST(SolverAcceptance, ShearedPrismCentreIsTheVertexMeanAndItsCapsSkewByThreeQuartersOfTheShear) {
  // An affine image of a right prism: plane faces, so OpenFOAM's centre is the exact
  // centroid, the mean of the six corners.
  const double h = 1.0, s = 6.0;
  const std::vector<Vec3> p = sheared_prism(h, {s, 0, 0});
  ASSERT_EQ(cell_validity(CellType::kWedge, p.data()), Validity::kValid);
  const Lone c = lone(CellType::kWedge, p);
  expect_near(c.cell.centre, vertex_mean(p));
  EXPECT_NEAR(c.cell.volume, 0.5 * h, kTol);
  // Bottom cap (face 0): the centre (1/3 + s/2, 1/3, h/2) projects s/2 beside the cap's
  // centroid (1/3, 1/3, 0); the cap reaches 2/3 from its centroid along x, which beats
  // 0.4 x h/2: skewness (s/2) / (2/3) = 3s/4. The top cap likewise.
  EXPECT_NEAR(boundary_face_skewness(c.faces[0], c.geo[0], c.cell.centre), 0.75 * s, kTol);
  EXPECT_NEAR(boundary_face_skewness(c.faces[1], c.geo[1], c.cell.centre), 0.75 * s, kTol);
  // Valid, yet alone in a mesh it breaks checkMesh's skewness limit of 4 (4.5).
  EXPECT_EQ(judge_lone_cell(CellType::kWedge, p.data(), only_boundary_skewness(4.0)),
            AcceptanceFailure::kBoundarySkewness);
  EXPECT_EQ(judge_lone_cell(CellType::kWedge, p.data(), only_boundary_skewness(4.6)), AcceptanceFailure::kNone);
}

TEST(SolverAcceptance, ZigZagPrismsSkewTheirSharedCapAndLeaningStacksAreNonOrthogonal) {
  const double h = 1.0, s = 2.0;
  const Lone lower = lone(CellType::kWedge, prism_between({0, 0, 0}, {s, 0, h}));
  // The cell above leans back: its top returns over the wall triangle.
  const Lone zig = lone(CellType::kWedge, prism_between({s, 0, h}, {0, 0, 2 * h}));
  // Shared cap: the lower cell's top (face 1), centroid (1/3 + s, 1/3, h). Both centres
  // sit at x = 1/3 + s/2, so the line between them is vertical and crosses the cap s/2
  // from its centroid; the cap's extent along x is 2/3: skewness 3s/4. The line is
  // along the cap normal: orthogonal.
  EXPECT_NEAR(face_skewness(lower.faces[1], lower.geo[1], lower.cell.centre, zig.cell.centre), 0.75 * s, kTol);
  EXPECT_NEAR(face_non_orthogonality_deg(lower.geo[1], lower.cell.centre, zig.cell.centre), 0.0, 1e-6);
  // The same shear on both: the centres are (s, 0, h) apart, at atan(s / h) to the
  // cap normal, and the line crosses the cap at its centroid.
  const Lone lean = lone(CellType::kWedge, prism_between({s, 0, h}, {2 * s, 0, 2 * h}));
  EXPECT_NEAR(face_non_orthogonality_deg(lower.geo[1], lower.cell.centre, lean.cell.centre),
              std::atan(s / h) * 180.0 / kPi, 1e-9);
  EXPECT_NEAR(face_skewness(lower.faces[1], lower.geo[1], lower.cell.centre, lean.cell.centre), 0.0, kTol);
}

TEST(SolverAcceptance, WarpOfAQuadIsTheWorseFoldOfItsTwoDiagonalSplits) {
  // Quad (a, b, b', a') with b' = (1, -t, h), h = t = 1. Split along a-b': normals
  // (0, -h, -t) and (-t h, -h, 0), cos = 1/2: 60 degrees. Split along b-a': normals
  // (-t h, -h, -t) and (0, -h, 0), cos = 1/sqrt 3: 54.7 degrees. The worse is 60.
  PolyFace q{4, {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, -1, 1}, Vec3{0, 0, 1}}};
  EXPECT_NEAR(face_warp_deg(q), 60.0, 1e-9);
  PolyFace plane{4, {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 0, 1}, Vec3{0, 0, 1}}};
  EXPECT_NEAR(face_warp_deg(plane), 0.0, kTol);
  PolyFace tri{3, {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, -1, 1}}};
  EXPECT_EQ(face_warp_deg(tri), 0.0);
}

TEST(SolverAcceptance, WarpedPrismPassesTheExactTestButNotTheWarpLimit) {
  // The right prism (h = 1) with b' moved to (1, -t, 1): its side quad y = 0 folds by
  // acos(1 / (1 + t^2)) along a-b' (the normals of the quad above, for t = 1/2: 36.9
  // degrees) and by acos(1 / sqrt(1 + 2 t^2)) = 35.3 degrees along b-a'.
  const double t = 0.5;
  std::vector<Vec3> p = test::right_prism(1.0);
  p[5] = {1, -t, 1};
  ASSERT_EQ(cell_validity(CellType::kWedge, p.data()), Validity::kValid);
  const Lone c = lone(CellType::kWedge, p);
  const double fold = std::acos(1.0 / (1.0 + t * t)) * 180.0 / kPi;
  EXPECT_NEAR(face_warp_deg(c.faces[4]), fold, 1e-9);  // face (2,5,3,0) = (b, b', a', a)
  AcceptanceLimits warp;
  warp.max_face_warp_deg = 30.0;
  EXPECT_EQ(judge_lone_cell(CellType::kWedge, p.data(), warp), AcceptanceFailure::kFaceWarp);
  double worst = 0.0;
  for (const PolyFace& f : c.faces) worst = std::max(worst, face_warp_deg(f));
  warp.max_face_warp_deg = worst;
  EXPECT_EQ(judge_lone_cell(CellType::kWedge, p.data(), warp), AcceptanceFailure::kNone) << "the limit is inclusive";
  EXPECT_LT(face_flatness(c.faces[4], c.geo[4]), 1.0);
  EXPECT_GT(face_flatness(c.faces[4], c.geo[4]), 0.8) << "checkMesh's flatness warning starts near 74 degrees";
}

TEST(SolverAcceptance, ButterflyQuadIsFarFromFlat) {
  // A bow-tie whose lobes have areas 0.327 and 0.227: |S| = 0.1 (the shoelace sum),
  // while the fan about any point covers both lobes, so the flatness is at most
  // 0.1 / 0.555 = 0.18.
  PolyFace bowtie{4, {Vec3{0, 0, 0}, Vec3{1, 1, 0}, Vec3{1, 0, 0}, Vec3{0, 1.2, 0}}};
  const FaceGeometry g = face_geometry(bowtie);
  EXPECT_NEAR(norm(g.area), 0.1, kTol);
  EXPECT_LT(face_flatness(bowtie, g), 0.18);
  EXPECT_GT(face_flatness(bowtie, g), 0.0);
}

TEST(SolverAcceptance, PyramidWithItsApexFarOutsideItsBaseIsValidButSkewed) {
  // Apex (a, 1/2, h) above the base plane: the exact test accepts it for any a. The
  // centre of a pyramid with plane faces is 3/4 base centroid + 1/4 apex, (3/8 + a/4,
  // 1/2, h/4): (a - 1/2) / 4 beside the base centroid, whose extent along x is 1/2.
  const double a = 10.5, h = 1.0;
  std::vector<Vec3> p = test::unit_pyramid(h);
  p[4] = {a, 0.5, h};
  ASSERT_EQ(cell_validity(CellType::kPyramid, p.data()), Validity::kValid);
  const Lone c = lone(CellType::kPyramid, p);
  expect_near(c.cell.centre, {0.375 + a / 4, 0.5, h / 4});
  EXPECT_NEAR(boundary_face_skewness(c.faces[0], c.geo[0], c.cell.centre), (a - 0.5) / 2.0, kTol);
  EXPECT_EQ(judge_lone_cell(CellType::kPyramid, p.data(), only_boundary_skewness(4.0)),
            AcceptanceFailure::kBoundarySkewness);
  // The pyramids and the face tets of this convex cell are all positive.
  AcceptanceLimits decomposition;
  decomposition.face_pyramids = decomposition.face_tets = true;
  EXPECT_EQ(judge_lone_cell(CellType::kPyramid, p.data(), decomposition), AcceptanceFailure::kNone);
}

TEST(SolverAcceptance, FacePyramidAndFaceTetsFailForACentreOutsideTheFace) {
  // A face seen from the wrong side: the centre in front of it.
  std::vector<Vec3> cube = test::unit_hex();
  const Lone c = lone(CellType::kHex, cube);
  const Vec3 outside{0.5, 0.5, -0.5};  // beyond face 0 (z = 0, normal -z)
  EXPECT_LT(face_pyramid_volume(c.geo[0], outside), 0.0);
  EXPECT_LT(face_tet_quality(c.faces[0], outside, nullptr), 0.0);
  AcceptanceLimits decomposition;
  decomposition.face_pyramids = decomposition.face_tets = true;
  EXPECT_EQ(judge_face(c.faces[0], c.geo[0], outside, FaceSide::kBoundary, outside, decomposition),
            AcceptanceFailure::kFacePyramid);
  // As an internal face: the neighbour's centre on the owner's side fails it too.
  EXPECT_EQ(judge_face(c.faces[0], c.geo[0], c.cell.centre, FaceSide::kInternal, c.cell.centre, decomposition),
            AcceptanceFailure::kFacePyramid);
}

TEST(SolverAcceptance, TwistedQuadBetweenTwoCellsHasNoSharedTetDecomposition) {
  // A quad folded along diagonal 0-2 (p1 and p3 raised by z): the split 0-2 is a
  // valley through (1/2, 1/2, 0), the split 1-3 a ridge through (1/2, 1/2, z). A centre
  // between the two on the axis sees only the ridge split from below (owner) and only
  // the valley split from above (neighbour): each side alone decomposes, the two
  // together share no base point (checkMesh's "face tets" error), while both face
  // pyramids about the centre (1/2, 1/2, z/2) are positive.
  const double z = 0.3;
  PolyFace q{4, {Vec3{0, 0, 0}, Vec3{1, 0, z}, Vec3{1, 1, 0}, Vec3{0, 1, z}}};
  // Right-hand normal of this winding is +z: owner below, neighbour above.
  const Vec3 below{0.5, 0.5, 0.1}, above{0.5, 0.5, 0.2};
  EXPECT_GT(face_tet_quality(q, below, nullptr), 0.0);
  PolyFace reversed{4, {q.p[0], q.p[3], q.p[2], q.p[1]}};
  EXPECT_GT(face_tet_quality(reversed, above, nullptr), 0.0);
  EXPECT_LT(face_tet_quality(q, below, &above), 0.0);
  AcceptanceLimits decomposition;
  decomposition.face_pyramids = decomposition.face_tets = true;
  const FaceGeometry g = face_geometry(q);
  EXPECT_GT(face_pyramid_volume(g, below), 0.0);
  EXPECT_LT(face_pyramid_volume(g, above), 0.0);
  EXPECT_EQ(judge_face(q, g, below, FaceSide::kInternal, above, decomposition), AcceptanceFailure::kFaceTets);
  EXPECT_EQ(judge_face(q, g, below, FaceSide::kBoundary, above, decomposition), AcceptanceFailure::kNone);
}

TEST(SolverAcceptance, AFaceWhoseTetsTheJudgeAcceptsHasEveryCheckMeshTetPositive) {
  // Random triangles and quads (warped up to the size of the face) with random centres
  // on either side: the judge's face-tet verdict (its early exits, and the base tet
  // alone for triangles) against every tet checkMesh looks at, computed in full.
  testing::Lcg rng(3);
  auto jitter = [&](double r) {
    return Vec3{r * (rng.uniform() - 0.5), r * (rng.uniform() - 0.5), r * (rng.uniform() - 0.5)};
  };
  AcceptanceLimits tets;
  tets.face_tets = true;
  int n_accepted = 0, n_refused = 0;
  for (int i = 0; i < 20000; ++i) {
    PolyFace f;
    f.n = i % 2 ? 4 : 3;
    const Vec3 square[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (int k = 0; k < f.n; ++k) f.p[k] = square[k] + jitter(0.6);
    const FaceGeometry g = face_geometry(f);
    const Vec3 own = Vec3{0.5, 0.5, -0.3} + jitter(0.8), nei = Vec3{0.5, 0.5, 0.3} + jitter(0.8);
    const bool internal = i % 3 != 0;
    const FaceSide side = internal ? FaceSide::kInternal : FaceSide::kBoundary;
    const bool judged = judge_face(f, g, own, side, nei, tets) == AcceptanceFailure::kNone;
    const bool check_mesh = face_centre_tet_quality(f, g, own) > 1e-30 &&
                            (!internal || face_centre_tet_quality(reversed(f), g, nei) > 1e-30) &&
                            face_tet_quality(f, own, internal ? &nei : nullptr) > 1e-30;
    EXPECT_TRUE(!judged || check_mesh) << "face " << i << ": accepted here, refused by checkMesh";
    (judged ? n_accepted : n_refused)++;
  }
  EXPECT_GT(n_accepted, 1000);
  EXPECT_GT(n_refused, 1000);
}

// A w x L rectangle split along its diagonal (0,0)-(w,L): the centroids' line crosses
// the diagonal at an angle whose cosine is 2 w L / (w^2 + L^2), whatever the plane the
// rectangle lies in. Near 0 degrees acos loses half the digits: 1e-16 in the cosine is
// 1.5e-8 rad, so the tolerance is 2e-6 degrees.
TEST(SolverAcceptance, WallEdgeNonOrthogonalityOfASplitRectangleIsInClosedForm) {
  for (double w : {1.0, 0.1, 1e-3, 5e-5}) {
    const double L = 1.0;
    const Vec3 a0{0, 0, 0}, b0{w, 0, 0}, a1{0, L, 0}, b1{w, L, 0};
    const double expected = std::acos(2.0 * w * L / (w * w + L * L)) * 180.0 / M_PI;
    EXPECT_NEAR(wall_edge_non_orthogonality_deg({a0, b0, b1}, {a0, b1, a1}, a0, b1), expected, 2e-6) << w;
    EXPECT_NEAR(wall_edge_non_orthogonality_deg({a0, b1, a1}, {a0, b0, b1}, b1, a0), expected, 2e-6) << w;
  }
  // The square's diagonal is crossed at right angles by its centroids' line.
  using Corners = std::array<Vec3, 3>;
  EXPECT_NEAR(wall_edge_non_orthogonality_deg(Corners{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}},
                                              Corners{{{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}}, {0, 0, 0}, {1, 1, 0}),
              0.0, 1e-6);
}

TEST(SolverAcceptance, InheritedLimitWidensOnlyNearTheLimitAndNeverToCheckMeshsError) {
  const double deg = 180.0 / M_PI;
  EXPECT_EQ(inherited_non_orthogonality_limit_deg(89.99, 30.0), 89.99);
  EXPECT_EQ(inherited_non_orthogonality_limit_deg(89.99, 89.9), 89.99);  // cos / 2 = 8.7e-4: 89.95
  EXPECT_NEAR(inherited_non_orthogonality_limit_deg(89.99, std::acos(1e-4) * deg), std::acos(5e-5) * deg, 1e-9);
  EXPECT_NEAR(inherited_non_orthogonality_limit_deg(70.0, std::acos(1e-4) * deg), std::acos(5e-5) * deg, 1e-9);
  const double error_side = std::acos(kMinNonOrthogonalityCosine) * deg;
  EXPECT_EQ(inherited_non_orthogonality_limit_deg(89.99, 90.0), error_side);
  EXPECT_EQ(inherited_non_orthogonality_limit_deg(89.99, 120.0), error_side);
  EXPECT_LT(error_side, 90.0);
  EXPECT_EQ(inherited_non_orthogonality_limit_deg(0.0, 89.999), 0.0);  // off stays off
}

TEST(SolverAcceptance, InheritedLimitBelowSixtyKeepsTheLimitOverFlatWallEdges) {
  const double deg = 180.0 / M_PI;
  // A flat wall edge widens nothing (half its cosine would give 60 degrees).
  EXPECT_EQ(inherited_non_orthogonality_limit_deg(50.0, 0.0), 50.0);
  EXPECT_EQ(inherited_non_orthogonality_limit_deg(30.0, 0.0), 30.0);
  // A leaning one widens L to the angle of cosine cos L cos i.
  const double c50 = std::cos(50.0 / deg), c40 = std::cos(40.0 / deg);
  EXPECT_NEAR(inherited_non_orthogonality_limit_deg(50.0, 40.0), std::acos(c50 * c40) * deg, 1e-9);
  // The two rules meet at 60 degrees.
  EXPECT_NEAR(inherited_non_orthogonality_limit_deg(60.0, 40.0), std::acos(0.5 * c40) * deg, 1e-9);
}

TEST(SolverAcceptance, LimitsOfZeroJudgeNothing) {
  std::vector<Vec3> p = sheared_prism(1.0, {100.0, 0, 0});
  EXPECT_FALSE(AcceptanceLimits{}.any());
  EXPECT_EQ(judge_lone_cell(CellType::kWedge, p.data(), AcceptanceLimits{}), AcceptanceFailure::kNone);
  EXPECT_STREQ(acceptance_failure_name(AcceptanceFailure::kFaceTets), "face_tets");
}

}  // namespace
}  // namespace blayer
