#include "blayer/io/mesh_faces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "blayer/core/errors.h"
#include "blayer/quality/mesh_check.h"
#include "grid_meshes.h"
#include "mixed_mesh.h"

namespace blayer {
namespace {

using testing::GridCell;
using Key = std::vector<std::int64_t>;

template <class Id>
Vec3 centroid(const VolumeMesh& m, const Id* nodes, int n) {
  Vec3 c{0, 0, 0};
  for (int k = 0; k < n; ++k) c += m.points[nodes[k]];
  return c / double(n);
}

// Area vector of a polygon (sum of fan cross products, exact for planar faces).
template <class Id>
Vec3 area_vector(const VolumeMesh& m, const Id* nodes, int n) {
  Vec3 a{0, 0, 0};
  for (int k = 1; k + 1 < n; ++k)
    a += 0.5 * cross(m.points[nodes[k]] - m.points[nodes[0]], m.points[nodes[k + 1]] - m.points[nodes[0]]);
  return a;
}

TEST(CellFaceTable, EveryLocalFacePointsOutOfItsCellAndTheFacesClose) {
  const VolumeMesh m = testing::mixed_mesh();
  ASSERT_TRUE(check_volume_mesh(m).totals.inverted == 0);  // the oracle's cells are positive
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const PointId* corners = m.cell_nodes(c);
    const Vec3 cell_centre = centroid(m, corners, corner_count(m.cell_types[c]));
    const CellFaceTable& t = cell_face_table(m.cell_types[c]);
    Vec3 closure{0, 0, 0};
    std::vector<int> uses(corner_count(m.cell_types[c]), 0);
    for (int f = 0; f < t.n_faces; ++f) {
      std::int64_t nodes[4];
      for (int k = 0; k < t.n_corners[f]; ++k) nodes[k] = corners[t.corners[f][k]], ++uses[t.corners[f][k]];
      const Vec3 a = area_vector(m, nodes, t.n_corners[f]);
      EXPECT_GT(dot(a, centroid(m, nodes, t.n_corners[f]) - cell_centre), 0.0)
          << cell_type_name(m.cell_types[c]) << " face " << f;
      closure += a;
    }
    EXPECT_NEAR(norm(closure), 0.0, 1e-12) << cell_type_name(m.cell_types[c]);
    // Every corner is on 3 faces, except a pyramid's apex (corner 4), on 4.
    for (std::size_t k = 0; k < uses.size(); ++k)
      EXPECT_EQ(uses[k], m.cell_types[c] == CellType::kPyramid && k == 4 ? 4 : 3) << cell_type_name(m.cell_types[c]);
  }
}

TEST(MeshFaces, TwoTetsSharingAFaceHaveOneInternalFaceFromTheLowerCell) {
  VolumeMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::int64_t a[4] = {0, 1, 2, 3}, b[4] = {0, 2, 1, 4};
  m.add_cell(CellType::kTet, a);
  m.add_cell(CellType::kTet, b);
  const MeshFaces f = build_mesh_faces(m);
  ASSERT_EQ(f.size(), 7u);
  ASSERT_EQ(f.n_internal, 1u);
  EXPECT_EQ(f.owner[0], 0);
  EXPECT_EQ(f.neighbour[0], 1);
  // The shared face z = 0 points from cell 0 (above) to cell 1 (below).
  EXPECT_LT(area_vector(m, f.nodes[0].data(), 3)[2], 0.0);
  for (std::size_t i = 1; i < f.size(); ++i) EXPECT_EQ(f.neighbour[i], -1);
}

// Brute force: every cell face keyed by its sorted nodes in a map.
void expect_matches_brute_force(const VolumeMesh& m) {
  std::map<Key, std::vector<std::int64_t>> cells_of_face;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const CellFaceTable& t = cell_face_table(m.cell_types[c]);
    for (int f = 0; f < t.n_faces; ++f) {
      Key k;
      for (int i = 0; i < t.n_corners[f]; ++i) k.push_back(m.connectivity[m.offsets[c] + t.corners[f][i]]);
      std::sort(k.begin(), k.end());
      cells_of_face[k].push_back(static_cast<std::int64_t>(c));
    }
  }
  const MeshFaces faces = build_mesh_faces(m);
  ASSERT_EQ(faces.size(), cells_of_face.size());
  std::size_t n_internal = 0;
  for (const auto& [k, cells] : cells_of_face) n_internal += cells.size() == 2;
  EXPECT_EQ(faces.n_internal, n_internal);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    Key k(faces.nodes[i].begin(), faces.nodes[i].begin() + faces.n_nodes[i]);
    std::sort(k.begin(), k.end());
    auto it = cells_of_face.find(k);
    ASSERT_NE(it, cells_of_face.end());
    if (i < faces.n_internal) {
      EXPECT_EQ(faces.owner[i], std::min(it->second[0], it->second[1]));
      EXPECT_EQ(faces.neighbour[i], std::max(it->second[0], it->second[1]));
      if (i > 0) {  // upper triangular
        EXPECT_LT(std::make_pair(faces.owner[i - 1], faces.neighbour[i - 1]),
                  std::make_pair(faces.owner[i], faces.neighbour[i]));
      }
    } else {
      EXPECT_EQ(faces.neighbour[i], -1);
      EXPECT_EQ(faces.owner[i], it->second[0]);
    }
    // Oriented out of the owner: towards the neighbour's centre, away from the owner's.
    const PointId* own = m.cell_nodes(faces.owner[i]);
    const Vec3 a = area_vector(m, faces.nodes[i].data(), faces.n_nodes[i]);
    const Vec3 fc = centroid(m, faces.nodes[i].data(), faces.n_nodes[i]);
    EXPECT_GT(dot(a, fc - centroid(m, own, corner_count(m.cell_types[faces.owner[i]]))), 0.0) << "face " << i;
  }
}

