#include "blayer/fill/hybrid_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "analytic_surfaces.h"
#include "blayer/quality/mesh_check.h"
#include "blayer/quality/orient3d.h"

namespace blayer {
namespace {

using test_surfaces::box;
using test_surfaces::icosphere;

// One layer of wedges on a wall whose normals point into the fluid, built by hand: the
// tops are the wall points moved by `top(p)`; points 0..V-1 are the wall's, V.. the
// tops'. The envelope is the wall's triangles on the tops.
struct OneLayer {
  TriSurface wall;
  VolumeMesh mesh;
  TriSurface envelope;
  std::vector<std::int64_t> envelope_ids;
};

template <class Top>
OneLayer one_layer(const TriSurface& wall, Top top) {
  OneLayer l;
  l.wall = wall;
  const std::int64_t nv = static_cast<std::int64_t>(wall.points.size());
  l.mesh.points = wall.points;
  for (const Vec3& p : wall.points) l.mesh.points.push_back(top(p));
  for (const Triangle& t : wall.triangles) {
    // VTK wedge: base (a, c, b) faces away from the top (a', c', b').
    const std::int64_t nodes[6] = {t[0], t[2], t[1], t[0] + nv, t[2] + nv, t[1] + nv};
    l.mesh.add_cell(CellType::kWedge, nodes);
  }
  l.mesh.point_data.push_back({"column_height", 1, std::vector<double>(2 * nv, 0.5)});
  l.mesh.cell_data.push_back({"layer", 1, ArrayValues(ValueType::kInt32, wall.triangles.size())});
  l.envelope.points.assign(l.mesh.points.begin() + nv, l.mesh.points.end());
  l.envelope.triangles = wall.triangles;
  for (std::int64_t i = 0; i < nv; ++i) l.envelope_ids.push_back(nv + i);
  return l;
}

using FaceKey = std::array<std::int64_t, 3>;

// Oracle for orientation: every cell face (tet faces, wedge caps) with the cells that
// have it, as (cell, centroid).
std::map<FaceKey, std::vector<Vec3>> cells_by_face(const VolumeMesh& m) {
  std::map<FaceKey, std::vector<Vec3>> faces;
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const PointId* n = m.cell_nodes(c);
    const int nn = corner_count(m.cell_types[c]);
    Vec3 centroid{0, 0, 0};
    for (int k = 0; k < nn; ++k) centroid += m.points[n[k]];
    centroid = centroid / static_cast<double>(nn);
    std::vector<FaceKey> keys;
    if (m.cell_types[c] == CellType::kTet)
      keys = {{n[1], n[2], n[3]}, {n[0], n[2], n[3]}, {n[0], n[1], n[3]}, {n[0], n[1], n[2]}};
    else
      keys = {{n[0], n[1], n[2]}, {n[3], n[4], n[5]}};
    for (FaceKey k : keys) {
      std::sort(k.begin(), k.end());
      faces[k].push_back(centroid);
    }
  }
  return faces;
}

// Each boundary triangle is a face of exactly one cell, which lies behind its normal.
void expect_outward_on_cells(const MarkedBoundary& b, const VolumeMesh& mesh) {
  const auto faces = cells_by_face(mesh);
  for (std::size_t i = 0; i < b.surface.triangles.size(); ++i) {
    const Triangle& t = b.surface.triangles[i];
    FaceKey k{t[0], t[1], t[2]};
    std::sort(k.begin(), k.end());
    const auto it = faces.find(k);
    ASSERT_NE(it, faces.end()) << "boundary triangle " << i << " is no cell face";
    ASSERT_EQ(it->second.size(), 1u) << "boundary triangle " << i << " has cells on both sides";
    const Vec3 &p = b.surface.points[t[0]], &q = b.surface.points[t[1]], &r = b.surface.points[t[2]];
    EXPECT_LT(orient3d_sign(p, q, r, it->second.front()), 0) << "boundary triangle " << i << " faces into the domain";
  }
}

double total_cell_volume(const VolumeMesh& m) {
  const MeshCheckReport r = check_volume_mesh(m);
  const auto it = std::find(kCheckMetricNames.begin(), kCheckMetricNames.end(), std::string("volume"));
  const std::vector<double>& v = r.metrics[it - kCheckMetricNames.begin()];
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum;
}

TEST(HybridMesh, AppendedFillKeepsTheLayerPointsAndAddsTheRest) {
  OneLayer l = one_layer(icosphere(1), [](const Vec3& p) { return 1.1 * p; });
  FillOptions opt;
  opt.farfield_scale = 3.0;
  const FillResult fill = fill_with_tets(l.envelope, opt);
  const std::size_t n_layer_points = l.mesh.points.size(), n_layer_cells = l.mesh.n_cells();
  const std::vector<Vec3> layer_points = l.mesh.points;
  const std::vector<std::int64_t> to_mesh = append_fill(fill, l.envelope_ids, &l.mesh);

  ASSERT_EQ(to_mesh.size(), fill.tets.points.size());
  EXPECT_EQ(l.mesh.points.size(), n_layer_points + fill.tets.points.size() - l.envelope.points.size());
  EXPECT_TRUE(std::equal(layer_points.begin(), layer_points.end(), l.mesh.points.begin()));
  for (std::size_t i = 0; i < to_mesh.size(); ++i) EXPECT_EQ(l.mesh.points[to_mesh[i]], fill.tets.points[i]) << i;
  for (std::size_t i = 0; i < l.envelope.points.size(); ++i) EXPECT_EQ(to_mesh[i], l.envelope_ids[i]);

  ASSERT_EQ(l.mesh.n_cells(), n_layer_cells + fill.tets.n_cells());
  const DataArray* region = l.mesh.find_cell_array("region");
  const DataArray* layer = l.mesh.find_cell_array("layer");
  ASSERT_NE(region, nullptr);
  ASSERT_NE(layer, nullptr);
  for (std::size_t c = 0; c < l.mesh.n_cells(); ++c) {
    const bool is_tet = c >= n_layer_cells;
    EXPECT_EQ(region->values[c], is_tet ? 1.0 : 0.0) << c;
    EXPECT_EQ(layer->values[c], is_tet ? -1.0 : 0.0) << c;
    EXPECT_EQ(l.mesh.cell_types[c], is_tet ? CellType::kTet : CellType::kWedge) << c;
  }
  const DataArray* height = l.mesh.find_point_array("column_height");
  ASSERT_EQ(height->values.size(), l.mesh.points.size());
  EXPECT_EQ(height->values[height->values.size() - 1], 0.0);
  EXPECT_EQ(height->values[0], 0.5);

  const MeshCheckReport check = check_volume_mesh(l.mesh);
  EXPECT_TRUE(check.ok()) << format_check_report(check);
}

TEST(HybridMesh, BoundaryMarksWallAndFarfieldOnTheMeshPointsFacingOutward) {
  OneLayer l = one_layer(icosphere(1), [](const Vec3& p) { return 1.1 * p; });
  FillOptions opt;
  opt.farfield_scale = 3.0;
  const FillResult fill = fill_with_tets(l.envelope, opt);
  const std::vector<std::int64_t> to_mesh = append_fill(fill, l.envelope_ids, &l.mesh);
  const MarkedBoundary b = hybrid_boundary(l.mesh, l.wall, fill, to_mesh);

  const std::size_t n_farfield = static_cast<std::size_t>(
      std::count(fill.boundary_marker.begin(), fill.boundary_marker.end(), kFarfieldMarker));
  ASSERT_EQ(b.marker.size(), b.surface.triangles.size());
  EXPECT_EQ(std::count(b.marker.begin(), b.marker.end(), 1), static_cast<long>(l.wall.triangles.size()));
  EXPECT_EQ(std::count(b.marker.begin(), b.marker.end(), 2), static_cast<long>(n_farfield));
  EXPECT_GE(n_farfield, 12u);
  EXPECT_EQ(b.surface.points, l.mesh.points);
  for (std::size_t t = 0; t < l.wall.triangles.size(); ++t) EXPECT_EQ(b.marker[t], 1);

  expect_outward_on_cells(b, l.mesh);
  // Outward everywhere: the divergence theorem gives the domain's volume.
  const double domain = total_cell_volume(l.mesh);
  EXPECT_GT(domain, 0.0);
  EXPECT_NEAR(signed_volume(b.surface), domain, 1e-9 * domain);
  EXPECT_EQ(check_volume_mesh(l.mesh).boundary_faces, b.surface.triangles.size());
}

// A half model: the layers' side quads over the cut lie in the plane with the fill's
// facet; listed as their halves, the symmetry triangles tile the half box's face on the
// plane (with the disk the wall's cut encloses), all facing out of the domain (-z).
TEST(HybridMesh, HalfModelBoundaryListsTheLayersFacesInThePlaneSoTheSymmetryTrianglesTileIt) {
  const int n_lon = 16;
  const TriSurface half = test_surfaces::cut_at_coordinate_plane(test_surfaces::uv_sphere(8, n_lon, 1.0, 0.0), 2);
  OneLayer l = one_layer(half, [](const Vec3& p) { return 1.1 * p; });
  FillOptions opt;
  opt.farfield_scale = 3.0;
  opt.symmetry = SymmetryPlane{{0.0, 0.0, 1.0}, 0.0, 2};
  const FillResult fill = fill_with_tets(l.envelope, opt);
  const std::vector<std::int64_t> to_mesh = append_fill(fill, l.envelope_ids, &l.mesh);
  const MarkedBoundary b = hybrid_boundary(l.mesh, l.wall, fill, to_mesh, &*opt.symmetry);

  double area = 0.0, lo_x = HUGE_VAL, hi_x = -HUGE_VAL, lo_y = HUGE_VAL, hi_y = -HUGE_VAL;
  long n_symmetry = 0;
  for (std::size_t i = 0; i < b.surface.triangles.size(); ++i) {
    if (b.marker[i] != 3) continue;
    ++n_symmetry;
    const Vec3& p = b.surface.points[b.surface.triangles[i][0]];
    const Vec3& q = b.surface.points[b.surface.triangles[i][1]];
    const Vec3& r = b.surface.points[b.surface.triangles[i][2]];
    ASSERT_TRUE(p[2] == 0.0 && q[2] == 0.0 && r[2] == 0.0) << "symmetry triangle " << i << " off the plane";
    const double z_normal = cross(q - p, r - p)[2];
    EXPECT_LT(z_normal, 0.0) << "symmetry triangle " << i << " faces into the domain";
    area -= 0.5 * z_normal;
    for (const Vec3& v : {p, q, r}) {
      lo_x = std::min(lo_x, v[0]);
      hi_x = std::max(hi_x, v[0]);
      lo_y = std::min(lo_y, v[1]);
      hi_y = std::max(hi_y, v[1]);
    }
  }
  const long n_facet = static_cast<long>(
      std::count(fill.boundary_marker.begin(), fill.boundary_marker.end(), kSymmetryMarker));
  EXPECT_EQ(n_symmetry, n_facet + 2 * n_lon) << "the facet and two halves per side quad over the cut";
  const double cut = 0.5 * n_lon * std::sin(2 * M_PI / n_lon);  // the wall's equator polygon
  const double box_face = (hi_x - lo_x) * (hi_y - lo_y);
  EXPECT_NEAR(area + cut, box_face, 1e-12 * box_face);

  // All the markers' triangles close the domain: every edge once in each direction.
  std::map<std::pair<int, int>, int> directed;
  for (const Triangle& t : b.surface.triangles)
    for (int e = 0; e < 3; ++e) ++directed[{t[e], t[(e + 1) % 3]}];
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second;
    ASSERT_EQ(directed.count({edge.second, edge.first}), 1u) << "edge " << edge.first << "-" << edge.second;
  }
}

