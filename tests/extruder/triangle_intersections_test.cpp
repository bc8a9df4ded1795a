#include "blayer/extruder/triangle_intersections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "blayer/extruder/triangle_bvh.h"
#include "lcg.h"

#include "test_surfaces.h"

namespace blayer {
namespace {

const Vec3 A{0, 0, 0}, B{1, 0, 0}, C{0, 1, 0};

// The oracle for triangles (v, a, b) and (v, c, d) sharing corner v: they meet beyond v
// iff an edge opposite v meets the other triangle.
bool meet_beyond_corner(const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return segment_intersects_triangle(a, b, v, c, d) || segment_intersects_triangle(c, d, v, a, b);
}

TEST(TriangleIntersections, SegmentThroughTheInteriorHits) {
  EXPECT_TRUE(segment_intersects_triangle({0.2, 0.2, -1}, {0.2, 0.2, 1}, A, B, C));
  EXPECT_FALSE(segment_intersects_triangle({0.8, 0.8, -1}, {0.8, 0.8, 1}, A, B, C));
  EXPECT_FALSE(segment_intersects_triangle({0.2, 0.2, 0.5}, {0.2, 0.2, 1}, A, B, C));
}

TEST(TriangleIntersections, TouchingCountsAsHitting) {
  EXPECT_TRUE(segment_intersects_triangle({0.2, 0.2, 0}, {0.2, 0.2, 1}, A, B, C));  // endpoint on the face
  EXPECT_TRUE(segment_intersects_triangle({0.5, 0.5, -1}, {0.5, 0.5, 1}, A, B, C));  // through the edge
  EXPECT_TRUE(segment_intersects_triangle({0, 0, -1}, {0, 0, 1}, A, B, C));          // through a vertex
}

TEST(TriangleIntersections, CoplanarSegmentsAreDecidedInThePlane) {
  EXPECT_TRUE(segment_intersects_triangle({-1, 0.2, 0}, {2, 0.2, 0}, A, B, C));
  EXPECT_TRUE(segment_intersects_triangle({0.1, 0.1, 0}, {0.2, 0.2, 0}, A, B, C));  // inside
  EXPECT_FALSE(segment_intersects_triangle({1, 1, 0}, {2, 2, 0}, A, B, C));
}

TEST(TriangleIntersections, SharedEdgeOnlyCountsWhenFolded) {
  const std::vector<Vec3> p = {A, B, C, {0.5, -1, 0}, {0.2, 0.3, 0}, {0.5, -1, 1}};
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 1, 2}, {1, 0, 3}));  // flat continuation
  EXPECT_TRUE(soup_triangles_intersect(p, {0, 1, 2}, {1, 0, 4}));   // folded onto itself
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 1, 2}, {1, 0, 5}));  // a dihedral angle
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 1, 2}, {2, 1, 0}));  // the same face
  // A triangle naming a point twice is a segment: it meets nothing, with either width.
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 1, 2}, {0, 0, 4}));
  EXPECT_FALSE(compact_soup_triangles_intersect(p, SoupTriangle{0, 1, 2}, SoupTriangle{0, 0, 4}));
  EXPECT_TRUE(compact_soup_triangles_intersect(p, SoupTriangle{0, 1, 2}, SoupTriangle{1, 0, 4}));
}

// Edge neighbours fold iff the four points are coplanar and the far corners lie on the
// same side of the shared edge. On lattice points (small integers: every product below
// is exact) that is a triple product of zero and a positive dot product of the two
// normals, a reference independent of the projection the test decides the side in. A
// third of the pairs are made coplanar, as flat quads of a front are, and a third nearly
// so (where the floating-point filter cannot tell).
TEST(TriangleIntersections, SharedEdgePairsFoldExactlyWhenCoplanarOnOneSide) {
  testing::Lcg lcg(4242);
  auto grid = [&]() { return std::floor(lcg.uniform() * 7.0) - 3.0; };
  int folds = 0, flat_unfolded = 0;
  for (int i = 0; i < 30000; ++i) {
    std::vector<Vec3> p(4);
    for (Vec3& x : p) x = {grid(), grid(), grid()};
    if (i % 3 != 2) p[3][2] = 0.0, p[0][2] = p[1][2] = p[2][2] = 0.0;  // all in z = 0
    if (i % 3 == 1) p[3][2] = std::nextafter(0.0, 1.0);  // the far corner one subnormal off it
    const Vec3 n_c = cross(p[1] - p[0], p[2] - p[0]), n_d = cross(p[1] - p[0], p[3] - p[0]);
    if (norm2(n_c) == 0.0 || norm2(n_d) == 0.0) continue;  // zero-area triangles: outside the contract
    const bool coplanar = dot(n_c, p[3] - p[0]) == 0.0;
    const bool expected = coplanar && dot(n_c, n_d) > 0.0;
    ASSERT_EQ(soup_triangles_intersect(p, {0, 1, 2}, {1, 0, 3}), expected) << "pair " << i;
    ASSERT_EQ(compact_soup_triangles_intersect(p, SoupTriangle{0, 1, 2}, SoupTriangle{1, 0, 3}), expected)
        << "pair " << i;
    folds += expected;
    flat_unfolded += coplanar && !expected;
  }
  EXPECT_GT(folds, 1000);
  EXPECT_GT(flat_unfolded, 1000);
}

