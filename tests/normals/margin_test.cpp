// The graded margin of a fan with no visible direction (best_margin_direction: the
// candidates of the hull of the face normals) against the enumeration of every single
// face, pair and triple (best_margin_direction_by_enumeration), on point sets that put
// the origin inside the hull, just outside it, on it, and hulls with coplanar facets,
// repeated normals and no volume. Likewise the most-visible normal from the supports on
// the hull (most_visible_on_hull) against most_visible_by_enumeration.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "blayer/normals/most_visible.h"
#include "cad_fans.h"
#include "link_vertex_lens.h"
#include "normal_hull.h"
#include "test_fans.h"

namespace blayer {
namespace {

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  for (;;) {
    const Vec3 v{g(rng), g(rng), g(rng)};
    if (norm(v) > 1e-3) return normalized(v);
  }
}

// Same margin as the enumeration, to rounding.
void expect_same_margin(const std::vector<Vec3>& f, const std::string& what) {
  const int k = static_cast<int>(f.size());
  const MostVisibleResult hull = best_margin_direction(f.data(), k);
  const MostVisibleResult all = best_margin_direction_by_enumeration(f.data(), k);
  EXPECT_NEAR(hull.visibility, all.visibility, 1e-12) << what;
}

TEST(BestMargin, MatchesTheEnumerationWithTheOriginInsideTheHull) {
  std::mt19937 rng(7);
  int inside = 0;
  for (int k : {4, 5, 8, 13, 21, 34})
    for (int t = 0; t < 20; ++t) {
      std::vector<Vec3> f;
      for (int i = 0; i < k; ++i) f.push_back(random_unit(rng));
      const MostVisibleResult all = best_margin_direction_by_enumeration(f.data(), k);
      inside += all.visibility < 0.0;
      expect_same_margin(f, "k " + std::to_string(k) + " #" + std::to_string(t));
    }
  EXPECT_GT(inside, 60);  // most random sets surround the origin
}

// Normals within a cap of half-angle just above or below 90 degrees: the origin lies
// just inside or just outside the hull, and the nearest hull point can be a facet, an
// edge or a vertex.
TEST(BestMargin, MatchesTheEnumerationWithTheOriginNearTheHull) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (double rim : {-1e-3, -1e-6, 1e-6, 1e-3})
    for (int k : {4, 6, 10, 16})
      for (int t = 0; t < 10; ++t) {
        std::vector<Vec3> f;
        for (int i = 0; i < k; ++i) {
          // Directions at elevation `rim` above the equator (a few) or higher up.
          const double phi = 2.0 * M_PI * u(rng);
          const double z = i < 3 ? rim : rim + 0.3 * u(rng);
          const double r = std::sqrt(1.0 - z * z);
          f.push_back({r * std::cos(phi), r * std::sin(phi), z});
        }
        expect_same_margin(f, "rim " + std::to_string(rim) + " k " + std::to_string(k) + " #" + std::to_string(t));
      }
}

// The origin exactly on the hull: in a facet (three equator directions around it and
// the pole) and on an edge (two opposite normals); the margin is 0.
TEST(BestMargin, MatchesTheEnumerationWithTheOriginOnTheHull) {
  const std::vector<Vec3> facet = {{1, 0, 0}, {-0.5, std::sqrt(0.75), 0}, {-0.5, -std::sqrt(0.75), 0}, {0, 0, 1}};
  expect_same_margin(facet, "origin in a facet");
  EXPECT_NEAR(best_margin_direction(facet.data(), 4).visibility, 0.0, 1e-15);
  const std::vector<Vec3> edge = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}};
  expect_same_margin(edge, "origin on an edge");
  EXPECT_NEAR(best_margin_direction(edge.data(), 4).visibility, 0.0, 1e-15);
}

