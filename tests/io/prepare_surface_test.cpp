#include <gtest/gtest.h>

#include <cmath>

#include "blayer/core/errors.h"
#include "blayer/io/prepare_surface.h"

namespace blayer {
namespace {

// Closed unit tetrahedron, outward.
PolygonSoup tetra() {
  return {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
}

// Expects prepare_surface to fail with a message naming the file, the kind of problem
// and the offending element.
void expect_rejected(const PolygonSoup& soup, const std::string& kind, const std::string& element,
                     PrepareOptions opt = {}) {
  try {
    prepare_surface(soup, "body.stl", opt);
    ADD_FAILURE() << "accepted a surface with " << kind;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("body.stl", 0), 0u) << msg;
    EXPECT_NE(msg.find(kind), std::string::npos) << msg;
    EXPECT_NE(msg.find(element), std::string::npos) << msg;
  }
}

TEST(PrepareSurface, AcceptsAClosedOutwardTetrahedronUnchanged) {
  const PreparedSurface p = prepare_surface(tetra(), "t.off", {});
  EXPECT_TRUE(p.closed);
  EXPECT_EQ(p.n_flipped_components, 0);
  EXPECT_TRUE(p.notes.empty());
  EXPECT_EQ(p.surface.triangles[0], (Triangle{0, 2, 1}));
  EXPECT_NEAR(p.enclosed_volume, 1.0 / 6.0, 1e-15);
}

TEST(PrepareSurface, FlipsAnInwardSurfaceForExternalFlowAndSaysSo) {
  PolygonSoup s = tetra();
  for (auto& f : s.faces) std::swap(f[1], f[2]);
  const PreparedSurface p = prepare_surface(s, "t.off", {});
  EXPECT_EQ(p.n_flipped_components, 1);
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("flipped"), std::string::npos);
  EXPECT_GT(signed_volume(p.surface), 0.0);
}

TEST(PrepareSurface, InwardSideOrientsNormalsIntoTheVolume) {
  PrepareOptions opt;
  opt.side = Side::kInward;
  const PreparedSurface p = prepare_surface(tetra(), "t.off", opt);
  EXPECT_EQ(p.n_flipped_components, 1);
  EXPECT_LT(signed_volume(p.surface), 0.0);
}

TEST(PrepareSurface, OrientsEachClosedComponentOnItsOwn) {
  PolygonSoup s = tetra();
  const PolygonSoup t = tetra();
  for (const Vec3& p : t.points) s.points.push_back(p + Vec3{5, 0, 0});
  for (auto f : t.faces) {
    for (int& v : f) v += 4;
    std::swap(f[1], f[2]);  // second body inside out
    s.faces.push_back(f);
  }
  const PreparedSurface p = prepare_surface(s, "two.off", {});
  EXPECT_EQ(p.n_components, 2);
  EXPECT_EQ(p.n_flipped_components, 1);
  EXPECT_NEAR(signed_volume(p.surface), 2.0 / 6.0, 1e-12);
}

TEST(PrepareSurface, TriangulatesPolygonsAndSaysSo) {
  // Unit cube with quad faces, outward.
  PolygonSoup cube{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
                   {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  const PreparedSurface p = prepare_surface(cube, "cube.obj", {});
  EXPECT_EQ(p.surface.triangles.size(), 12u);
  ASSERT_FALSE(p.notes.empty());
  EXPECT_NE(p.notes[0].find("triangulated 6 polygons"), std::string::npos);
  EXPECT_NEAR(signed_volume(p.surface), 1.0, 1e-14);
}

TEST(PrepareSurface, RejectsNoFaces) {
  expect_rejected({{{0, 0, 0}}, {}}, "no faces", "");
}

TEST(PrepareSurface, RejectsNonFiniteCoordinatesNamingTheVertex) {
  PolygonSoup s = tetra();
  s.points[2][1] = std::nan("");
  expect_rejected(s, "non-finite coordinates", "vertex 2");
  s.points[2][1] = INFINITY;
  expect_rejected(s, "non-finite coordinates", "vertex 2");
}

TEST(PrepareSurface, RejectsOutOfRangeIndices) {
  PolygonSoup s = tetra();
  s.faces[3][1] = 7;
  expect_rejected(s, "out of range", "face 3 refers to vertex 7");
}

TEST(PrepareSurface, RejectsFacesWithTooFewVertices) {
  PolygonSoup s = tetra();
  s.faces.push_back({0, 1});
  expect_rejected(s, "fewer than 3 vertices", "face 4");
}

TEST(PrepareSurface, RejectsRepeatedVertexInAFace) {
  PolygonSoup s = tetra();
  s.faces[1] = {0, 1, 1};
  expect_rejected(s, "degenerate faces", "face 1 uses vertex 1");
}

TEST(PrepareSurface, RejectsZeroAreaTriangles) {
  PolygonSoup s = tetra();
  s.points.push_back({0.5, 0.5, 0});  // on edge 1-2 of the base
  // Base and side split at point 4 on edge 1-2, plus the collinear triangle (1,4,2).
  s.faces = {{0, 2, 4}, {0, 4, 1}, {0, 1, 3}, {1, 4, 3}, {4, 2, 3}, {0, 3, 2}, {1, 4, 2}};
  expect_rejected(s, "degenerate (zero-area) triangles", "triangle 6");
}

TEST(PrepareSurface, RejectsDuplicateTriangles) {
  PolygonSoup s = tetra();
  s.faces.push_back({2, 1, 0});
  expect_rejected(s, "duplicate triangles", "triangle 4");
}

TEST(PrepareSurface, RejectsNonManifoldEdges) {
  PolygonSoup s = tetra();
  s.points.push_back({0.3, -1, 0.3});
  s.faces.push_back({0, 1, 4});  // a fin on edge (0,1)
  expect_rejected(s, "non-manifold edges", "edge (0, 1) is shared by 3 triangles");
}

TEST(PrepareSurface, RejectsHolesUnlessOpenSurfacesAreAllowed) {
  PolygonSoup s = tetra();
  s.faces.pop_back();
  s.faces.pop_back();  // two faces missing: the hole's rim is not planar (one planar loop is a half model's cut)
  expect_rejected(s, "open boundary edges (holes)", "has no neighbour");
  PrepareOptions open;
  open.allow_open = true;
  const PreparedSurface p = prepare_surface(s, "open.off", open);
  EXPECT_FALSE(p.closed);
  EXPECT_EQ(p.surface.triangles.size(), 2u);
}

TEST(PrepareSurface, RejectsInconsistentOrientation) {
  PolygonSoup s = tetra();
  std::swap(s.faces[2][1], s.faces[2][2]);
  expect_rejected(s, "inconsistent orientation", "triangle 2");
}

TEST(PrepareSurface, RejectsNonManifoldVertices) {
  // Two tetrahedra touching at vertex 0 only.
  PolygonSoup s = tetra();
  const PolygonSoup t = tetra();
  s.points.push_back({-1, 0, 0});
  s.points.push_back({0, -1, 0});
  s.points.push_back({0, 0, -1});
  // Mirror of the tetra through the origin, sharing vertex 0; mirroring reverses
  // orientation, so reverse the winding too.
  for (auto f : t.faces) {
    for (int& v : f)
      if (v != 0) v += 3;
    std::swap(f[1], f[2]);
    s.faces.push_back(f);
  }
  expect_rejected(s, "non-manifold vertices", "vertex 0");
}

TEST(PrepareSurface, RejectsUnusedVertices) {
  PolygonSoup s = tetra();
  s.points.push_back({9, 9, 9});
  expect_rejected(s, "unused vertices", "vertex 4");
}

TEST(PrepareSurface, RejectsAFlatClosedSurface) {
  // A unit square triangulated along one diagonal on top and the other below: closed,
  // manifold, consistently oriented, and enclosing no volume.
  PolygonSoup s{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}, {1, 0, 3}, {1, 3, 2}}};
  expect_rejected(s, "enclosing no volume", "component 0");
}

// Edge problems are listed by edge (lower point, then higher point), so one input
// gives one message on every run and platform.
TEST(PrepareSurface, ListsEdgeProblemsInEdgeOrder) {
  PolygonSoup s = tetra();
  s.faces.erase(s.faces.begin() + 1);  // triangle (0, 1, 3) missing: three open edges
  PrepareOptions no_symmetry;  // (their triangle would be a half model's cut)
  no_symmetry.symmetry.mode = SymmetryMode::kNone;
  try {
    prepare_surface(s, "body.stl", no_symmetry);
    FAIL() << "accepted a surface with a hole";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    const std::size_t a = msg.find("edge (0, 1)"), b = msg.find("edge (0, 3)"), c = msg.find("edge (1, 3)");
    ASSERT_NE(a, std::string::npos) << msg;
    ASSERT_NE(b, std::string::npos) << msg;
    ASSERT_NE(c, std::string::npos) << msg;
    EXPECT_LT(a, b) << msg;
    EXPECT_LT(b, c) << msg;
  }
}

}  // namespace
}  // namespace blayer
