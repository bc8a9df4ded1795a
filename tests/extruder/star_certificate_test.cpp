#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "blayer/extruder/front_checker.h"
#include "blayer/extruder/triangle_intersections.h"
#include "blayer/extruder/wall_topology.h"
#include "lcg.h"
#include "test_surfaces.h"

namespace blayer {
namespace {

using testing::Lcg;

using Side = std::array<std::int32_t, 2>;

std::vector<Side> shuffled(std::vector<Side> sides, Lcg* rng) {
  for (int i = static_cast<int>(sides.size()) - 1; i > 0; --i)
    std::swap(sides[i], sides[static_cast<int>(rng->uniform() * (i + 1)) % (i + 1)]);
  return sides;
}

TEST(StarRing, OrdersAShuffledClosedRingPointAfterPoint) {
  Lcg rng(3);
  std::vector<Side> sides;
  for (int i = 0; i < 7; ++i) sides.push_back({10 + i, 10 + (i + 1) % 7});
  const std::vector<Side> given = shuffled(sides, &rng);
  std::vector<std::int32_t> ring;
  bool closed = false;
  ASSERT_TRUE(order_star_ring(99, given.data(), 7, &ring, &closed));
  EXPECT_TRUE(closed);
  ASSERT_EQ(ring.size(), 7u);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(ring[(i + 1) % 7], 10 + (ring[i] - 10 + 1) % 7) << i;
}

TEST(StarRing, OrdersAnOpenFanFromThePointNoTriangleEndsAt) {
  Lcg rng(5);
  const std::vector<Side> given = shuffled({{1, 2}, {2, 3}, {3, 4}, {4, 5}}, &rng);
  std::vector<std::int32_t> ring;
  bool closed = true;
  ASSERT_TRUE(order_star_ring(0, given.data(), 4, &ring, &closed));
  EXPECT_FALSE(closed);
  EXPECT_EQ(ring, (std::vector<std::int32_t>{1, 2, 3, 4, 5}));
}

TEST(StarRing, RefusesStarsThatAreNotOneRing) {
  std::vector<std::int32_t> ring;
  bool closed;
  const std::vector<Side> two_cycles{{1, 2}, {2, 3}, {3, 1}, {4, 5}, {5, 6}, {6, 4}};
  EXPECT_FALSE(order_star_ring(0, two_cycles.data(), 6, &ring, &closed));
  const std::vector<Side> cycle_and_path{{1, 2}, {2, 3}, {3, 1}, {4, 5}};
  EXPECT_FALSE(order_star_ring(0, cycle_and_path.data(), 4, &ring, &closed));
  const std::vector<Side> two_paths{{1, 2}, {3, 4}};
  EXPECT_FALSE(order_star_ring(0, two_paths.data(), 2, &ring, &closed));
  const std::vector<Side> branch{{1, 2}, {1, 3}};
  EXPECT_FALSE(order_star_ring(0, branch.data(), 2, &ring, &closed));
  const std::vector<Side> merge{{1, 3}, {2, 3}};
  EXPECT_FALSE(order_star_ring(0, merge.data(), 2, &ring, &closed));
  // A path running into a cycle: every triangle is reached, but point 2 twice.
  const std::vector<Side> into_a_cycle{{1, 2}, {2, 3}, {3, 2}};
  EXPECT_FALSE(order_star_ring(0, into_a_cycle.data(), 3, &ring, &closed));
  const std::vector<Side> names_centre{{1, 2}, {2, 0}};
  EXPECT_FALSE(order_star_ring(0, names_centre.data(), 2, &ring, &closed));
  const std::vector<Side> names_a_point_twice{{1, 2}, {2, 2}};
  EXPECT_FALSE(order_star_ring(0, names_a_point_twice.data(), 2, &ring, &closed));
}

// A random star around v: ring points at increasing angles (some steps backwards when
// `folds`) through `turns` times the full circle (a fraction of it for an open ring),
// lifted by a height law, rotated and moved. Points: v first, then the ring.
struct Star {
  std::vector<Vec3> points;
  std::vector<std::int32_t> ring;
  bool closed = false;
  // Every step turns one way by less than half a turn, and the steps reach a full turn
  // beyond the first point (open) or two turns (closed).
  bool full_turn = false;
  bool flat = false;  // in one plane, or within 1e-9 of it
  std::string what;
};

Vec3 rotated(const Vec3& p, const Vec3& e0, const Vec3& e1, const Vec3& e2) {
  return p[0] * e0 + p[1] * e1 + p[2] * e2;
}

Star random_star(Lcg* rng, int draw) {
  Star s;
  const int m = 3 + static_cast<int>(rng->uniform() * 14);
  s.closed = rng->uniform() < 0.6;
  const int turns = rng->uniform() < 0.3 ? 2 : 1;
  const bool folds = rng->uniform() < 0.15;
  const int height = static_cast<int>(rng->uniform() * 4);  // flat, noisy, cone, helix
  s.flat = height <= 1;
  const bool coincide = rng->uniform() < 0.1;
  const double total = 2.0 * M_PI * turns * (s.closed ? 1.0 : 0.5 + 0.45 * rng->uniform());
  std::vector<double> steps(s.closed ? m : m - 1);
  double sum = 0.0;
  for (double& x : steps) sum += (x = 0.1 + rng->uniform());
  std::vector<double> angle(m, 0.0);
  bool one_way = true;
  for (int i = 1; i < m; ++i) {
    const double step = total * steps[i - 1] / sum * (folds && rng->uniform() < 0.3 ? -1 : 1);
    one_way = one_way && step > 0.0 && step < M_PI;
    angle[i] = angle[i - 1] + step;
  }
  if (s.closed) one_way = one_way && total - angle[m - 1] < M_PI;
  s.full_turn = one_way && total > 2.0 * M_PI * (s.closed ? 1.5 : 1.0);
  const Vec3 e0 = normalized(Vec3{rng->uniform() - 0.5, rng->uniform() - 0.5, rng->uniform() - 0.5});
  const Vec3 e1 = normalized(cross(e0, Vec3{rng->uniform() - 0.5, rng->uniform() - 0.5, rng->uniform() - 0.5}));
  const Vec3 e2 = cross(e0, e1);
  const Vec3 v{rng->uniform() * 10.0, rng->uniform() * 10.0, rng->uniform() * 10.0};
  s.points.push_back(v);
  for (int i = 0; i < m; ++i) {
    const double r = 0.5 + 1.5 * rng->uniform();
    double z = 0.0;
    if (height == 1) z = 1e-9 * (rng->uniform() - 0.5);
    if (height == 2) z = -0.3 * r;
    if (height == 3) z = 0.2 * angle[i];
    s.points.push_back(v + rotated(Vec3{r * std::cos(angle[i]), r * std::sin(angle[i]), z}, e0, e1, e2));
    s.ring.push_back(1 + i);
  }
  if (coincide && m >= 4) s.points[1 + m - 1] = s.points[1 + 1];  // two ring points at one place
  s.what = "draw " + std::to_string(draw) + ": m " + std::to_string(m) + (s.closed ? " closed" : " open") + ", turns " +
           std::to_string(turns) + (folds ? ", folds" : "") + ", height law " + std::to_string(height) +
           (coincide ? ", coincident points" : "");
  return s;
}

// The oracle: every two triangles of the star that share only v, by the exact test.
int meeting_pairs(const Star& s) {
  const int m = static_cast<int>(s.ring.size());
  const int n = s.closed ? m : m - 1;
  std::vector<IndexedTriangle> t;
  for (int i = 0; i < n; ++i) t.push_back({0, s.ring[i], s.ring[(i + 1) % m]});
  int meeting = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const bool neighbours = j == i + 1 || (s.closed && i == 0 && j == n - 1);
      if (!neighbours && soup_triangles_intersect(s.points, t[i], t[j])) ++meeting;
    }
  return meeting;
}

TEST(StarCertificate, NoPairOfACertifiedStarMeetsBeyondTheCentre) {
  Lcg rng(11);
  int certified = 0, refused_meeting = 0, flat_full_turns = 0, flat_full_turns_certified = 0;
  for (int draw = 0; draw < 4000; ++draw) {
    const Star s = random_star(&rng, draw);
    const int m = static_cast<int>(s.ring.size());
    const bool ok = star_pairs_meet_only_at_centre(s.points, 0, s.ring.data(), m, s.closed);
    const int meeting = meeting_pairs(s);
    flat_full_turns += s.flat && s.full_turn;
    if (ok) {
      ++certified;
      EXPECT_EQ(meeting, 0) << s.what;
      flat_full_turns_certified += s.flat && s.full_turn;
    } else if (meeting > 0) {
      ++refused_meeting;
    }
  }
  // The draws reach both verdicts: stars certified, and stars whose pairs do meet.
  EXPECT_GT(certified, 1000);
  EXPECT_GT(refused_meeting, 300);
  // A flat star whose triangles turn one way through more than a full turn (two turns
  // when closed) is refused in every projection. (Lifted as a helix, a star may turn
  // less in the projection the certificate chooses.)
  EXPECT_GT(flat_full_turns, 100);
  EXPECT_EQ(flat_full_turns_certified, 0);
}

TEST(StarCertificate, AFlatFanOnceAroundIsCertifiedAndTwiceAroundIsNot) {
  for (int turns : {1, 2}) {
    Star s;
    s.closed = true;
    s.points.push_back({0, 0, 0});
    const int m = 9;
    for (int i = 0; i < m; ++i) {
      const double a = 2.0 * M_PI * turns * i / m;
      s.points.push_back({std::cos(a), std::sin(a), 0.0});
      s.ring.push_back(1 + i);
    }
    EXPECT_EQ(star_pairs_meet_only_at_centre(s.points, 0, s.ring.data(), m, true), turns == 1) << turns;
    EXPECT_EQ(meeting_pairs(s) > 0, turns == 2) << turns;
  }
}

// A point on a CAD part's edge: four triangles on the top face (normal +z), four on the
// side face (+x). No axis sees both faces with an area, the direction between them does.
TEST(StarCertificate, AStarAcrossARightAngledEdgeIsCertified) {
  Star s;
  s.closed = true;
  s.points = {{0, 0, 0},  {0, 1, 0},  {-1, 1, 0}, {-1, 0, 0},  {-1, -1, 0},
              {0, -1, 0}, {0, -1, -1}, {0, 0, -1}, {0, 1, -1}};
  for (int i = 1; i < 9; ++i) s.ring.push_back(i);
  EXPECT_TRUE(star_pairs_meet_only_at_centre(s.points, 0, s.ring.data(), 8, true));
  EXPECT_EQ(meeting_pairs(s), 0);
}

// The ring's own geometry refuses a repeated point and a triangle of no area.
TEST(StarCertificate, RefusesRepeatedRingIdsAndAFlatTriangle) {
  std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}};
  const std::vector<std::int32_t> repeated{1, 2, 3, 4, 1};
  EXPECT_FALSE(star_pairs_meet_only_at_centre(p, 0, repeated.data(), 5, false));
  const std::vector<std::int32_t> inner_repeat{1, 2, 3, 4, 5, 2};  // 5 is 1's place again
  EXPECT_FALSE(star_pairs_meet_only_at_centre(p, 0, inner_repeat.data(), 6, false));
  const std::vector<std::int32_t> names_centre{1, 2, 0, 4};
  EXPECT_FALSE(star_pairs_meet_only_at_centre(p, 0, names_centre.data(), 4, true));
  const std::vector<std::int32_t> once{1, 2, 3, 4};
  EXPECT_TRUE(star_pairs_meet_only_at_centre(p, 0, once.data(), 4, true));
  p[3] = {0, 2, 0};  // (v, ring[1], ring[2]) collinear with v: no area
  EXPECT_FALSE(star_pairs_meet_only_at_centre(p, 0, once.data(), 4, true));
}