// The cube's corner directions (four coplanar on each face of their hull) and the
// octahedron's with repeats; normals spanning no volume (a great circle, a small circle,
// an opposite pair with a third) take the enumeration itself: this only checks that
// they get there.
TEST(BestMargin, MatchesTheEnumerationOnDegenerateHulls) {
  std::vector<Vec3> cube;
  for (int m = 0; m < 8; ++m) cube.push_back(normalized(Vec3{m & 1 ? 1.0 : -1.0, m & 2 ? 1.0 : -1.0, m & 4 ? 1.0 : -1.0}));
  expect_same_margin(cube, "cube corners");
  std::vector<Vec3> octa = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, 0, -1}};
  expect_same_margin(octa, "octahedron with repeats");
  std::vector<Vec3> great, small;
  for (int i = 0; i < 9; ++i) {
    const double a = 2.0 * M_PI * i / 9.0;
    great.push_back({std::cos(a), std::sin(a), 0.0});
    small.push_back(normalized(Vec3{std::cos(a), std::sin(a), -0.2}));
  }
  expect_same_margin(great, "great circle");
  expect_same_margin(small, "small circle");
  expect_same_margin({{0, 0, 1}, {0, 0, -1}, {1, 0, 0}}, "opposite pair");
}

// A normal that is not finite (no surface blayer accepts has one, but the function is
// public) never reaches the hull's exact predicates: the enumeration takes the set.
TEST(BestMargin, NonFiniteNormalsSkipTheHull) {
  std::vector<std::array<int, 3>> facets;
  const std::vector<Vec3> f = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, -1}, {HUGE_VAL, 0, 0}};
  EXPECT_FALSE(detail::normal_hull_facets(f.data(), 5, &facets));
  EXPECT_TRUE(facets.empty());
  const std::vector<Vec3> g = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {NAN, 0, 0}};
  EXPECT_FALSE(detail::normal_hull_facets(g.data(), 4, &facets));
  EXPECT_TRUE(detail::normal_hull_facets(f.data(), 4, &facets));  // the four finite ones
  EXPECT_EQ(facets.size(), 4u);
}

// The hull's triangles close a convex surface around every point, wound outwards: each
// point lies on or below each triangle's plane, every triangle has area, and every edge
// is shared by exactly two triangles, in opposite directions. A closed convex surface
// through input points around all of them is their hull.
void expect_closed_hull(const std::vector<Vec3>& f, const std::string& what) {
  std::vector<std::array<int, 3>> facets;
  ASSERT_TRUE(detail::normal_hull_facets(f.data(), static_cast<int>(f.size()), &facets)) << what;
  std::vector<std::array<int, 2>> edges;
  for (const auto& [a, b, c] : facets) {
    const Vec3 out = cross(f[b] - f[a], f[c] - f[a]);
    EXPECT_GT(norm(out), 0.0) << what;
    for (const Vec3& x : f) EXPECT_LE(dot(out, x - f[a]), 1e-12 * norm(out)) << what;
    edges.push_back({a, b});
    edges.push_back({b, c});
    edges.push_back({c, a});
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    EXPECT_TRUE(e == 0 || edges[e] != edges[e - 1]) << what << ": an edge used twice one way";
    EXPECT_TRUE(std::binary_search(edges.begin(), edges.end(), std::array<int, 2>{edges[e][1], edges[e][0]}))
        << what << ": an edge without its twin";
  }
}

// k unit points in general position, or (cluster) within about 1e-3 of +z, as a fan
// face's normals.
std::vector<Vec3> random_points(std::mt19937& rng, int k, bool cluster) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Vec3> f;
  for (int i = 0; i < k; ++i) {
    Vec3 x{gauss(rng), gauss(rng), gauss(rng)};
    if (cluster) x = Vec3{0.0, 0.0, 1.0} + 1e-3 * x;
    f.push_back(normalized(x));
  }
  return f;
}

// A cube's corners, face centres and edge midpoints, with `repeats` of them twice,
// shuffled: points land in facet planes, on edges and on vertices as the hull grows.
std::vector<Vec3> cube_grid(std::mt19937& rng, int repeats) {
  std::vector<Vec3> grid;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) grid.push_back({0.5 * x, 0.5 * y, 0.5 * z});
  std::vector<Vec3> f = grid;
  for (int r = 0; r < repeats; ++r) f.push_back(grid[static_cast<std::size_t>(r * 7) % grid.size()]);
  std::shuffle(f.begin(), f.end(), rng);
  return f;
}

// An apex over 24 points on one circle.
std::vector<Vec3> cone_points() {
  std::vector<Vec3> cone{{0.0, 0.0, 1.0}};
  for (int i = 0; i < 24; ++i)
    cone.push_back({0.5 * std::cos(M_PI * i / 12.0), 0.5 * std::sin(M_PI * i / 12.0), -0.5});
  return cone;
}