TEST(TriangleIntersections, SharedVertexCountsWhenTheTrianglesCrossBeyondIt) {
  // Both triangles contain the origin; the second pierces the first away from it.
  const std::vector<Vec3> p = {A, B, C, {0.3, 0.3, -1}, {0.3, 0.3, 1}, {-1, -1, 1}, {-1, 0, 1}};
  EXPECT_TRUE(soup_triangles_intersect(p, {0, 1, 2}, {0, 3, 4}));
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 1, 2}, {0, 5, 6}));
}

TEST(TriangleIntersections, ATriangleNamingAnIdTwiceMeetsNothing) {
  // Fan strips whose fan did not grow: (a, a, b) is a segment of its neighbours' edges.
  // Before the guard, these pairs counted 2 and 4 shared ids and read and wrote past the
  // shared-id arrays (found by the extrude_check fuzzer).
  const std::vector<Vec3> p = {A, B, C, {0.3, 0.3, -1}};
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 0, 1}, {0, 2, 3}));
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 0, 1}, {0, 0, 2}));
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 2, 3}, {1, 1, 0}));
}

TEST(TriangleIntersections, ClosedSphereHasNoIntersectingPairs) {
  const TriSurface s = test::icosphere(2, 1.0);
  std::vector<IndexedTriangle> t;
  for (const Triangle& f : s.triangles) t.push_back({f[0], f[1], f[2]});
  EXPECT_TRUE(find_triangle_intersections(s.points, t).empty());
}

TEST(TriangleIntersections, PushingAVertexThroughTheSphereIsFound) {
  TriSurface s = test::icosphere(2, 1.0);
  s.points[0] = -1.5 * s.points[0];  // through the centre and out the other side
  std::vector<IndexedTriangle> t;
  for (const Triangle& f : s.triangles) t.push_back({f[0], f[1], f[2]});
  const auto pairs = find_triangle_intersections(s.points, t);
  EXPECT_FALSE(pairs.empty());
  for (const auto& pr : pairs) EXPECT_LT(pr.first, pr.second);
  // Restricting the test to the moved vertex's triangles finds the same pairs.
  std::vector<char> check(t.size(), 0);
  for (std::size_t i = 0; i < t.size(); ++i) check[i] = t[i][0] == 0 || t[i][1] == 0 || t[i][2] == 0;
  const auto restricted = find_triangle_intersections(s.points, t, &check);
  for (const auto& pr : restricted) EXPECT_TRUE(check[pr.first] || check[pr.second]);
  EXPECT_FALSE(restricted.empty());
}

// Two triangles sharing one vertex meet beyond it iff an edge opposite the shared vertex
// meets the other triangle: the plane tests that settle most pairs first must give the
// same verdict, also on grid points where points are coplanar or collinear (triangles of
// zero area aside: the edge tests treat them as planes).
TEST(TriangleIntersections, SharedVertexVerdictIsTheOppositeEdgeTests) {
  testing::Lcg lcg(777);
  auto grid = [&]() { return std::floor(lcg.uniform() * 5.0) - 2.0; };
  auto flat = [](const Vec3& a, const Vec3& b, const Vec3& c) { return norm2(cross(b - a, c - a)) == 0.0; };
  int crossing = 0, apart = 0;
  for (int t = 0; t < 20000; ++t) {
    std::vector<Vec3> p(5);
    p[0] = {0.0, 0.0, 0.0};
    for (int i = 1; i < 5; ++i)
      p[i] = t % 2 == 0 ? Vec3{grid(), grid(), grid() * (t % 4 == 0 ? 0.0 : 1.0)}
                        : Vec3{lcg.uniform() - 0.5, lcg.uniform() - 0.5, lcg.uniform() - 0.5};
    if (flat(p[0], p[1], p[2]) || flat(p[0], p[3], p[4])) continue;
    const bool expected = meet_beyond_corner(p[0], p[1], p[2], p[3], p[4]);
    // Ids 1-4 are distinct: the triangles share id 0 alone even where positions repeat.
    ASSERT_EQ(soup_triangles_intersect(p, {0, 1, 2}, {0, 3, 4}), expected) << "pair " << t;
    ASSERT_EQ(compact_soup_triangles_intersect(p, SoupTriangle{0, 1, 2}, SoupTriangle{0, 3, 4}), expected) << "pair " << t;
    (expected ? crossing : apart)++;
  }
  EXPECT_GT(crossing, 1000);
  EXPECT_GT(apart, 1000);
}