// The checker's collision verdicts against every pair of the fronts, tested exactly: on
// a plate whose first layer's points are jittered sideways, every new triangle whose
// cells pass (a checker without the collision test says which) is flagged exactly when
// it meets another new triangle beyond their shared points, or the wall. The jitter
// folds stars: crossings between triangles that share only their centre's column are
// among those found, the pairs the certificate lets go untested when it holds.
TEST(StarCertificate, TheCheckerFlagsEveryCrossingOfAllPairsOfAJitteredFront) {
  const int n = 7;
  const TriSurface wall = test::square_plate(n, static_cast<double>(n));
  const int nv = static_cast<int>(wall.points.size()), nt = static_cast<int>(wall.triangles.size());
  Lcg rng(23);
  int judged = 0, crossing = 0, crossing_at_one_point = 0;
  for (int draw = 0; draw < 200; ++draw) {
    std::vector<Vec3> top = wall.points, next = wall.points;
    for (Vec3& p : next)
      p += Vec3{0.9 * (rng.uniform() - 0.5), 0.9 * (rng.uniform() - 0.5), 0.05 + 0.5 * rng.uniform()};
    const std::vector<int> layers(nv, 0);
    const std::vector<char> grows(nv, 1);
    FrontVerdict with, cells_only;
    FrontChecker checker(wall, build_wall_topology(wall), true), no_collisions(wall, build_wall_topology(wall), false);
    checker.begin_layer(0, top, layers);
    checker.check(0, top, next, grows, &with);
    no_collisions.begin_layer(0, top, layers);
    no_collisions.check(0, top, next, grows, &cells_only);
    // The soup of the brute force: the wall's points, then the new ones.
    std::vector<Vec3> soup = wall.points;
    soup.insert(soup.end(), next.begin(), next.end());
    auto lifted = [&](const Triangle& t, int base) { return IndexedTriangle{t[0] + base, t[1] + base, t[2] + base}; };
    for (int f = 0; f < nt; ++f) {
      if (cells_only.bad_triangle[f]) continue;
      ++judged;
      bool meets = false, at_one_point = false;
      for (int j = 0; j < nt; ++j) {
        if (j != f && soup_triangles_intersect(soup, lifted(wall.triangles[f], nv), lifted(wall.triangles[j], nv))) {
          meets = true;
          int shared = 0;
          for (int a : wall.triangles[f])
            for (int b : wall.triangles[j]) shared += a == b;
          at_one_point = at_one_point || shared == 1;
        }
        meets = meets || soup_triangles_intersect(soup, lifted(wall.triangles[f], nv), lifted(wall.triangles[j], 0));
      }
      crossing += meets;
      crossing_at_one_point += at_one_point;
      EXPECT_EQ(static_cast<bool>(with.bad_triangle[f]), meets) << "draw " << draw << ", triangle " << f;
    }
  }
  EXPECT_GT(judged, 10000);
  EXPECT_GT(crossing, 40);
  EXPECT_GT(crossing_at_one_point, 30);
}

}  // namespace
}  // namespace blayer