// Points in general position and CAD-like clusters.
TEST(NormalHull, TrianglesCloseTheHullWoundOutwards) {
  std::mt19937 rng(31);
  for (int trial = 0; trial < 40; ++trial)
    expect_closed_hull(random_points(rng, 5 + trial, trial % 2 == 1), "trial " + std::to_string(trial));
}

// Exactly coplanar points on the facets and repeats, and a cone of points on one circle
// around an apex.
TEST(NormalHull, TrianglesCloseTheHullOfCoplanarAndRepeatedPoints) {
  std::mt19937 rng(8);
  for (int trial = 0; trial < 30; ++trial)
    expect_closed_hull(cube_grid(rng, trial % 5), "cube grid, trial " + std::to_string(trial));
  expect_closed_hull(cone_points(), "cone");
}

// The face normals of CAD-like fans of valence 12 to 60 (thin fan triangles: many nearly
// equal normals), whether or not they have a visible direction.
TEST(BestMargin, MatchesTheEnumerationOnCadLikeFans) {
  std::mt19937 rng(2027);
  int n = 0;
  testing_fans::for_each_cad_fan(rng, {12, 24, 40, 60}, 2, [&](const FanGeometry& g, const std::string& label) {
    ++n;
    expect_same_margin(g.face_normals, label);
  });
  EXPECT_GT(n, 80);
}

// Same answer as the enumeration of every support, to rounding, and the same verdict on
// feasibility. Infeasible answers are not compared: with the origin within rounding of
// the hull any tiny q passes the certificate, and which one does is arbitrary (callers
// use a cap only when it is feasible).
// Returns whether the enumeration's answer is feasible.
bool expect_same_most_visible(const std::vector<Vec3>& f, const std::string& what,
                              const Tolerances& tol = default_tolerances()) {
  const int k = static_cast<int>(f.size());
  const MostVisibleResult hull = most_visible_on_hull(f.data(), k, tol);
  const MostVisibleResult all = most_visible_by_enumeration(f.data(), k, tol);
  EXPECT_EQ(hull.feasible, all.feasible) << what;
  if (!all.feasible) return false;
  EXPECT_NEAR(hull.visibility, all.visibility, 1e-12) << what;
  EXPECT_LE(norm(hull.normal - all.normal), 1e-9) << what;
  return true;
}

// The link directions of CAD-like fans (near-flat links whose cap is a hemisphere by a
// hair, with the solver's visibility floor of 1e-12; Wolfe's iteration left them
// uncertified, for the hull, until its affinely dependent steps were handled) and their
// face normals.
TEST(MostVisibleOnHull, MatchesTheEnumerationOnCadLikeFans) {
  std::mt19937 rng(2029);
  const Tolerances cap_tol = detail::lens_cap_tolerances(default_tolerances());
  int n = 0, uncertified_feasible = 0, on_hull = 0;
  std::vector<std::array<int, 3>> facets;
  testing_fans::for_each_cad_fan(rng, {12, 24, 40, 60}, 2, [&](const FanGeometry& g, const std::string& label) {
    ++n;
    on_hull += detail::normal_hull_facets(g.dirs.data(), g.n_faces(), &facets);  // not the enumeration's path
    MostVisibleResult wolfe;
    const bool uncertified =
        wolfe_min_norm_point(g.dirs.data(), g.n_faces(), cap_tol, &wolfe) == WolfeOutcome::kUncertified;
    uncertified_feasible += expect_same_most_visible(g.dirs, "link of " + label, cap_tol) && uncertified;
    expect_same_most_visible(g.face_normals, "faces of " + label);
  });
  EXPECT_GT(n, 80);
  EXPECT_GT(on_hull, n / 2);
  // Every feasible link is certified by Wolfe's iteration: its affinely dependent steps
  // (near-flat links, nearly coplanar) take the best face through the new point.
  EXPECT_EQ(uncertified_feasible, 0);
}

