#include "tet_plc.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "blayer/core/assert.h"
#include "blayer/core/errors.h"
#include "blayer/core/point_in_surface.h"
#include "blayer/fill/tet_fill.h"

namespace blayer::fill_detail {
namespace {

// Hole seeds are tried at these fractions of sqrt(triangle area) behind a triangle:
// the first that the parity test accepts is used, so a thin body still gets one.
constexpr double kHoleDepths[] = {0.1, 0.01, 0.001};
// Number of the largest triangles of a body tried as hole-seed bases.
constexpr int kHoleCandidates = 16;

void check_distinct_points(const std::vector<Vec3>& points) {
  std::vector<int> idx(points.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::sort(idx.begin(), idx.end(), [&](int a, int b) { return points[a] < points[b]; });
  for (std::size_t i = 1; i < idx.size(); ++i)
    if (points[idx[i]] == points[idx[i - 1]])
      throw InputError("two boundary points coincide at " + format_point(points[idx[i]]) +
                       "; merge duplicate points before the fill");
}

// A point behind the triangles of body c that ray parity confirms, if any.
bool find_hole_point(const TriSurface& envelope, std::vector<int> tris, bool outside, double length_scale,
                     Vec3* hole) {
  const int n_try = std::min<int>(kHoleCandidates, static_cast<int>(tris.size()));
  std::partial_sort(tris.begin(), tris.begin() + n_try, tris.end(), [&](int a, int b) {
    return norm2(triangle_area_vector(envelope, envelope.triangles[a])) >
           norm2(triangle_area_vector(envelope, envelope.triangles[b]));
  });
  for (int i = 0; i < n_try; ++i) {
    const Triangle& tri = envelope.triangles[tris[i]];
    const Vec3 area2 = triangle_area_vector(envelope, tri);
    const Vec3 centroid = (envelope.points[tri[0]] + envelope.points[tri[1]] + envelope.points[tri[2]]) / 3.0;
    const double size = std::sqrt(0.5 * norm(area2));
    for (double depth : kHoleDepths) {
      const Vec3 seed = centroid - (depth * size) * normalized(area2);
      const Containment c = point_in_closed_surface(envelope, seed, length_scale);
      // Not in the fill region: inside a body for outside, outside every wall for inside.
      if (c == (outside ? Containment::kInside : Containment::kOutside)) {
        *hole = seed;
        return true;
      }
    }
  }
  return false;
}

}  // namespace

UsedPoints used_points(const TriSurface& s) {
  UsedPoints u;
  u.local_of.assign(s.points.size(), -1);
  for (const Triangle& t : s.triangles)
    for (int v : t) u.local_of[v] = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (u.local_of[i] == 0) {
      u.local_of[i] = static_cast<int>(u.used.size());
      u.used.push_back(static_cast<int>(i));
    }
  return u;
}

FillPlc assemble_plc(const TriSurface& envelope, UsedPoints envelope_points, const OuterBoundary& outer) {
  const TriSurface& farfield = outer.surface;
  FillPlc plc;
  plc.envelope = std::move(envelope_points);
  // The farfield's own points that its triangles use (envelope points they name are the
  // envelope's).
  plc.farfield.local_of.assign(farfield.points.size(), -1);
  for (const Triangle& t : farfield.triangles)
    for (int v : t)
      if (!outer.is_envelope_point(v)) plc.farfield.local_of[v] = 0;
  for (std::size_t i = 0; i < farfield.points.size(); ++i)
    if (plc.farfield.local_of[i] == 0) {
      plc.farfield.local_of[i] = static_cast<int>(plc.farfield.used.size());
      plc.farfield.used.push_back(static_cast<int>(i));
    }
  plc.n_envelope_triangles = envelope.triangles.size();
  BLAYER_ASSERT(plc.envelope.local_of.size() == envelope.points.size());
  for (int i : plc.envelope.used) plc.points.push_back(envelope.points[i]);
  for (int i : plc.farfield.used) plc.points.push_back(farfield.points[i]);
  check_distinct_points(plc.points);
  const int n_local_envelope = static_cast<int>(plc.envelope.used.size());
  TetgenPlc& t = plc.tetgen;
  for (const Vec3& p : plc.points) t.points.insert(t.points.end(), p.begin(), p.end());
  for (const Triangle& tri : envelope.triangles) {
    for (int v : tri) t.triangles.push_back(plc.envelope.local_of[v]);
    t.markers.push_back(kEnvelopeMarker);
  }
  for (std::size_t f = 0; f < farfield.triangles.size(); ++f) {
    for (int v : farfield.triangles[f])
      t.triangles.push_back(outer.is_envelope_point(v) ? plc.envelope.local_of[outer.envelope_point(v)]
                                                       : n_local_envelope + plc.farfield.local_of[v]);
    t.markers.push_back(outer.markers[f]);
  }
  return plc;
}

std::string describe_plc_face(const FillPlc& plc, const std::array<int, 3>& face) {
  std::array<int, 3> k = face;
  std::sort(k.begin(), k.end());
  const std::size_t n_boundary = plc.tetgen.triangles.size() / 3;
  for (std::size_t t = 0; t < n_boundary; ++t) {
    std::array<int, 3> g{plc.tetgen.triangles[3 * t], plc.tetgen.triangles[3 * t + 1],
                         plc.tetgen.triangles[3 * t + 2]};
    std::sort(g.begin(), g.end());
    if (g != k) continue;
    const bool env = t < plc.n_envelope_triangles;
    const std::size_t id = env ? t : t - plc.n_envelope_triangles;
    const Vec3 c = (plc.points[face[0]] + plc.points[face[1]] + plc.points[face[2]]) / 3.0;
    return std::string(env ? "envelope" : "farfield") + " triangle " + std::to_string(id) + " near " +
           format_point(c);
  }
  return "a triangle TetGen created";
}

std::vector<Vec3> hole_points(const TriSurface& envelope, const EnvelopeParts& parts, bool outside,
                              double length_scale) {
  std::vector<Vec3> holes;
  for (int c = 0; c < parts.components.count; ++c) {
    if (parts.volume[c] < 0.0) continue;
    std::vector<int> tris;
    for (std::size_t t = 0; t < envelope.triangles.size(); ++t)
      if (parts.components.of_triangle[t] == c) tris.push_back(static_cast<int>(t));
    Vec3 hole;
    if (!find_hole_point(envelope, std::move(tris), outside, length_scale, &hole))
      throw InputError("envelope component " + std::to_string(c) +
                       ": found no point inside its body for TetGen's hole seed (ray-parity tests "
                       "disagree); the envelope is probably self-intersecting or nested");
    holes.push_back(hole);
  }
  return holes;
}

}  // namespace blayer::fill_detail
