#include "blayer/normals/vertex_normal.h"

#include "blayer/normals/weighted_normal.h"

namespace blayer {

namespace {

VertexNormal finish(const FanGeometry& g, const Vec3& n, NormalStatus status) {
  VertexNormal r;
  r.normal = n;
  r.status = status;
  r.visibility = fan_visibility(g, n);
  r.normality = fan_normality(g, n);
  return r;
}

}  // namespace

VertexNormal compute_vertex_normal(const FanGeometry& g, NormalMethod method, const Tolerances& tol) {
  (void)tol;
  const bool weighted = method != NormalMethod::kMostNormal && method != NormalMethod::kMostVisible;
  const Vec3 angle = weighted_average_normal(g, weighted ? method : NormalMethod::kAngle);
  if (norm2(angle) == 0.0) return finish(g, angle, NormalStatus::kDegenerateFan);
  if (g.any_degenerate) return finish(g, angle, NormalStatus::kDegenerateFan);
  if (!g.closed) return finish(g, angle, NormalStatus::kBoundary);
  return finish(g, angle, NormalStatus::kOk);
}

}  // namespace blayer
