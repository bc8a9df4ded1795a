#include "blayer/fill/fill_envelope.h"

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "blayer/core/triangle_ids.h"
#include "blayer/io/mesh_faces.h"
#include "blayer/quality/quad_cap.h"

namespace blayer {

namespace {

// The apex of the cap over quad q (nodes ordered with the normal out of the layers). The
// extruder accepts a fan strip's cell only if its quad that can end on the envelope can
// be capped (layer_cells.h); a quad that cannot is an internal failure.
Vec3 cap_apex(const std::array<Vec3, 4>& q, const std::array<std::int64_t, 4>& ids) {
  if (const std::optional<Vec3> apex = quad_cap_apex(q)) return *apex;
  throw std::runtime_error("fill: no valid pyramid caps the envelope quad (" + std::to_string(ids[0]) + ", " +
                           std::to_string(ids[1]) + ", " + std::to_string(ids[2]) + ", " + std::to_string(ids[3]) +
                           ") of the layer mesh");
}

void append_caps(const std::vector<std::array<std::int64_t, 5>>& caps, const std::vector<Vec3>& apexes,
                 VolumeMesh* mesh) {
  for (std::size_t i = 0; i < caps.size(); ++i) {
    mesh->points.push_back(apexes[i]);
    mesh->add_cell(CellType::kPyramid, caps[i].data());
  }
  for (DataArray& a : mesh->point_data) a.values.resize(mesh->points.size() * a.n_components, 0.0);
  for (DataArray& a : mesh->cell_data)
    a.values.resize(mesh->n_cells() * a.n_components, a.name == "layer" ? -1.0 : 0.0);
}

}  // namespace

FillEnvelope fill_envelope(const TriSurface& envelope, const std::vector<std::int64_t>& envelope_point_ids,
                           VolumeMesh* layers) {
  FillEnvelope out;
  // Distinct mesh points, in the order of first use.
  std::map<std::int64_t, int> index_of;
  for (std::int64_t id : envelope_point_ids)
    if (index_of.emplace(id, static_cast<int>(out.point_ids.size())).second) out.point_ids.push_back(id);
  std::map<TriangleKey, int> triangle_of;
  std::vector<Triangle> tris;
  for (const Triangle& t : envelope.triangles) {
    const std::int64_t a = envelope_point_ids[t[0]], b = envelope_point_ids[t[1]], c = envelope_point_ids[t[2]];
    if (names_a_point_twice({a, b, c})) continue;
    triangle_of.emplace(sorted_triangle(a, b, c), static_cast<int>(tris.size()));
    tris.push_back({index_of[a], index_of[b], index_of[c]});
  }
  // Quad boundary faces of the layer mesh whose halves (either diagonal) are envelope
  // triangles.
  const MeshFaces faces = build_mesh_faces(*layers);
  std::vector<char> capped(tris.size(), 0);
  std::vector<std::array<std::int64_t, 5>> caps;
  std::vector<Vec3> apexes;
  const std::int64_t first_apex = static_cast<std::int64_t>(layers->points.size());
  for (std::size_t f = faces.n_internal; f < faces.size(); ++f) {
    if (faces.n_nodes[f] != 4) continue;
    const std::array<std::int64_t, 4>& q = faces.nodes[f];
    int halves[2] = {-1, -1};
    for (int diagonal = 0; diagonal < 2 && halves[1] < 0; ++diagonal) {
      const std::array<TriangleKey, 2> keys = quad_halves(q, diagonal);
      auto a = triangle_of.find(keys[0]);
      auto b = triangle_of.find(keys[1]);
      if (a != triangle_of.end() && b != triangle_of.end()) {
        halves[0] = a->second;
        halves[1] = b->second;
      }
    }
    if (halves[1] < 0) continue;
    capped[halves[0]] = capped[halves[1]] = 1;
    std::array<Vec3, 4> p;
    for (int i = 0; i < 4; ++i) p[i] = layers->points[q[i]];
    const std::int64_t apex = first_apex + static_cast<std::int64_t>(caps.size());
    apexes.push_back(cap_apex(p, q));
    caps.push_back({q[0], q[1], q[2], q[3], apex});
  }
  out.surface.points.reserve(out.point_ids.size() + caps.size());
  for (std::int64_t id : out.point_ids) out.surface.points.push_back(layers->points[id]);
  for (std::size_t t = 0; t < tris.size(); ++t)
    if (!capped[t]) out.surface.triangles.push_back(tris[t]);
  for (std::size_t i = 0; i < caps.size(); ++i) {
    const int apex = static_cast<int>(out.surface.points.size());
    out.surface.points.push_back(apexes[i]);
    out.point_ids.push_back(first_apex + static_cast<std::int64_t>(i));
    for (int k = 0; k < 4; ++k)
      out.surface.triangles.push_back({index_of[caps[i][k]], index_of[caps[i][(k + 1) % 4]], apex});
  }
  append_caps(caps, apexes, layers);
  out.n_caps = static_cast<std::int64_t>(caps.size());
  return out;
}

}  // namespace blayer