// A zero-area triangle along a line through the shared vertex that leaves the other
// triangle's plane there meets it at that vertex alone.
TEST(TriangleIntersections, ZeroAreaNeighbourOffThePlaneMeetsOnlyAtTheSharedVertex) {
  const std::vector<Vec3> p = {{0, 0, 0}, {-2, -2, 0}, {-1, -1, 0}, {1, 2, 1}, {0, 2, 0}};
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 1, 2}, {0, 3, 4}));
  EXPECT_FALSE(soup_triangles_intersect(p, {0, 3, 4}, {0, 1, 2}));
}

// Pairs on a flat, tilted stretch of front (z = x / 2 + y / 4 on a dyadic grid, exact),
// each corner left on it or moved one ulp or one subnormal off it: the plane tests
// cannot decide these with floating point, and the projected certificates
// (projections_apart, corner_angles_apart) settle most of them first. Every verdict must
// be the definition's: an edge of one meets the other (no shared corner), an edge
// opposite the shared corner meets the other triangle (one shared corner).
TEST(TriangleIntersections, NearlyFlatPairsGetTheVerdictOfTheEdgeTests) {
  testing::Lcg lcg(2718);
  auto corner = [&]() {
    const double x = std::floor(lcg.uniform() * 9.0) / 4.0, y = std::floor(lcg.uniform() * 9.0) / 4.0;
    double z = x / 2.0 + y / 4.0;
    const int off = static_cast<int>(lcg.uniform() * 4.0);
    if (off == 1) z = std::nextafter(z, HUGE_VAL);
    if (off == 2) z = std::nextafter(z, -HUGE_VAL);
    if (off == 3) z += std::nextafter(0.0, 1.0);
    return Vec3{x, y, z};
  };
  auto flat = [](const Vec3& a, const Vec3& b, const Vec3& c) { return norm2(cross(b - a, c - a)) == 0.0; };
  int disjoint_hits = 0, disjoint_misses = 0, corner_hits = 0, corner_misses = 0;
  for (int i = 0; i < 40000; ++i) {
    std::vector<Vec3> p(6);
    for (Vec3& x : p) x = corner();
    if (flat(p[0], p[1], p[2]) || flat(p[3], p[4], p[5])) continue;
    bool expected = false;
    for (int k = 0; k < 3; ++k)
      expected = expected || segment_intersects_triangle(p[k], p[(k + 1) % 3], p[3], p[4], p[5]) ||
                 segment_intersects_triangle(p[3 + k], p[3 + (k + 1) % 3], p[0], p[1], p[2]);
    ASSERT_EQ(soup_triangles_intersect(p, {0, 1, 2}, {3, 4, 5}), expected) << "disjoint ids, pair " << i;
    ASSERT_EQ(compact_soup_triangles_intersect(p, SoupTriangle{0, 1, 2}, SoupTriangle{3, 4, 5}), expected)
        << "disjoint ids, pair " << i;
    (expected ? disjoint_hits : disjoint_misses)++;
    // The same corners with the first one shared (ids 0, 1, 2 and 0, 4, 5).
    if (flat(p[0], p[4], p[5])) continue;
    const bool beyond = meet_beyond_corner(p[0], p[1], p[2], p[4], p[5]);
    ASSERT_EQ(soup_triangles_intersect(p, {0, 1, 2}, {0, 4, 5}), beyond) << "shared corner, pair " << i;
    ASSERT_EQ(compact_soup_triangles_intersect(p, SoupTriangle{0, 1, 2}, SoupTriangle{0, 4, 5}), beyond)
        << "shared corner, pair " << i;
    (beyond ? corner_hits : corner_misses)++;
  }
  EXPECT_GT(disjoint_hits, 1000);
  EXPECT_GT(disjoint_misses, 1000);
  EXPECT_GT(corner_hits, 1000);
  EXPECT_GT(corner_misses, 1000);
}

// The BVH-based search must find exactly the pairs a brute-force double loop finds.
TEST(TriangleIntersections, TreeSearchMatchesBruteForceOnRandomTriangles) {
  testing::Lcg lcg(12345);
  auto rnd = [&]() { return lcg.uniform(); };
  std::vector<Vec3> pts;
  std::vector<IndexedTriangle> tris;
  for (int i = 0; i < 400; ++i) {
    const Vec3 c{rnd() * 4, rnd() * 4, rnd() * 4};
    for (int k = 0; k < 3; ++k) pts.push_back(c + Vec3{rnd() - 0.5, rnd() - 0.5, rnd() - 0.5});
    tris.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  std::vector<std::pair<int, int>> brute;
  for (int i = 0; i < 400; ++i)
    for (int j = i + 1; j < 400; ++j)
      if (soup_triangles_intersect(pts, tris[i], tris[j])) brute.emplace_back(i, j);
  ASSERT_GT(brute.size(), 10u);
  EXPECT_EQ(find_triangle_intersections(pts, tris), brute);
}


}  // namespace
}  // namespace blayer
