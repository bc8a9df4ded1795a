#include "blayer/io/solver_mesh.h"

#include <gtest/gtest.h>

#include "blayer/core/errors.h"
#include "grid_meshes.h"

namespace blayer {
namespace {

using testing::GridCell;

// The bottom (z = 0) boundary triangles of a wedge grid, as a listed patch.
PatchTriangles bottom_triangles(const VolumeMesh& m, const std::string& name) {
  PatchTriangles p{name, PatchKind::kWall, {}};
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const PointId* n = m.cell_nodes(c);
    if (m.points[n[0]][2] == 0.0 && m.points[n[1]][2] == 0.0 && m.points[n[2]][2] == 0.0)
      p.triangles.push_back({n[0], n[1], n[2]});
  }
  return p;
}

TEST(SolverMesh, ListedTrianglesFormTheirPatchAndEveryOtherBoundaryFaceTheRest) {
  const VolumeMesh m = testing::grid_mesh(3, 2, 2, GridCell::kWedges);
  const SolverMesh s = make_solver_mesh(m, {bottom_triangles(m, "floor")}, "rest");
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_EQ(s.patches[0].name, "floor");
  EXPECT_EQ(s.patches[0].size, 12u);  // 3 x 2 cubes, two triangles each
  EXPECT_EQ(s.patches[1].name, "rest");
  EXPECT_EQ(s.patches[1].kind, PatchKind::kOpen);
  // Every boundary face in exactly one patch, the patches contiguous and in order.
  EXPECT_EQ(s.patches[0].start, s.faces.n_internal);
  EXPECT_EQ(s.patches[1].start, s.patches[0].start + s.patches[0].size);
  EXPECT_EQ(s.patches[1].start + s.patches[1].size, s.faces.size());
  for (std::size_t f = s.patches[0].start; f < s.patches[0].start + s.patches[0].size; ++f) {
    EXPECT_EQ(s.faces.n_nodes[f], 3);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(s.cells.points[s.faces.nodes[f][k]][2], 0.0);
  }
}

TEST(SolverMesh, PatchesWithNoFaceAreDroppedAndTheFirstListingWins) {
  const VolumeMesh m = testing::grid_mesh(2, 2, 1, GridCell::kWedges);
  PatchTriangles none{"unused", PatchKind::kSymmetry, {}};
  const SolverMesh s = make_solver_mesh(m, {bottom_triangles(m, "first"), none, bottom_triangles(m, "second")}, "rest");
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_EQ(s.patches[0].name, "first");
  EXPECT_EQ(s.patches[1].name, "rest");
}

TEST(SolverMesh, PointsNoCellUsesAreDroppedAndTheCellsRenumbered) {
  VolumeMesh m = testing::grid_mesh(1, 1, 1, GridCell::kHex);
  m.points.insert(m.points.begin(), Vec3{9, 9, 9});  // an unused point 0
  for (PointId& p : m.connectivity) ++p;
  const SolverMesh s = make_solver_mesh(m, {}, "rest");
  EXPECT_EQ(s.cells.points.size(), 8u);
  EXPECT_EQ(s.point_of_input[0], -1);
  EXPECT_EQ(s.point_of_input[1], 0);
  EXPECT_EQ(s.cells.points[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(s.n_cells_of(CellType::kHex), 1u);
  EXPECT_EQ(s.patches.size(), 1u);
  EXPECT_EQ(s.patches[0].size, 6u);
}

TEST(SolverMesh, AQuadFaceJoinsThePatchThatListsBothItsHalves) {
  const VolumeMesh m = testing::grid_mesh(2, 1, 1, GridCell::kHex);
  // The top (z = 1) quads of the two hexes: one listed along each diagonal, and one
  // half of a third quad that is not a face (the patch must not take a quad by half).
  PatchTriangles top{"top", PatchKind::kOpen, {}};
  int n_top = 0;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const PointId* n = m.cell_nodes(c) + 4;  // VTK hex top 4..7
    if (n_top++ == 0)
      top.triangles.insert(top.triangles.end(), {{n[0], n[1], n[2]}, {n[2], n[3], n[0]}});
    else
      top.triangles.insert(top.triangles.end(), {{n[1], n[2], n[3]}, {n[3], n[0], n[1]}});
  }
  PatchTriangles half{"half", PatchKind::kWall, {}};
  const PointId* b = m.cell_nodes(0);  // the first hex's bottom
  half.triangles.push_back({b[0], b[1], b[2]});
  const SolverMesh s = make_solver_mesh(m, {top, half}, "rest");
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_EQ(s.patches[0].name, "top");
  EXPECT_EQ(s.patches[0].size, 2u);
  EXPECT_EQ(s.patches[1].name, "rest");
  EXPECT_EQ(s.patches[1].size, 8u);
  for (std::size_t f = s.patches[0].start; f < s.patches[0].start + s.patches[0].size; ++f) {
    EXPECT_EQ(s.faces.n_nodes[f], 4);
    for (int k = 0; k < 4; ++k) EXPECT_EQ(s.cells.points[s.faces.nodes[f][k]][2], 1.0);
  }
}

TEST(SolverMesh, TwoPatchesWithOneNameAreRejected) {
  const VolumeMesh m = testing::grid_mesh(1, 1, 1, GridCell::kWedges);
  EXPECT_THROW(make_solver_mesh(m, {bottom_triangles(m, "wall"), bottom_triangles(m, "wall")}, "rest"), InputError);
  EXPECT_THROW(make_solver_mesh(m, {bottom_triangles(m, "rest")}, "rest"), InputError);
}

TEST(WallPatches, OneComponentIsWallAndSeveralAreNumberedFromOne) {
  TriSurface one;
  one.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  one.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const std::vector<PatchTriangles> a = wall_patches(one);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_EQ(a[0].name, "wall");
  EXPECT_EQ(a[0].triangles.size(), 4u);

  TriSurface two = one;
  for (const Vec3& p : one.points) two.points.push_back(p + Vec3{5, 0, 0});
  for (const Triangle& t : one.triangles) two.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  const std::vector<PatchTriangles> b = wall_patches(two);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].name, "wall_1");
  EXPECT_EQ(b[1].name, "wall_2");
  EXPECT_EQ(b[1].triangles[0], (std::array<std::int64_t, 3>{4, 6, 5}));
}

TEST(PatchTrianglesOf, MapsThePointsThroughTheGivenIds) {
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  s.triangles = {{0, 1, 2}};
  const PatchTriangles p = patch_triangles("bl_outer", PatchKind::kOpen, s, {10, 11, 12});
  EXPECT_EQ(p.triangles[0], (std::array<std::int64_t, 3>{10, 11, 12}));
}

}  // namespace
}  // namespace blayer
