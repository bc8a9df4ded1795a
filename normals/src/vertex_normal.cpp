#include "blayer/normals/vertex_normal.h"

#include "blayer/normals/most_normal.h"
#include "blayer/normals/most_visible.h"
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
  return compute_vertex_normal(g, method, tol, nullptr, nullptr);
}

VertexNormal compute_vertex_normal(const FanGeometry& g, NormalMethod method, const Tolerances& tol,
                                   MostNormalWarmStart* warm, bool* hit) {
  if (hit) *hit = false;
  const bool weighted = method != NormalMethod::kMostNormal && method != NormalMethod::kMostVisible;
  const bool most_normal = method == NormalMethod::kMostNormal && g.n_faces() > 0 && !g.any_degenerate && g.closed;
  if (warm && !most_normal) *warm = MostNormalWarmStart{};
  if (g.n_faces() == 0) return finish(g, Vec3{0.0, 0.0, 0.0}, NormalStatus::kDegenerateFan);
  if (g.any_degenerate) {
    return finish(g, weighted_average_normal(g, NormalMethod::kAngle), NormalStatus::kDegenerateFan);
  }
  if (weighted) {
    const Vec3 n = weighted_average_normal(g, method);
    if (norm2(n) == 0.0) return finish(g, n, NormalStatus::kDegenerateFan);
    return finish(g, n, g.closed ? NormalStatus::kOk : NormalStatus::kBoundary);
  }
  if (method == NormalMethod::kMostVisible || !g.closed) {
    const MostVisibleResult mv = most_visible_normal(g.face_normals.data(), g.n_faces(), tol);
    VertexNormal r;
    r.normal = mv.normal;
    r.visibility = mv.visibility;
    r.normality = fan_normality(g, mv.normal);
    r.status = !mv.feasible ? NormalStatus::kNoVisibleDirection
                            : (g.closed ? NormalStatus::kOk : NormalStatus::kBoundary);
    return r;
  }
  const MostNormalResult mn = warm ? most_normal_normal(g, warm, hit, tol) : most_normal_normal(g, tol);
  VertexNormal r;
  r.normal = mn.normal;
  r.visibility = mn.visibility;
  r.normality = mn.normality;
  r.status = mn.status;
  return r;
}

}  // namespace blayer
