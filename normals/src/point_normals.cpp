#include "blayer/normals/point_normals.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/most_normal.h"
#include "blayer/normals/vertex_normal.h"
#include "blayer/normals/weighted_normal.h"

namespace blayer {

namespace {

struct MethodName {
  NormalMethod method;
  const char* name;
};

constexpr MethodName kMethodNames[] = {
    {NormalMethod::kMostNormal, "most-normal"}, {NormalMethod::kMostVisible, "most-visible"},
    {NormalMethod::kAngle, "angle"},            {NormalMethod::kArea, "area"},
    {NormalMethod::kUnit, "unit"},              {NormalMethod::kInverseArea, "inverse-area"},
    {NormalMethod::kMax, "max"},
};

}  // namespace

const char* normal_method_name(NormalMethod m) {
  for (const MethodName& e : kMethodNames)
    if (e.method == m) return e.name;
  return "unknown";
}

bool parse_normal_method(const std::string& name, NormalMethod* out) {
  for (const MethodName& e : kMethodNames)
    if (name == e.name) {
      *out = e.method;
      return true;
    }
  return false;
}

std::vector<std::string> normal_method_names() {
  std::vector<std::string> names;
  for (const MethodName& e : kMethodNames) names.emplace_back(e.name);
  return names;
}

const char* normal_status_name(NormalStatus s) {
  switch (s) {
    case NormalStatus::kOk: return "ok";
    case NormalStatus::kNonUnique: return "non-unique";
    case NormalStatus::kVisibilityConstrained: return "visibility-constrained";
    case NormalStatus::kNoVisibleDirection: return "no-visible-direction";
    case NormalStatus::kDegenerateFan: return "degenerate-fan";
    case NormalStatus::kBoundary: return "boundary";
  }
  return "unknown";
}

PointNormals compute_point_normals(const TriSurface& s, const VertexFans& fans, NormalMethod method,
                                   const Tolerances& tol) {
  return compute_point_normals(s, fans, method, tol, nullptr, nullptr);
}

PointNormals compute_point_normals(const TriSurface& s, const VertexFans& fans, NormalMethod method,
                                   const Tolerances& tol, std::vector<MostNormalWarmStart>* warm,
                                   WarmStartCounts* counts) {
  const std::size_t nv = s.points.size();
  PointNormals out;
  out.normal.assign(nv, Vec3{0.0, 0.0, 0.0});
  out.visibility.assign(nv, 0.0);
  out.normality.assign(nv, 0.0);
  out.status.assign(nv, NormalStatus::kDegenerateFan);
  if (warm && warm->size() < nv) warm->resize(nv);
  std::atomic<long> n_warm{0}, n_hits{0};
  // Each vertex writes only its own slots, so the result does not depend on the
  // partition or the thread count.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, std::min(nv, fans.fans.size()), 256),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      std::vector<Vec3> ring;
                      FanGeometry g;
                      long local_warm = 0, local_hits = 0;
                      for (std::size_t v = range.begin(); v != range.end(); ++v) {
                        const VertexFan& fan = fans.fans[v];
                        if (fan.triangles.empty()) {
                          if (warm) (*warm)[v] = MostNormalWarmStart{};
                          continue;
                        }
                        ring.clear();
                        for (int r : fan.ring) ring.push_back(s.points[r]);
                        build_fan_geometry(s.points[v], ring, fan.closed, tol, &g);
                        VertexNormal vn;
                        if (warm) {
                          bool hit = false;
                          local_warm += (*warm)[v].valid ? 1 : 0;
                          vn = compute_vertex_normal(g, method, tol, &(*warm)[v], &hit);
                          local_hits += hit ? 1 : 0;
                        } else {
                          vn = compute_vertex_normal(g, method, tol);
                        }
                        out.normal[v] = vn.normal;
                        out.visibility[v] = vn.visibility;
                        out.normality[v] = vn.normality;
                        out.status[v] = vn.status;
                      }
                      n_warm += local_warm;
                      n_hits += local_hits;
                    });
  if (counts) {
    counts->warm = n_warm;
    counts->hits = n_hits;
  }
  return out;
}

}  // namespace blayer
