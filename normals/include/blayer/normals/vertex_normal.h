// The normal of a single vertex fan by any NormalMethod, with its diagnostics. This is
// the per-vertex kernel of compute_point_normals, exposed for callers that work on
// isolated fans (tests, re-computation after local edits).
//
// Contract: g from build_fan_geometry. Result normal is unit length except when no
// direction can be formed (no usable triangle), where it is zero with kDegenerateFan.
// visibility = V(normal), normality = D(normal) (radians), both over the fan's faces.
// Fallbacks:
//   - any degenerate triangle, or a folded link (most-normal only): angle average,
//     kDegenerateFan;
//   - open fan (boundary vertex): most-visible of the half fan for most-normal and
//     most-visible (the fluid region of an open link is undefined), the weighted average
//     for the others; kBoundary;
//   - no visible direction (most-normal, most-visible): the direction of best margin
//     max_n min_i n.f_i <= 0 (or below tol.min_visibility), kNoVisibleDirection, the
//     margin in visibility.
#pragma once

#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/most_normal.h"
#include "blayer/normals/point_normals.h"

namespace blayer {

struct VertexNormal {
  Vec3 normal{0.0, 0.0, 0.0};
  double visibility = 0.0;
  double normality = 0.0;
  NormalStatus status = NormalStatus::kOk;
};

VertexNormal compute_vertex_normal(const FanGeometry& g, NormalMethod method,
                                   const Tolerances& tol = default_tolerances());

// The same with a most-normal warm start (most_normal.h): *warm in and out, *hit
// (optional) whether its certificate held. Methods other than most-normal, and every
// fallback, leave *warm invalid.
VertexNormal compute_vertex_normal(const FanGeometry& g, NormalMethod method, const Tolerances& tol,
                                   MostNormalWarmStart* warm, bool* hit = nullptr);

}  // namespace blayer
