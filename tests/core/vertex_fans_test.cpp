#include "blayer/core/vertex_fans.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "analytic_surfaces.h"

namespace blayer {
namespace {

// Oracle: the triangles around v, found by scanning all of them.
std::multiset<int> triangles_at(const TriSurface& s, int v) {
  std::multiset<int> out;
  for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f)
    for (int k = 0; k < 3; ++k)
      if (s.triangles[f][k] == v) out.insert(f);
  return out;
}

// Triangle f seen from v in its winding: (v, a, b).
bool winds_as(const Triangle& t, int v, int a, int b) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == v && t[(k + 1) % 3] == a && t[(k + 2) % 3] == b) return true;
  return false;
}

// Every fan against the oracle: its triangles are exactly v's, each (v, ring[j],
// ring[j+1]) in the surface's winding, and the ring closes on itself when it is closed.
void expect_fans_match_brute_force(const TriSurface& s) {
  const VertexFans fans = build_vertex_fans(s);
  ASSERT_EQ(fans.fans.size(), s.points.size());
  for (int v = 0; v < static_cast<int>(s.points.size()); ++v) {
    const VertexFan fan = fans.fans[v];
    const std::multiset<int> expected = triangles_at(s, v);
    EXPECT_EQ(std::multiset<int>(fan.triangles.begin(), fan.triangles.end()), expected) << "point " << v;
    const std::size_t k = fan.triangles.size();
    ASSERT_EQ(fan.ring.size(), fan.closed ? k : k + 1) << "point " << v;
    for (std::size_t j = 0; j < k; ++j)
      EXPECT_TRUE(winds_as(s.triangles[fan.triangles[j]], v, fan.ring[j], fan.ring[(j + 1) % fan.ring.size()]))
          << "point " << v << ", fan triangle " << j;
  }
}

TEST(VertexFans, ClosedFansOfASphereFollowTheWindingAroundEveryPoint) {
  const TriSurface s = test_surfaces::icosphere(2);
  expect_fans_match_brute_force(s);
  const VertexFans fans = build_vertex_fans(s);
  EXPECT_TRUE(fans.non_manifold.empty());
  for (std::size_t v = 0; v < fans.fans.size(); ++v) EXPECT_TRUE(fans.fans[v].closed) << v;
}

TEST(VertexFans, BoundaryPointsOfAPlateHaveOpenFansWithOneRingPointMore) {
  const TriSurface s = test_surfaces::square_plate(4, 1.0);
  expect_fans_match_brute_force(s);
  const VertexFans fans = build_vertex_fans(s);
  int open = 0;
  for (std::size_t v = 0; v < fans.fans.size(); ++v) open += !fans.fans[v].closed;
  EXPECT_EQ(open, 16);  // the 4 x 4 cells' boundary points
}

TEST(VertexFans, UnusedAndBowTiePointsGetEmptyFansAndTheBowTieIsListed) {
  // Two triangles meeting only at point 0 (a bow tie), and point 5 used by none.
  const TriSurface s{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {9, 9, 9}}, {{0, 1, 2}, {0, 3, 4}}};
  const VertexFans fans = build_vertex_fans(s);
  EXPECT_EQ(fans.non_manifold, std::vector<int>{0});
  EXPECT_TRUE(fans.fans[0].triangles.empty());
  EXPECT_TRUE(fans.fans[0].ring.empty());
  EXPECT_TRUE(fans.fans[5].triangles.empty());
  EXPECT_TRUE(fans.fans[5].ring.empty());
  EXPECT_EQ(fans.fans[1].triangles.size(), 1u);
  EXPECT_EQ(fans.fans[1].ring.size(), 2u);
}

TEST(VertexFans, AllFansLieInOneFlatArrayInPointOrder) {
  // One list per point in a shared array, not a heap block per fan: a run keeps the
  // fans of every wall and front point through its march.
  const TriSurface s = test_surfaces::icosphere(1);
  const VertexFans fans = build_vertex_fans(s);
  for (std::size_t v = 0; v + 1 < fans.fans.size(); ++v) {
    EXPECT_EQ(fans.fans[v].ring.end(), fans.fans[v + 1].ring.begin()) << v;
    EXPECT_EQ(fans.fans[v].triangles.end(), fans.fans[v + 1].triangles.begin()) << v;
  }
}

}  // namespace
}  // namespace blayer