TEST(HybridMesh, InternalFlowBoundaryIsTheWallAloneFacingOutOfThePipe) {
  const TriSurface pipe = box({0, 0, 0}, {3, 1, 1}, 3, /*inward=*/true);
  const Vec3 centre{1.5, 0.5, 0.5};
  OneLayer l = one_layer(pipe, [&](const Vec3& p) { return centre + 0.9 * (p - centre); });
  FillOptions opt;
  opt.region = FillOptions::Region::kInside;
  const FillResult fill = fill_with_tets(l.envelope, opt);
  const std::vector<std::int64_t> to_mesh = append_fill(fill, l.envelope_ids, &l.mesh);
  const MarkedBoundary b = hybrid_boundary(l.mesh, l.wall, fill, to_mesh);
  EXPECT_EQ(b.surface.triangles.size(), pipe.triangles.size());
  EXPECT_EQ(std::count(b.marker.begin(), b.marker.end(), 1), static_cast<long>(pipe.triangles.size()));
  expect_outward_on_cells(b, l.mesh);
  EXPECT_NEAR(signed_volume(b.surface), 3.0, 1e-12);
  EXPECT_NEAR(total_cell_volume(l.mesh), 3.0, 1e-9);
}

TEST(HybridMesh, MarkerValuesAreTheFileFormat) {
  EXPECT_EQ(static_cast<int>(BoundaryMarker::kWall), 1);
  EXPECT_EQ(static_cast<int>(BoundaryMarker::kFarfield), 2);
  EXPECT_EQ(static_cast<int>(BoundaryMarker::kSymmetry), 3);
}

TEST(HybridMesh, EnvelopeIdsThatDoNotMatchTheFillAreAProgrammerError) {
  OneLayer l = one_layer(icosphere(1), [](const Vec3& p) { return 1.1 * p; });
  FillOptions opt;
  opt.farfield_scale = 3.0;
  const FillResult fill = fill_with_tets(l.envelope, opt);
  std::vector<std::int64_t> shifted = l.envelope_ids;
  std::rotate(shifted.begin(), shifted.begin() + 1, shifted.end());
  VolumeMesh mesh = l.mesh;
  EXPECT_THROW(append_fill(fill, shifted, &mesh), std::logic_error);
  shifted.pop_back();
  EXPECT_THROW(append_fill(fill, shifted, &mesh), std::logic_error);
}

}  // namespace
}  // namespace blayer