// The link directions and face normals of a pole whose ring carries noise: nearly
// coplanar, so that Wolfe's support of three plus the next point is affinely dependent
// to rounding. Its step then takes the best face through the new point, and the
// iteration ends certified, at the enumeration's answer.
TEST(WolfeMinNormPoint, CertifiesTheNearlyCoplanarNormalsOfANoisyPole) {
  std::mt19937 rng(404);
  std::normal_distribution<double> nd;
  const Tolerances cap_tol = detail::lens_cap_tolerances(default_tolerances());
  for (int k : {16, 48})
    for (double noise : {1e-12, 1e-9, 1e-7}) {
      std::vector<Vec3> ring;
      for (int j = 0; j < k; ++j)
        ring.push_back(Vec3{std::cos(2.0 * M_PI * j / k), std::sin(2.0 * M_PI * j / k), -0.05} +
                       noise * Vec3{nd(rng), nd(rng), nd(rng)});
      Vec3 q[3];
      testing_fans::random_rotation(rng, q);
      for (Vec3& r : ring) r = testing_fans::rotate(r, q);
      const FanGeometry g = testing_fans::geometry(ring);
      const std::string what = "valence " + std::to_string(k) + ", noise " + testing::PrintToString(noise);
      for (const auto& [f, tol] : {std::pair{&g.dirs, cap_tol}, std::pair{&g.face_normals, default_tolerances()}}) {
        MostVisibleResult wolfe;
        ASSERT_EQ(wolfe_min_norm_point(f->data(), k, tol, &wolfe), WolfeOutcome::kCertified) << what;
        const MostVisibleResult all = most_visible_by_enumeration(f->data(), k, tol);
        ASSERT_TRUE(all.feasible) << what;
        // Wolfe's certificate accepts x.x - f.x up to 1e-13 (kSupportSlack): V within
        // 1e-13 / V*, 2e-12 here (V* = 0.05).
        EXPECT_NEAR(wolfe.visibility, all.visibility, 1e-13 / all.visibility + 1e-15) << what;
        EXPECT_LE(norm(wolfe.normal - all.normal), 1e-9) << what;
      }
    }
}

// Directions in caps just under and over a hemisphere, and within small caps: the
// min-norm point on a facet, an edge or a vertex of the hull, or the origin inside it.
TEST(MostVisibleOnHull, MatchesTheEnumerationOnRandomCaps) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int feasible = 0, infeasible = 0;
  for (double rim : {-1e-3, -1e-6, 1e-6, 1e-3, 0.5})
    for (int k : {4, 6, 10, 16, 30})
      for (int t = 0; t < 10; ++t) {
        std::vector<Vec3> f;
        for (int i = 0; i < k; ++i) {
          const double phi = 2.0 * M_PI * u(rng);
          const double z = i < 3 ? rim : rim + (1.0 - rim) * u(rng);
          const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
          f.push_back({r * std::cos(phi), r * std::sin(phi), z});
        }
        const std::string what = "rim " + std::to_string(rim) + " k " + std::to_string(k) + " #" + std::to_string(t);
        expect_same_most_visible(f, what);
        (most_visible_by_enumeration(f.data(), k).feasible ? feasible : infeasible) += 1;
      }
  EXPECT_GT(feasible, 50);
  EXPECT_GT(infeasible, 20);
}

// Repeated normals (merged, or within rounding of each other), two squares on parallel
// circles (coplanar facets, q* on a facet's diagonal, several supports tie), three
// normals and normals on one small circle (no volume: the enumeration's path).
TEST(MostVisibleOnHull, MatchesTheEnumerationOnDegenerateSets) {
  auto tilted = [](double x, double y) { return normalized(Vec3{x, y, 1.0}); };
  std::vector<Vec3> square;
  for (double x : {-0.2, 0.2})
    for (double y : {-0.2, 0.2}) square.push_back(tilted(x + 0.3, y));
  square.push_back(tilted(0.1, 0.0));  // inside: not on the hull
  expect_same_most_visible(square, "square cap");
  std::vector<Vec3> repeats = square;
  repeats.push_back(square[0]);
  repeats.push_back(normalized(square[1] + Vec3{1e-15, 0.0, 0.0}));
  expect_same_most_visible(repeats, "repeated normals");
  std::vector<Vec3> rings;  // two squares on parallel circles: q* = (0, 0, 0.8) on a diagonal
  for (int i = 0; i < 4; ++i)
    for (double z : {0.8, 0.9}) {
      const double a = 0.5 * M_PI * i + (z > 0.85 ? 0.25 * M_PI : 0.0), r = std::sqrt(1.0 - z * z);
      rings.push_back({r * std::cos(a), r * std::sin(a), z});
    }
  expect_same_most_visible(rings, "two rings");
  EXPECT_NEAR(most_visible_on_hull(rings.data(), 8).visibility, 0.8, 1e-12);
  expect_same_most_visible({tilted(0.1, 0.0), tilted(-0.1, 0.1), tilted(0.0, -0.2)}, "three normals");
  std::vector<Vec3> circle;
  for (int i = 0; i < 9; ++i) circle.push_back(normalized(Vec3{std::cos(0.7 * i), std::sin(0.7 * i), 3.0}));
  expect_same_most_visible(circle, "small circle");
}

