#include "blayer/core/edge_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <utility>

#include "analytic_surfaces.h"

namespace blayer {
namespace {

// Oracle: an ordered map from the undirected edge to its directed uses.
struct Counts {
  int n_edges = 0, boundary = 0, non_manifold = 0, inconsistent = 0;
};
Counts brute_force_counts(const TriSurface& s) {
  std::map<std::pair<int, int>, std::vector<bool>> uses;
  for (const Triangle& t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      uses[{std::min(a, b), std::max(a, b)}].push_back(a < b);
    }
  Counts c;
  for (const auto& [edge, dirs] : uses) {
    ++c.n_edges;
    if (dirs.size() == 1) ++c.boundary;
    if (dirs.size() > 2) ++c.non_manifold;
    if (dirs.size() == 2 && dirs[0] == dirs[1]) ++c.inconsistent;
  }
  return c;
}

void expect_counts_match_brute_force(const TriSurface& s) {
  const EdgeTopology e = build_edge_topology(s);
  const Counts c = brute_force_counts(s);
  EXPECT_EQ(static_cast<int>(e.edges.size()), c.n_edges);
  EXPECT_EQ(e.n_boundary, c.boundary);
  EXPECT_EQ(e.n_non_manifold, c.non_manifold);
  EXPECT_EQ(e.n_inconsistent, c.inconsistent);
  for (std::size_t i = 1; i < e.edges.size(); ++i)
    EXPECT_LT(std::make_pair(e.edges[i - 1].lo, e.edges[i - 1].hi), std::make_pair(e.edges[i].lo, e.edges[i].hi));
}

TEST(EdgeTopology, ClosedOrientedSurfaceHasOnlyManifoldEdges) {
  const TriSurface s = test_surfaces::icosphere(2);
  const EdgeTopology e = build_edge_topology(s);
  EXPECT_TRUE(e.closed_manifold_oriented());
  EXPECT_EQ(e.edges.size(), 3 * s.triangles.size() / 2);  // Euler: E = 3F/2 when closed
  for (const SurfaceEdge& edge : e.edges) {
    EXPECT_EQ(edge.kind, EdgeKind::kManifold);
    EXPECT_LT(edge.lo, edge.hi);
    EXPECT_LT(edge.triangle[0], edge.triangle[1]);
    EXPECT_NE(edge.forward[0], edge.forward[1]);
  }
  expect_counts_match_brute_force(s);
}

TEST(EdgeTopology, MissingTriangleLeavesThreeBoundaryEdges) {
  TriSurface s = test_surfaces::icosphere(1);
  s.triangles.pop_back();
  const EdgeTopology e = build_edge_topology(s);
  EXPECT_EQ(e.n_boundary, 3);
  EXPECT_EQ(e.n_non_manifold + e.n_inconsistent, 0);
  expect_counts_match_brute_force(s);
}

TEST(EdgeTopology, FlippedTriangleMakesItsThreeEdgesInconsistent) {
  TriSurface s = test_surfaces::icosphere(1);
  std::swap(s.triangles[5][1], s.triangles[5][2]);
  const EdgeTopology e = build_edge_topology(s);
  EXPECT_EQ(e.n_inconsistent, 3);
  for (const SurfaceEdge& edge : e.edges)
    if (edge.kind == EdgeKind::kInconsistent) {
      EXPECT_TRUE(edge.triangle[0] == 5 || edge.triangle[1] == 5);
    }
  expect_counts_match_brute_force(s);
}

TEST(EdgeTopology, FinOnAnEdgeMakesItNonManifold) {
  TriSurface s = test_surfaces::icosphere(1);
  const Triangle t = s.triangles[0];
  s.points.push_back({3, 3, 3});
  s.triangles.push_back({t[0], t[1], static_cast<int>(s.points.size()) - 1});
  const EdgeTopology e = build_edge_topology(s);
  EXPECT_EQ(e.n_non_manifold, 1);
  EXPECT_EQ(e.n_boundary, 2);  // the fin's two free edges
  expect_counts_match_brute_force(s);
}

TEST(EdgeTopology, OpenSurfacesMatchBruteForce) {
  TriSurface s = test_surfaces::box({0, 0, 0}, {1, 1, 1}, 3);
  s.triangles.erase(s.triangles.begin(), s.triangles.begin() + 18);  // one face of the box
  expect_counts_match_brute_force(s);
  EXPECT_GT(build_edge_topology(s).n_boundary, 0);
}

// Every edge's first two users, in ascending triangle order, with their directions,
// against a map from each edge to all its uses in triangle order. Random triangles on
// few points give edges of many uses; a pole of 50 triangles (its point first, so it is
// the lower point of all its edges) takes the sort for points of many edges, the others
// the one for few.
TEST(EdgeTopology, EdgeUsersAreTheFirstTwoInTriangleOrder) {
  TriSurface s;
  const int n_pole = 50;
  s.points.resize(1 + n_pole + 12);
  for (int j = 0; j < n_pole; ++j) s.triangles.push_back({0, 1 + j, 1 + (j + 1) % n_pole});
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(1, n_pole + 12);
  for (int f = 0; f < 400; ++f) {
    const int a = pick(rng), b = pick(rng), c = pick(rng);
    if (a != b && b != c && a != c) s.triangles.push_back({a, b, c});
  }
  std::shuffle(s.triangles.begin(), s.triangles.end(), rng);
  std::map<std::pair<int, int>, std::vector<std::pair<int, bool>>> uses;
  for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = s.triangles[f][k], b = s.triangles[f][(k + 1) % 3];
      uses[{std::min(a, b), std::max(a, b)}].push_back({f, a < b});
    }
  const EdgeTopology e = build_edge_topology(s);
  ASSERT_EQ(e.edges.size(), uses.size());
  auto it = uses.begin();
  int many = 0;
  for (const SurfaceEdge& edge : e.edges) {
    const auto& [key, list] = *it++;
    ASSERT_EQ(std::make_pair(edge.lo, edge.hi), key);
    ASSERT_EQ(edge.n_uses, static_cast<int>(list.size()));
    many += edge.n_uses > 2;
    for (int u = 0; u < std::min(2, edge.n_uses); ++u) {
      EXPECT_EQ(edge.triangle[u], list[u].first);
      EXPECT_EQ(edge.forward[u], list[u].second);
    }
  }
  EXPECT_GT(many, 0);
}

}  // namespace
}  // namespace blayer
