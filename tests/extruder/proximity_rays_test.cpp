// The batched proximity query (ProximityRays::first_hits, one pair traversal of a tree
// over the rays' segments with the wall's and the front's trees) against its oracle,
// one ray at a time (first_hit), and first_hit against itself without the trees'
// normal boxes: the same distance for every column, to the bit, over rays that hit the
// wall, the front, the symmetry plane or nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "blayer/extruder/proximity_rays.h"
#include "blayer/extruder/triangle_bvh.h"
#include "blayer/io/prepare_surface.h"

namespace blayer {
namespace {

// Regression case 006: two walls facing each other across a slot narrower than the
// layers, so that rays from one side hit the other.
TriSurface thin_slot() {
  return load_surface(std::string(BLAYER_CASES_DIR) + "/006_thin_slot/surface.stl", {}).surface;
}

double extent(const TriSurface& s) {
  Vec3 lo = s.points[0], hi = s.points[0];
  for (const Vec3& p : s.points)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  return norm(hi - lo);
}

// Rays in random directions (half of them along the wall normal, which is how the
// extruder casts them) with random reaches up to the surface's extent; every
// seventh column inactive.
struct RayBatch {
  std::vector<char> active;
  std::vector<Vec3> origin, dir;
  std::vector<double> reach;
};

RayBatch random_rays(const TriSurface& wall, const std::vector<Vec3>& origin, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = static_cast<int>(origin.size());
  std::vector<Vec3> normal(n, Vec3{0.0, 0.0, 0.0});
  for (const Triangle& t : wall.triangles) {
    const Vec3 a = cross(wall.points[t[1]] - wall.points[t[0]], wall.points[t[2]] - wall.points[t[0]]);
    for (int c : t) normal[c] += a;
  }
  RayBatch b;
  b.origin = origin;
  const double size = extent(wall);
  for (int v = 0; v < n; ++v) {
    b.active.push_back(v % 7 != 3);
    const Vec3 random_dir = normalized(Vec3{g(rng), g(rng), g(rng)});
    b.dir.push_back(v % 2 == 0 ? normalized(normal[v]) : random_dir);
    b.reach.push_back(size * u(rng));
  }
  return b;
}

// The rays' distances one at a time and batched, and one at a time without the trees'
// normal boxes (nothing skipped); counts the columns that hit something.
int expect_batched_equals_one_by_one(const ProximityRays& rays, const RayBatch& b, RaySegments* kept) {
  std::vector<double> gap;
  rays.first_hits(b.active, b.origin, b.dir, b.reach, &gap, kept);
  EXPECT_EQ(gap.size(), b.origin.size());
  ProximityRays unfiltered = rays;
  unfiltered.wall_normal_boxes = nullptr;
  unfiltered.front_normal_boxes = nullptr;
  int hits = 0;
  for (std::size_t v = 0; v < b.origin.size() && v < gap.size(); ++v) {
    const int c = static_cast<int>(v);
    const double one = b.active[v] ? rays.first_hit(c, b.origin[v], b.dir[v], b.reach[v]) : HUGE_VAL;
    const double plain = b.active[v] ? unfiltered.first_hit(c, b.origin[v], b.dir[v], b.reach[v]) : HUGE_VAL;
    EXPECT_EQ(one, plain) << "column " << v;
    EXPECT_EQ(gap[v], one) << "column " << v;
    hits += one < HUGE_VAL;
  }
  return hits;
}

TEST(ProximityRays, BatchedHitsOnTheWallEqualOneRayAtATime) {
  const TriSurface wall = thin_slot();
  const WallTree tree(wall);
  const ProximityRays rays = wall_proximity_rays(wall.triangles, wall.points, tree);
  const int hits = expect_batched_equals_one_by_one(rays, random_rays(wall, wall.points, 1), nullptr);
  EXPECT_GT(hits, 50);  // the comparison covers hits, not only misses
}

// The front: the wall moved out along its normals, searched as the extruder's layers
// search it (columns on the front, their own triangles left out), with a symmetry plane
// through the slot that the columns off it may hit.
TEST(ProximityRays, BatchedHitsOnTheFrontAndThePlaneEqualOneRayAtATime) {
  const TriSurface wall = thin_slot();
  const WallTree tree(wall);
  ProximityRays rays = wall_proximity_rays(wall.triangles, wall.points, tree);
  const RayBatch on_wall = random_rays(wall, wall.points, 2);
  std::vector<Vec3> top(wall.points.size());
  const double lift = 0.01 * extent(wall);
  for (std::size_t v = 0; v < top.size(); ++v) top[v] = wall.points[v] + lift * on_wall.dir[v];
  TriangleBvh front_tree;
  front_tree.build_triangles(static_cast<int>(wall.triangles.size()), [&](int f, Vec3* c) {
    for (int i = 0; i < 3; ++i) c[i] = top[wall.triangles[f][i]];
  });
  std::vector<Vec3> front_normal;
  unit_triangle_normals(wall.triangles, top, &front_normal);
  rays.front_points = &top;
  rays.front_tree = &front_tree;
  rays.front_normal = &front_normal;
  std::vector<UnitVectorBox> front_normal_boxes;
  front_tree.node_value_boxes([&](int f) { return front_normal[f]; }, &front_normal_boxes);
  rays.front_normal_boxes = &front_normal_boxes;
  SymmetryPlane plane;
  Vec3 centre{0.0, 0.0, 0.0};
  for (const Vec3& p : wall.points) centre += p / static_cast<double>(wall.points.size());
  plane.normal = Vec3{1.0, 0.0, 0.0};
  plane.offset = centre[0];
  std::vector<char> on_plane(wall.points.size(), 0);
  for (std::size_t v = 0; v < on_plane.size(); v += 5) on_plane[v] = 1;
  rays.plane = &plane;
  rays.on_plane = &on_plane;
  const int hits = expect_batched_equals_one_by_one(rays, random_rays(wall, top, 3), nullptr);
  EXPECT_GT(hits, 50);
}

// A kept tree is refitted to the next call's segments (the columns moved, some stopped)
// and rebuilt for another number of columns; stale boxes would miss the moved rays' hits.
TEST(ProximityRays, AKeptRayTreeFollowsTheSegmentsFromCallToCall) {
  const TriSurface wall = thin_slot();
  const WallTree tree(wall);
  const ProximityRays rays = wall_proximity_rays(wall.triangles, wall.points, tree);
  RaySegments kept;
  RayBatch b = random_rays(wall, wall.points, 4);
  expect_batched_equals_one_by_one(rays, b, &kept);
  // Every ray turned to another random direction and reach, every fifth column stopped.
  RayBatch turned = random_rays(wall, wall.points, 5);
  for (std::size_t v = 0; v < turned.active.size(); v += 5) turned.active[v] = 0;
  const int hits = expect_batched_equals_one_by_one(rays, turned, &kept);
  EXPECT_GT(hits, 50);
  // Half the columns: the kept tree no longer fits and is rebuilt.
  RayBatch half = turned;
  const std::size_t n = half.origin.size() / 2;
  half.active.resize(n);
  half.origin.resize(n);
  half.dir.resize(n);
  half.reach.resize(n);
  expect_batched_equals_one_by_one(rays, half, &kept);
  EXPECT_EQ(kept.tree.size(), static_cast<int>(n));
}

}  // namespace
}  // namespace blayer
