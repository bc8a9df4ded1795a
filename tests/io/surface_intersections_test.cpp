// The exact self-intersection and overlap checks of prepare_surface: surfaces that pass
// through themselves, bodies that pass through each other, and the near misses that
// must stay accepted (neighbours sharing edges, bodies a hair apart).
#include "blayer/io/surface_intersections.h"

#include <gtest/gtest.h>

#include "blayer/core/errors.h"
#include "blayer/io/prepare_surface.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

using testing::append;
using testing::box;

std::string prepare_error(const PolygonSoup& s, PrepareOptions opt = {}) {
  try {
    prepare_surface(s, "body.off", opt);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_CONTAINS(text, fragment) EXPECT_NE((text).find(fragment), std::string::npos) << (text)

// Brute force over all pairs with the same exact pair test: the oracle for the tree.
std::size_t brute_force_pairs(const TriSurface& s) {
  std::size_t n = 0;
  for (std::size_t a = 0; a < s.triangles.size(); ++a)
    for (std::size_t b = a + 1; b < s.triangles.size(); ++b) {
      TriSurface two{s.points, {s.triangles[a], s.triangles[b]}};
      n += find_surface_intersections(two, 10).size();
    }
  return n;
}

TriSurface as_triangles(const PolygonSoup& soup) {
  TriSurface s{soup.points, {}};
  for (const auto& f : soup.faces) s.triangles.push_back({f[0], f[1], f[2]});
  return s;
}

TEST(SurfaceIntersections, AClosedBoxHasNoneAndABoxWithACornerPushedThroughItselfHasThem) {
  const PolygonSoup cube = box({0, 0, 0}, {1, 1, 1});
  EXPECT_TRUE(find_surface_intersections(as_triangles(cube), 100).empty());
  PolygonSoup folded = cube;
  folded.points[6] = {-0.5, 0.5, 0.5};  // corner (1,1,1) pushed through the face x = 0
  const TriSurface s = as_triangles(folded);
  const auto pairs = find_surface_intersections(s, 100);
  EXPECT_EQ(pairs.size(), brute_force_pairs(s));
  ASSERT_FALSE(pairs.empty());
  for (const auto& x : pairs) {
    EXPECT_LT(x.a, x.b);
    EXPECT_NEAR(x.near[0], 0.0, 1e-12) << "the corner's triangles cross the face x = 0 there";
  }
}

TEST(SurfaceIntersections, ASurfacePassingThroughItselfIsRefusedNamingTheFirstPairs) {
  PolygonSoup folded = box({0, 0, 0}, {1, 1, 1});
  folded.points[6] = {-0.5, 0.5, 0.5};
  const std::string msg = prepare_error(folded);
  EXPECT_CONTAINS(msg, "self-intersections (the surface passes through itself) (8)");
  EXPECT_CONTAINS(msg, "component 0: triangle 2 [vertices 4, 5, 6] and triangle 10 [vertices 3, 0, 4] meet near (0, ");
}

TEST(SurfaceIntersections, TwoBodiesPassingThroughEachOtherAreRefusedNamingBothComponents) {
  PolygonSoup s = box({0, 0, 0}, {1, 1, 1});
  append(&s, box({0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}));
  const std::string msg = prepare_error(s);
  EXPECT_CONTAINS(msg, "intersecting components (one body's surface passes through another's)");
  EXPECT_CONTAINS(msg, "components 0 and 1: triangle 2 [vertices 4, 5, 6] and triangle 16 [vertices 8, 9, 13]");
  EXPECT_EQ(msg.find("self-intersections"), std::string::npos) << msg;
}

TEST(SurfaceIntersections, BodiesThatOnlyTouchAreRefusedAndBodiesAHairApartAreAccepted) {
  PolygonSoup touching = box({0, 0, 0}, {1, 1, 1});
  append(&touching, box({1, 0.25, 0.25}, {2, 0.75, 0.75}));  // face on face, separate vertices
  EXPECT_CONTAINS(prepare_error(touching), "intersecting components");
  PolygonSoup apart = box({0, 0, 0}, {1, 1, 1});
  append(&apart, box({1 + 1e-12, 0.25, 0.25}, {2, 0.75, 0.75}));
  EXPECT_EQ(prepare_error(apart), "");
}

TEST(SurfaceIntersections, OpenSurfacesAreCheckedToo) {
  PolygonSoup folded = box({0, 0, 0}, {1, 1, 1});
  folded.points[6] = {-0.5, 0.5, 0.5};
  folded.faces.pop_back();  // a hole as well
  PrepareOptions open;
  open.allow_open = true;
  EXPECT_CONTAINS(prepare_error(folded, open), "self-intersections");
}

}  // namespace
}  // namespace blayer
