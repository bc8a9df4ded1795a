#include "blayer/extruder/extrude_layers.h"
#include "blayer/extruder/triangle_intersections.h"

namespace blayer {

std::vector<std::pair<int, int>> find_envelope_intersections(const TriSurface& wall, const ExtrusionResult& result,
                                                             std::size_t max_pairs) {
  std::vector<IndexedTriangle> tris;
  tris.reserve(2 * wall.triangles.size());
  for (const Triangle& t : wall.triangles) tris.push_back({t[0], t[1], t[2]});
  for (const Triangle& t : result.envelope.triangles)
    tris.push_back({result.envelope_point_ids[t[0]], result.envelope_point_ids[t[1]], result.envelope_point_ids[t[2]]});
  return find_triangle_intersections(result.mesh.points, tris, nullptr, max_pairs);
}

}  // namespace blayer
