#include "blayer/core/surface_components.h"

#include "blayer/core/assert.h"
#include "blayer/core/union_find.h"

namespace blayer {

SurfaceComponents edge_connected_components(const TriSurface& s, const EdgeTopology& edges) {
  const int nt = static_cast<int>(s.triangles.size());
  UnionFind sets(nt);
  for (const SurfaceEdge& e : edges.edges) {
    BLAYER_ASSERT_MSG(e.triangle[0] < nt && e.triangle[1] < nt, "edge topology belongs to another surface");
    if (e.n_uses == 2) sets.unite(e.triangle[0], e.triangle[1]);
  }
  SurfaceComponents out;
  out.of_triangle.resize(nt);
  std::vector<int> label_of_root(nt, -1);
  for (int t = 0; t < nt; ++t) {
    const int r = sets.find(t);
    if (label_of_root[r] < 0) label_of_root[r] = out.count++;
    out.of_triangle[t] = label_of_root[r];
  }
  return out;
}

std::vector<double> component_signed_volumes(const TriSurface& s, const SurfaceComponents& components) {
  BLAYER_ASSERT(components.of_triangle.size() == s.triangles.size());
  Vec3 r{0, 0, 0};
  for (const Vec3& p : s.points) r += p;
  if (!s.points.empty()) r = r / static_cast<double>(s.points.size());
  std::vector<double> volume(components.count, 0.0);
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const Triangle& tr = s.triangles[t];
    const Vec3 a = s.points[tr[0]] - r, b = s.points[tr[1]] - r, c = s.points[tr[2]] - r;
    volume[components.of_triangle[t]] += dot(a, cross(b, c));
  }
  for (double& v : volume) v /= 6.0;
  return volume;
}

}  // namespace blayer
