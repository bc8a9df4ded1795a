// Point normals of a triangle surface, one per vertex, by a chosen method, with the
// per-vertex diagnostics every caller needs (visibility, normality, status).
//
// Methods (maths and references in docs/normals.md):
//   most-normal   (default) maximises the minimum angle D between n and the incident
//                 triangles (largest empty circle among the link arcs on the unit sphere),
//                 subject to visibility V >= V*/2; ties broken by larger D, then larger V.
//   most-visible  maximises V = min_i n.f_i (minimum-norm point of conv{f_i}).
//   angle, area, unit, inverse-area, max: classic weighted averages of face normals.
#pragma once

#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/core/tolerances.h"
#include "blayer/core/vertex_fans.h"

namespace blayer {

enum class NormalMethod { kMostNormal, kMostVisible, kAngle, kArea, kUnit, kInverseArea, kMax };

// Names as used on the command line: "most-normal", "most-visible", "angle", "area",
// "unit", "inverse-area", "max". parse returns false for an unknown name.
const char* normal_method_name(NormalMethod m);
bool parse_normal_method(const std::string& name, NormalMethod* out);
std::vector<std::string> normal_method_names();

// Written as the int array `normal_status`; the values are part of the output contract.
enum class NormalStatus : int {
  kOk = 0,
  kNonUnique = 1,              // a plateau of optimal directions; tie-break applied
  kVisibilityConstrained = 2,  // the unconstrained most-normal optimum was invisible
  kNoVisibleDirection = 3,     // no n with all n.f_i > 0; normal is the best-margin one
  kDegenerateFan = 4,          // zero-area or folded fan; normal is the angle average
  kBoundary = 5,               // open-surface boundary vertex (half fan)
};

const char* normal_status_name(NormalStatus s);

struct PointNormals {
  std::vector<Vec3> normal;        // unit length
  std::vector<double> visibility;  // min over incident faces of n.f_i
  std::vector<double> normality;   // min angle (radians) between n and the incident triangles
  std::vector<NormalStatus> status;
};

// Normals at every point of s (fans from build_vertex_fans(s)). Points without
// triangles get a zero normal and kDegenerateFan. Runs in parallel over vertices.
PointNormals compute_point_normals(const TriSurface& s, const VertexFans& fans, NormalMethod method,
                                   const Tolerances& tol = default_tolerances());

struct MostNormalWarmStart;  // most_normal.h

// What the warm starts of one compute_point_normals call did (most-normal only).
struct WarmStartCounts {
  long warm = 0;  // points whose warm start was valid on entry
  long hits = 0;  // of those, points whose certificate held (the rebuilt optimum stood)
  double hit_rate() const { return warm > 0 ? static_cast<double>(hits) / static_cast<double>(warm) : 0.0; }
};

// The same, warm-started across the fronts of one surface (same points and triangles,
// the points moved): *warm holds one MostNormalWarmStart per point (most_normal.h),
// resized to the point count if shorter; on return it describes these normals, ready
// for the next front. Start with an empty vector. The normals are those of the call
// without warm starts (ties aside, see most_normal.h); only the most-normal method
// uses them, the others leave *warm empty of valid entries. *counts (optional) receives
// the hit rate.
PointNormals compute_point_normals(const TriSurface& s, const VertexFans& fans, NormalMethod method,
                                   const Tolerances& tol, std::vector<MostNormalWarmStart>* warm,
                                   WarmStartCounts* counts = nullptr);

}  // namespace blayer
