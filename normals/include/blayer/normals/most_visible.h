// Most-visible normal (docs/normals.md, Part 1): n_MV = argmax_{|n|=1} min_i n.f_i, the
// centre of the smallest spherical cap holding the face normals f_i; V* = min_i n_MV.f_i.
//
// Algorithm: the min-norm point q* of conv{f_i} gives n_MV = q*/|q*| and V* = |q*|.
// most_visible_normal runs Wolfe's min-norm-point algorithm (Wolfe 1976; an exact
// active-set method that ends in finitely many steps) and accepts its answer only with
// the optimality certificate lambda >= 0 on the support (|S| <= 3) and
// f_j.q >= |q|^2 - slack for every j. Without a certificate (singular affine hull from
// rounding) it falls back to most_visible_by_enumeration, which tries every support of
// at most 3 distinct normals (duplicates closer than tol.duplicate_normal merged).
//
// No visible direction: when 0 lies in conv{f_i} (Gordan) or V* < tol.min_visibility,
// feasible is false and the result is the direction of best margin
// max_n min_i n.f_i = -dist(0, boundary of conv{f_i}) <= 0 (or the tiny V*), found by
// evaluating the directions of the hull's facets and edges (best_margin_direction); it
// is never a silent arbitrary vector.
//
// Input: k >= 1 unit vectors. Cost O(k) per Wolfe step (a few steps in practice);
// O(k^4) for the enumeration fallback, O(k^2) after a hull for the margin (O(k^4) when
// the normals span no volume).
#pragma once

#include <vector>

#include "blayer/core/tolerances.h"
#include "blayer/core/vec3.h"

namespace blayer {

struct MostVisibleResult {
  Vec3 normal{0.0, 0.0, 0.0};  // unit
  double visibility = 0.0;     // V* when feasible, else the best margin (<= V* small)
  bool feasible = false;       // V* >= tol.min_visibility with a certificate
  int support_size = 0;        // faces carrying positive multipliers (feasible only)
};

MostVisibleResult most_visible_normal(const Vec3* f, int k, const Tolerances& tol = default_tolerances());
MostVisibleResult most_visible_by_enumeration(const Vec3* f, int k,
                                              const Tolerances& tol = default_tolerances());
// The enumeration's answer from the supports on conv{f_i}'s boundary only: its vertices,
// edges and facets (exact predicates), O(k^2) after an O(k log k) hull instead of O(k^4);
// q* lies on the boundary when 0 is outside the hull, in a facet, edge or vertex of the
// triangulated hull. Equal to the enumeration up to rounding (a tie between supports that
// give the same q*); normals that span no volume go to the enumeration.
MostVisibleResult most_visible_on_hull(const Vec3* f, int k, const Tolerances& tol = default_tolerances());

// max over unit n of min_i n.f_i with its maximiser (the graded margin of a fan with no
// visible direction), by direct evaluation of the candidates built from the vertices,
// edges and facets of conv{f_i} (exact predicates), O(k^2) after an O(k log k) hull;
// normals that span no volume go to the enumeration below. Used when no visible
// direction exists.
MostVisibleResult best_margin_direction(const Vec3* f, int k);
// The same from every single face, pair and triple (facet normals, pair bisectors and
// great circles, single faces): O(k^4), the oracle of the above.
MostVisibleResult best_margin_direction_by_enumeration(const Vec3* f, int k);

// Wolfe's algorithm alone: kCertified with the certified min-norm point in *out (whose
// evaluated V may still fall below tol.min_visibility by rounding: out->feasible), or
// kNoVisibleDirection (V* below tol.min_visibility, or 0 in conv{f_i}), or kUncertified
// (no convergence within its step limit, or only singular faces where a new point is
// affinely dependent on the support),
// leaving *out unspecified. most_visible_normal is this plus its fallbacks, whose cost
// grows as k^4; callers that only profit from a certified answer skip them.
enum class WolfeOutcome { kCertified, kNoVisibleDirection, kUncertified };
WolfeOutcome wolfe_min_norm_point(const Vec3* f, int k, const Tolerances& tol, MostVisibleResult* out);

inline MostVisibleResult most_visible_normal(const std::vector<Vec3>& f,
                                             const Tolerances& tol = default_tolerances()) {
  return most_visible_normal(f.data(), static_cast<int>(f.size()), tol);
}

}  // namespace blayer
