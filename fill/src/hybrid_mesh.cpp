#include "blayer/fill/hybrid_mesh.h"

#include <algorithm>
#include <set>
#include <utility>

#include "blayer/core/assert.h"
#include "blayer/io/mesh_faces.h"

namespace blayer {

std::vector<std::int64_t> append_fill(const FillResult& fill, const std::vector<std::int64_t>& envelope_point_ids,
                                      VolumeMesh* mesh) {
  const std::size_t n_envelope = envelope_point_ids.size();
  BLAYER_ASSERT_MSG(static_cast<std::int64_t>(n_envelope) == fill.stats.n_envelope_points,
                    "one layer-mesh point per envelope point of the fill");
  std::vector<std::int64_t> to_mesh(fill.tets.points.size());
  for (std::size_t i = 0; i < n_envelope; ++i) {
    const std::int64_t id = envelope_point_ids[i];
    BLAYER_ASSERT(id >= 0 && id < static_cast<std::int64_t>(mesh->points.size()));
    BLAYER_ASSERT_MSG(mesh->points[id] == fill.tets.points[i], "the fill's envelope points are the layers' tops");
    to_mesh[i] = id;
  }
  for (std::size_t i = n_envelope; i < fill.tets.points.size(); ++i) {
    to_mesh[i] = static_cast<std::int64_t>(mesh->points.size());
    mesh->points.push_back(fill.tets.points[i]);
  }
  require_indexable_points(mesh->points.size(), "layers and fill");
  const std::size_t n_layer_cells = mesh->n_cells();
  for (std::size_t c = 0; c < fill.tets.n_cells(); ++c) {
    BLAYER_ASSERT(fill.tets.cell_types[c] == CellType::kTet);
    std::int64_t nodes[4];
    for (int k = 0; k < 4; ++k) nodes[k] = to_mesh[fill.tets.connectivity[fill.tets.offsets[c] + k]];
    mesh->add_cell(CellType::kTet, nodes);
  }
  for (DataArray& a : mesh->point_data) a.values.resize(mesh->points.size() * a.n_components, 0.0);
  for (DataArray& a : mesh->cell_data)
    a.values.resize(mesh->n_cells() * a.n_components, a.name == "layer" ? -1.0 : 0.0);
  // Layer cells are region 0; the tets and the pyramids capping the quad tops of fan
  // strips (fill_envelope.h: "layer" -1) belong to the fill.
  const DataArray* layer = mesh->find_cell_array("layer");
  std::vector<std::int32_t> region(mesh->n_cells());
  for (std::size_t c = 0; c < region.size(); ++c)
    region[c] = c >= n_layer_cells || (layer && layer->values[c] < 0.0) ? 1 : 0;
  mesh->cell_data.push_back({"region", 1, ArrayValues(std::move(region))});
  return to_mesh;
}

namespace {

// The cells' faces that lie in the plane, as outward triangles (quads split along
// q0-q2), except those already listed (the fill's plane facet). A face in the plane has
// the domain on one side only, so it is a boundary face.
std::vector<Triangle> other_faces_in_plane(const VolumeMesh& mesh, const SymmetryPlane& plane,
                                           const std::vector<Triangle>& listed) {
  std::vector<char> on(mesh.points.size());
  for (std::size_t i = 0; i < on.size(); ++i) on[i] = plane.signed_distance(mesh.points[i]) == 0.0;
  std::set<TriangleKey> seen;  // the listed triangles in the plane
  for (const Triangle& t : listed)
    if (on[t[0]] && on[t[1]] && on[t[2]]) seen.insert(sorted_triangle(t[0], t[1], t[2]));
  std::vector<Triangle> out;
  for (std::size_t c = 0; c < mesh.n_cells(); ++c) {
    const PointId* n = mesh.cell_nodes(c);
    const int nn = corner_count(mesh.cell_types[c]);
    if (std::count_if(n, n + nn, [&](std::int64_t v) { return on[v]; }) < 3) continue;
    const CellFaceTable& table = cell_face_table(mesh.cell_types[c]);
    for (int f = 0; f < table.n_faces; ++f) {
      const int k = table.n_corners[f];
      int v[4] = {0, 0, 0, 0};  // a face has 3 or 4 corners: what the compiler cannot see
      bool in_plane = true;
      for (int j = 0; j < k; ++j) {
        v[j] = static_cast<int>(n[table.corners[f][j]]);
        in_plane = in_plane && on[v[j]];
      }
      if (!in_plane || (k == 3 && seen.count(sorted_triangle(v[0], v[1], v[2])))) continue;
      out.push_back({v[0], v[1], v[2]});
      if (k == 4) out.push_back({v[0], v[2], v[3]});
    }
  }
  return out;
}

}  // namespace

MarkedBoundary hybrid_boundary(const VolumeMesh& mesh, const TriSurface& wall, const FillResult& fill,
                               const std::vector<std::int64_t>& fill_to_mesh, const SymmetryPlane* plane) {
  BLAYER_ASSERT(wall.points.size() <= mesh.points.size());
  BLAYER_ASSERT_MSG(std::equal(wall.points.begin(), wall.points.end(), mesh.points.begin()),
                    "the wall points are the mesh's first points");
  BLAYER_ASSERT_MSG(fill_to_mesh.size() == fill.tets.points.size(), "fill_to_mesh comes from append_fill");
  BLAYER_ASSERT(fill.boundary_marker.size() == fill.boundary.triangles.size());
  MarkedBoundary b;
  b.surface.points = mesh.points;
  // The wall's triangles face the fluid, i.e. into the domain: reversed. The fill winds
  // its farfield triangles into the domain too: reversed as well.
  for (const Triangle& t : wall.triangles) {
    b.surface.triangles.push_back({t[0], t[2], t[1]});
    b.marker.push_back(static_cast<int>(BoundaryMarker::kWall));
  }
  for (std::size_t i = 0; i < fill.boundary.triangles.size(); ++i) {
    const int m = fill.boundary_marker[i];
    if (m != kFarfieldMarker && m != kSymmetryMarker) continue;
    const Triangle& t = fill.boundary.triangles[i];
    b.surface.triangles.push_back({static_cast<int>(fill_to_mesh[t[0]]), static_cast<int>(fill_to_mesh[t[2]]),
                                   static_cast<int>(fill_to_mesh[t[1]])});
    b.marker.push_back(static_cast<int>(m == kFarfieldMarker ? BoundaryMarker::kFarfield : BoundaryMarker::kSymmetry));
  }
  if (plane)
    for (const Triangle& t : other_faces_in_plane(mesh, *plane, b.surface.triangles)) {
      b.surface.triangles.push_back(t);
      b.marker.push_back(static_cast<int>(BoundaryMarker::kSymmetry));
    }
  return b;
}

}  // namespace blayer
