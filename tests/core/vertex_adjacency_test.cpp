#include "blayer/core/vertex_adjacency.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "analytic_surfaces.h"

namespace blayer {
namespace {

// Oracles: scan every triangle for every vertex.
std::vector<int> brute_force_triangles(const TriSurface& s, int v) {
  std::vector<int> out;
  for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f)
    for (int u : s.triangles[f])
      if (u == v) out.push_back(f);
  return out;
}

std::vector<int> brute_force_neighbours(const TriSurface& s, int v) {
  std::set<int> out;
  for (const Triangle& t : s.triangles)
    if (std::count(t.begin(), t.end(), v) > 0)
      for (int u : t)
        if (u != v) out.insert(u);
  return {out.begin(), out.end()};
}

void expect_tables_match_brute_force(const TriSurface& s) {
  const CsrTable vtri = vertex_triangles(s);
  const CsrTable nbr = vertex_neighbours(s, vtri);
  ASSERT_EQ(vtri.n_rows(), static_cast<int>(s.points.size()));
  ASSERT_EQ(nbr.n_rows(), static_cast<int>(s.points.size()));
  for (int v = 0; v < vtri.n_rows(); ++v) {
    EXPECT_EQ(std::vector<int>(vtri.begin(v), vtri.end(v)), brute_force_triangles(s, v)) << "vertex " << v;
    EXPECT_EQ(std::vector<int>(nbr.begin(v), nbr.end(v)), brute_force_neighbours(s, v)) << "vertex " << v;
    EXPECT_EQ(vtri.count(v), vtri.end(v) - vtri.begin(v));
  }
}

TEST(VertexAdjacency, MatchesBruteForceOnClosedSurfaces) {
  expect_tables_match_brute_force(test_surfaces::icosphere(2));
  expect_tables_match_brute_force(test_surfaces::box({0, 0, 0}, {2, 1, 1}, 3));
}

TEST(VertexAdjacency, OpenSurfaceAndUnusedPointsGetTheirOwnRows) {
  TriSurface s = test_surfaces::icosphere(1);
  s.triangles.pop_back();
  s.points.push_back({9, 9, 9});  // used by no triangle
  expect_tables_match_brute_force(s);
  const CsrTable vtri = vertex_triangles(s);
  EXPECT_EQ(vtri.count(static_cast<int>(s.points.size()) - 1), 0);
}

TEST(VertexAdjacency, ValenceOfTheIcosahedronIsFive) {
  const TriSurface s = test_surfaces::icosphere(0);
  const CsrTable nbr = vertex_neighbours(s, vertex_triangles(s));
  for (int v = 0; v < nbr.n_rows(); ++v) EXPECT_EQ(nbr.count(v), 5) << v;
}

TEST(VertexAdjacency, TriangleIndexOutsideThePointsIsAProgrammerError) {
  TriSurface s = test_surfaces::icosphere(0);
  s.triangles[3][1] = 99;
  EXPECT_THROW(vertex_triangles(s), std::logic_error);
}

}  // namespace
}  // namespace blayer
