#include "blayer/extruder/wall_planes.h"

#include <algorithm>
#include <cmath>

#include "parallel.h"

namespace blayer {

WallPlanes::WallPlanes(const TriSurface& wall, const ColumnLayout& layout, const WallTopology& topo)
    : origin_(layout.front.points) {
  const int nc = layout.n_columns();
  normal_.resize(wall.triangles.size());
  tbb::parallel_for(0, static_cast<int>(wall.triangles.size()),
                    [&](int f) { normal_[f] = normalized(triangle_area_vector(wall, wall.triangles[f])); });
  for (int c = 0; c < nc; ++c) {
    const Csr& vtri = topo.vertex_triangles;
    if (layout.faceless[c]) {
      normal_of_.items.push_back(static_cast<int>(normal_.size()));
      normal_.push_back(layout.direction[c]);
    } else {
      for (const int* t = vtri.begin(c); t != vtri.end(c); ++t)
        if (layout.wall_face[*t] >= 0) normal_of_.items.push_back(layout.wall_face[*t]);
    }
    normal_of_.start.push_back(static_cast<int>(normal_of_.items.size()));
  }
}

double WallPlanes::height_above(int v, const Vec3& q) const {
  double m = HUGE_VAL;
  const Vec3 r = q - origin_[v];
  for (const int* f = normal_of_.begin(v); f != normal_of_.end(v); ++f) m = std::min(m, dot(r, normal_[*f]));
  return m;
}

double WallPlanes::visibility(int v, const Vec3& d) const {
  double m = HUGE_VAL;
  for (const int* f = normal_of_.begin(v); f != normal_of_.end(v); ++f) m = std::min(m, dot(d, normal_[*f]));
  return m;
}

double WallPlanes::step_to_height(int v, const Vec3& from, const Vec3& d, double height) const {
  double s = -1.0;
  const Vec3 r = from - origin_[v];
  for (const int* f = normal_of_.begin(v); f != normal_of_.end(v); ++f) {
    const double b = dot(d, normal_[*f]);
    if (b > 0.0) s = std::max(s, (height - dot(r, normal_[*f])) / b);
  }
  return s;
}

}  // namespace blayer
