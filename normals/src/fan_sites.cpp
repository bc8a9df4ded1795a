#include "fan_sites.h"

#include <algorithm>
#include <cmath>

namespace blayer {
namespace detail {

void build_fan_sites(const FanGeometry& g, const Tolerances& tol, FanSites* out) {
  FanSites& s = *out;
  const int k = g.n_faces();
  s.arcs.clear();
  s.points.clear();
  s.arc_of_face.assign(k, -1);
  s.point_of_vertex.assign(k, -1);
  thread_local std::vector<char> straight;
  straight.assign(k, 0);
  bool all_reflex = true;
  for (int j = 0; j < k; ++j) {
    const int a = (j + k - 1) % k;
    const double side = dot(g.face_normals[a], g.dirs[(j + 1) % k]);
    straight[j] = std::fabs(side) <= tol.coplanar_arc && dot(g.face_normals[a], g.face_normals[j]) > 0.0;
    const bool reflex = !straight[j] && side < 0.0;
    if (reflex) {
      s.point_of_vertex[j] = static_cast<int>(s.points.size());
      s.points.push_back({g.dirs[j], j});
    }
    all_reflex &= straight[j] || reflex;
  }
  s.all_reflex = all_reflex;
  int start = 0;
  while (start < k && straight[start]) ++start;
  if (start == k) start = 0;
  for (int c = 0; c < k;) {
    const int i0 = (start + c) % k;
    double length = g.angles[i0];
    int len = 1;
    while (c + len < k) {
      const int j = (start + c + len) % k;
      if (!straight[j] || length + g.angles[j] >= M_PI) break;
      length += g.angles[j];
      ++len;
    }
    const int id = static_cast<int>(s.arcs.size());
    for (int t = 0; t < len; ++t) s.arc_of_face[(i0 + t) % k] = id;
    s.arcs.push_back({g.dirs[i0], g.dirs[(i0 + len) % k], g.face_normals[i0], i0, len});
    c += len;
  }
}

void same_plane_runs(const FanGeometry& g, std::vector<int>* first) {
  const int k = g.n_faces();
  first->resize(k);
  for (int j = 0; j < k; ++j) {
    const int f = j > 0 ? (*first)[j - 1] : 0;
    (*first)[j] = norm2(g.face_normals[j] - g.face_normals[f]) <= kSamePlaneNormal * kSamePlaneNormal ? f : j;
  }
}

void drop_repeated_planes(const std::vector<int>& first, std::vector<int>* faces) {
  thread_local std::vector<char> seen;
  seen.assign(first.size(), 0);
  faces->erase(std::remove_if(faces->begin(), faces->end(),
                              [&](int i) {
                                char& s = seen[first[i]];
                                const bool repeated = s != 0;
                                s = 1;
                                return repeated;
                              }),
               faces->end());
}

}  // namespace detail
}  // namespace blayer