// Point sets for the hull's two constructions: general position, clusters (a fan
// face's normals), the cube grid with repeats (points in facet planes, on edges and on
// vertices), a cone of points on one circle, and the face normals and link directions
// of CAD-like fans of valence 12 to 60.
template <class Visit>
void for_each_hull_case(Visit&& visit) {
  std::mt19937 rng(41);
  for (int trial = 0; trial < 40; ++trial)
    visit(random_points(rng, 5 + trial, trial % 2 == 1), "random trial " + std::to_string(trial));
  for (int trial = 0; trial < 30; ++trial) visit(cube_grid(rng, trial % 5), "cube grid trial " + std::to_string(trial));
  visit(cone_points(), "cone");
  std::mt19937 fans(2029);
  testing_fans::for_each_cad_fan(fans, {12, 24, 40, 60}, 2, [&](const FanGeometry& g, const std::string& label) {
    visit(g.face_normals, label + " normals");
    visit(g.dirs, label + " link");
  });
}

// Each triangle turned to start at its smallest index (winding kept), all sorted.
std::vector<std::array<int, 3>> canonical(std::vector<std::array<int, 3>> facets) {
  for (std::array<int, 3>& t : facets) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(facets.begin(), facets.end());
  return facets;
}

// The conflicts add the same points at the same steps as the sweep, so they build the
// same triangles, coplanar facets included.
TEST(NormalHull, ConflictsBuildTheSweepsTriangles) {
  int n = 0;
  for_each_hull_case([&](const std::vector<Vec3>& f, const std::string& what) {
    std::vector<std::array<int, 3>> fast, sweep;
    const int k = static_cast<int>(f.size());
    const bool built = detail::normal_hull_facets(f.data(), k, &fast);
    ASSERT_EQ(built, detail::normal_hull_facets_by_sweep(f.data(), k, &sweep)) << what;
    EXPECT_EQ(canonical(fast), canonical(sweep)) << what;
    n += built;
  });
  EXPECT_GT(n, 250);
}

// best_margin_direction offers the hull's features in any order; its answer is, to the
// bit, that of offering them in the enumeration's order (vertices, edges and facets by
// sorted indices, + before -) and keeping the first of equal margins. The cube grid and
// the cone hold exact ties between facets.
TEST(BestMargin, OfEqualMarginsTheFirstInTheEnumerationsOrderWins) {
  int n = 0;
  for_each_hull_case([&](const std::vector<Vec3>& f, const std::string& what) {
    const int k = static_cast<int>(f.size());
    std::vector<std::array<int, 3>> facets;
    if (!detail::normal_hull_facets_by_sweep(f.data(), k, &facets)) return;
    std::vector<std::array<int, 3>> keys;
    for (int a = 0; a < k; ++a) keys.push_back({a, -1, -1});
    for (std::array<int, 3> t : facets) {
      std::sort(t.begin(), t.end());
      keys.push_back(t);
      keys.push_back({t[0], t[1], -1});
      keys.push_back({t[0], t[2], -1});
      keys.push_back({t[1], t[2], -1});
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    double best = -INFINITY;
    Vec3 best_n{0.0, 0.0, 0.0};
    for (const auto& [a, b, c] : keys) {
      const Vec3 x = b < 0 ? f[a] : c < 0 ? f[a] + f[b] : cross(f[b] - f[a], f[c] - f[a]);
      if (!(norm(x) > 0.0)) continue;
      for (const Vec3& dir : {x / norm(x), -x / norm(x)}) {
        double v = INFINITY;
        for (const Vec3& g : f) v = std::min(v, dot(g, dir));
        if (v > best) best = v, best_n = dir;
      }
    }
    const MostVisibleResult r = best_margin_direction(f.data(), k);
    EXPECT_EQ(r.visibility, best) << what;
    EXPECT_EQ(r.normal, best_n) << what;
    ++n;
  });
  EXPECT_GT(n, 250);
}

}  // namespace
}  // namespace blayer
