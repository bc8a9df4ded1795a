// Exact intersection tests between closed triangles, and a checker that finds every
// intersecting pair in a triangle soup with shared vertex ids (e.g. an envelope together
// with its wall). All decisions use the exact orient3d of quality/orient3d.h; touching
// counts as intersecting.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "blayer/core/triangle_ids.h"
#include "blayer/core/vec3.h"

namespace blayer {

// Closed segment pq against closed triangle abc, including the coplanar case (decided in
// the projection that drops the dominant axis of the triangle's normal). The triangle
// must not be degenerate (collinear corners); the segment may be a point.
bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c);

// Do the two closed triangles of a soup meet anywhere other than at the vertex ids they
// share?  Sharing three ids: the same face, never an intersection. Sharing an edge: only
// a coplanar fold (the two opposite corners on the same side of the edge) counts.
// Sharing one vertex v: (v,a,b) and (v,c,d) meet beyond v iff segment ab meets the
// second triangle or cd meets the first (the common part of two triangles through v
// ends on one of these opposite edges). Otherwise: iff an edge of one meets the other.
// A triangle that names one id twice (a fan strip's half where the fan did not grow) is
// a segment of its neighbours' edges, not a face: it meets nothing.
bool soup_triangles_intersect(const std::vector<Vec3>& points, const IndexedTriangle& s,
                              const IndexedTriangle& t);

// The same on 32-bit ids, for soups of fewer than 2^31 points: the front checker's
// tables of them, read at every pair its trees give, take half the cache.
using SoupTriangle = std::array<std::int32_t, 3>;
bool compact_soup_triangles_intersect(const std::vector<Vec3>& points, const SoupTriangle& s, const SoupTriangle& t);

// The ring of a star: the triangles (v, a_i, b_i), each as its winding runs from v and
// given in any order, as one path or one cycle of distinct points other than v:
// *ring receives a_0, then each next point (b of the triangle whose a is the point
// before), *closed whether the last point leads back to the first. False where the
// triangles form no such ring (a point with two triangles on one side, two rings, a
// triangle naming v or one point twice).
bool order_star_ring(std::int32_t v, const std::array<std::int32_t, 2>* triangles, int n,
                     std::vector<std::int32_t>* ring, bool* closed);

// A certificate for the star of soup point v whose ring (as order_star_ring gives it)
// is ring[0..m): true means that no two of its triangles that share only v (as ids)
// meet anywhere else, so their pair tests may be skipped; false means "not certified",
// never "they meet".
// It holds when, in the projection along a direction near the star's vector area
// (exactly along q - v for a point q rounded from it), every triangle has a non-zero
// area of one sign (its angle at v is then convex and turns one way) and no triangle other than
// those at ring[0] holds ring[0]'s direction in its closed angle at v. The angles then
// turn through less than one full turn along a path (exactly one around a cycle: a
// second turn would pass ring[0]'s direction inside another triangle's angle), so the
// angles of two triangles that share only v have only v's projection in common, and
// the triangles only v (a triangle whose projection has an area holds no other point
// that projects onto v's). Decided by the floating-point filter of the exact
// orientation; where it cannot decide, the star is not certified. A ring that names a
// point twice fails these conditions (its second visit is a full turn on). About 2m
// orientations, where the pair tests it replaces are O(m^2).
bool star_pairs_meet_only_at_centre(const std::vector<Vec3>& points, std::int32_t v, const std::int32_t* ring,
                                    int m, bool closed);

// All pairs (i < j) of intersecting triangles per soup_triangles_intersect, found with a
// TriangleBvh over the triangles' boxes, in increasing (i, j) order. If `check` is given
// (one flag per triangle) only pairs with at least one flagged triangle are tested.
// Returns the first max_pairs of them in that order. Parallel; the result is
// deterministic.
std::vector<std::pair<int, int>> find_triangle_intersections(
    const std::vector<Vec3>& points, const std::vector<IndexedTriangle>& triangles,
    const std::vector<char>* check = nullptr,
    std::size_t max_pairs = std::numeric_limits<std::size_t>::max());

}  // namespace blayer
