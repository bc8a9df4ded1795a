#include "blayer/extruder/wall_planes.h"

#include <algorithm>
#include <cmath>

#include "parallel.h"

namespace blayer {

WallPlanes::WallPlanes(const TriSurface& wall, const WallTopology& topo)
    : points_(&wall.points), vertex_triangles_(&topo.vertex_triangles), face_normal_(wall.triangles.size()) {
  tbb::parallel_for(0, static_cast<int>(wall.triangles.size()),
                    [&](int f) { face_normal_[f] = normalized(triangle_area_vector(wall, wall.triangles[f])); });
}

double WallPlanes::height_above(int v, const Vec3& q) const {
  double m = HUGE_VAL;
  const Vec3 r = q - (*points_)[v];
  for (const int* f = vertex_triangles_->begin(v); f != vertex_triangles_->end(v); ++f)
    m = std::min(m, dot(r, face_normal_[*f]));
  return m;
}

double WallPlanes::visibility(int v, const Vec3& d) const {
  double m = HUGE_VAL;
  for (const int* f = vertex_triangles_->begin(v); f != vertex_triangles_->end(v); ++f)
    m = std::min(m, dot(d, face_normal_[*f]));
  return m;
}

double WallPlanes::step_to_height(int v, const Vec3& from, const Vec3& d, double height) const {
  double s = -1.0;
  const Vec3 r = from - (*points_)[v];
  for (const int* f = vertex_triangles_->begin(v); f != vertex_triangles_->end(v); ++f) {
    const double b = dot(d, face_normal_[*f]);
    if (b > 0.0) s = std::max(s, (height - dot(r, face_normal_[*f])) / b);
  }
  return s;
}

}  // namespace blayer