std::string grid_cell_name(const ::testing::TestParamInfo<GridCell>& info) {
  static const char* const names[] = {"hexes", "wedges", "pyramids", "tets"};
  return names[static_cast<int>(info.param)];
}

class MeshFacesOnGrids : public ::testing::TestWithParam<GridCell> {};

TEST_P(MeshFacesOnGrids, MatchBruteForceOwnerNeighbourAndOrientation) {
  const VolumeMesh m = testing::grid_mesh(3, 2, 2, GetParam());
  ASSERT_TRUE(check_volume_mesh(m).ok());
  expect_matches_brute_force(m);
}

INSTANTIATE_TEST_SUITE_P(EveryCellType, MeshFacesOnGrids,
                         ::testing::Values(GridCell::kHex, GridCell::kWedges, GridCell::kPyramids, GridCell::kTets),
                         grid_cell_name);

TEST(MeshFaces, MixedGridMatchesBruteForce) {
  const VolumeMesh m = testing::mixed_grid_mesh(3, 2, 3);
  ASSERT_TRUE(check_volume_mesh(m).ok());
  expect_matches_brute_force(m);
}

TEST(MeshFaces, CubeGridCountsAreTheAnalyticOnes) {
  // n^3 hexes: 3 n^2 (n+1) faces, of which 6 n^2 on the boundary.
  const int n = 4;
  const MeshFaces f = build_mesh_faces(testing::grid_mesh(n, n, n, GridCell::kHex));
  EXPECT_EQ(f.size(), std::size_t(3 * n * n * (n + 1)));
  EXPECT_EQ(f.n_boundary(), std::size_t(6 * n * n));
}

TEST(MeshFaces, AFaceSharedByThreeCellsIsAnErrorNamingThem) {
  VolumeMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0, 0, 2}};
  const std::int64_t a[4] = {0, 1, 2, 3}, b[4] = {0, 2, 1, 4}, c[4] = {0, 1, 2, 5};
  m.add_cell(CellType::kTet, a);
  m.add_cell(CellType::kTet, b);
  m.add_cell(CellType::kTet, c);
  try {
    build_mesh_faces(m);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than two cells"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nodes 0 1 2"), std::string::npos) << e.what();
  }
}

TEST(MeshFaces, ACellFaceWithARepeatedNodeIsAnError) {
  VolumeMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::int64_t a[4] = {0, 1, 1, 3};
  m.add_cell(CellType::kTet, a);
  EXPECT_THROW(build_mesh_faces(m), InputError);
}

TEST(QuadHalves, EachDiagonalSplitsTheQuadIntoTwoSortedTrianglesSharingIt) {
  const std::array<std::int64_t, 4> q{7, 3, 9, 5};
  const auto d0 = quad_halves(q, 0);  // diagonal 7-9
  EXPECT_EQ(d0[0], (TriangleKey{3, 7, 9}));
  EXPECT_EQ(d0[1], (TriangleKey{5, 7, 9}));
  const auto d1 = quad_halves(q, 1);  // diagonal 3-5
  EXPECT_EQ(d1[0], (TriangleKey{3, 5, 9}));
  EXPECT_EQ(d1[1], (TriangleKey{3, 5, 7}));
  EXPECT_EQ(sorted_triangle(4, -1, 2), (TriangleKey{-1, 2, 4}));
}

}  // namespace
}  // namespace blayer
