// The convex hull of a fan's unit face normals, for the margin of a fan with no visible
// direction (most_visible.h, best_margin_direction) and for the cap of the link vertices
// where Wolfe's iteration is uncertified (most_visible_on_hull): its facets, as triples
// of indices into the normals. Internal to blayer_normals; exact through the filtered
// orient3d of blayer_quality.
#pragma once

#include <array>
#include <vector>

#include "blayer/core/vec3.h"

namespace blayer {
namespace detail {

// The triangles of the hull of f[0..k-1] (coplanar facets triangulated), wound with
// their normals pointing out of the hull; a repeated point is named by one of its
// indices. Returns false, leaving *facets empty, when the points span no volume (k < 4,
// all coplanar) or a coordinate is not finite. Exact predicates. Beneath-beyond in index
// order with conflicts: each point is tested against the facets it may see, not against
// every facet, in about O(k log k) tests.
bool normal_hull_facets(const Vec3* f, int k, std::vector<std::array<int, 3>>* facets);

// The same triangles (in another order) by the plain sweep: each point in index order
// against every facet, O(k h) tests. The oracle of the tests, and the answer where the
// conflicts meet a patch whose rim is not one cycle.
bool normal_hull_facets_by_sweep(const Vec3* f, int k, std::vector<std::array<int, 3>>* facets);

}  // namespace detail
}  // namespace blayer
