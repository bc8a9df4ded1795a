#include "blayer/fill/fill_envelope.h"

#include <gtest/gtest.h>

#include "blayer/fill/hybrid_mesh.h"
#include "blayer/quality/cell_validity.h"
#include "blayer/quality/mesh_check.h"

namespace blayer {
namespace {

// One unit hex in VTK order (bottom 0..3 counter-clockwise seen from above, top 4..7),
// whose top face is the envelope: two halves on mesh points 4..7, facing up.
struct HexTop {
  VolumeMesh mesh;
  TriSurface envelope;
  std::vector<std::int64_t> ids{4, 5, 6, 7};
};

HexTop hex_top() {
  HexTop h;
  h.mesh.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::int64_t hex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  h.mesh.add_cell(CellType::kHex, hex);
  h.mesh.cell_data.push_back({"layer", 1, ArrayValues(ValueType::kInt32, std::vector<double>{3.0})});
  h.mesh.point_data.push_back({"fan_column", 1, ArrayValues(ValueType::kInt32, std::vector<double>(8, 1.0))});
  h.envelope.points.assign(h.mesh.points.begin() + 4, h.mesh.points.end());
  h.envelope.triangles = {{0, 1, 2}, {0, 2, 3}};
  return h;
}

TEST(FillEnvelope, CapsTheQuadTopOfAHexWithAValidPyramid) {
  HexTop h = hex_top();
  const FillEnvelope e = fill_envelope(h.envelope, h.ids, &h.mesh);
  EXPECT_EQ(e.n_caps, 1);
  ASSERT_EQ(h.mesh.n_cells(), 2u);
  EXPECT_EQ(h.mesh.cell_types[1], CellType::kPyramid);
  ASSERT_EQ(h.mesh.points.size(), 9u);
  // Half the shortest edge (1) above the centre of the top.
  EXPECT_NEAR(h.mesh.points[8][0], 0.5, 1e-15);
  EXPECT_NEAR(h.mesh.points[8][1], 0.5, 1e-15);
  EXPECT_NEAR(h.mesh.points[8][2], 1.5, 1e-15);
  Vec3 corners[5];
  for (int k = 0; k < 5; ++k) corners[k] = h.mesh.points[h.mesh.connectivity[h.mesh.offsets[1] + k]];
  EXPECT_EQ(cell_validity(CellType::kPyramid, corners), Validity::kValid);
  EXPECT_EQ(h.mesh.cell_data[0].values[1], -1.0);  // "layer" of a cap
  EXPECT_EQ(h.mesh.point_data[0].values[8], 0.0);
  // The surface: the four side triangles, facing up and out, on mesh points 4..8.
  ASSERT_EQ(e.surface.triangles.size(), 4u);
  ASSERT_EQ(e.point_ids, (std::vector<std::int64_t>{4, 5, 6, 7, 8}));
  for (const Triangle& t : e.surface.triangles) {
    const Vec3 n = cross(e.surface.points[t[1]] - e.surface.points[t[0]], e.surface.points[t[2]] - e.surface.points[t[0]]);
    const Vec3 c = (e.surface.points[t[0]] + e.surface.points[t[1]] + e.surface.points[t[2]]) / 3.0 - Vec3{0.5, 0.5, 1.0};
    EXPECT_GT(n[2], 0.0);
    EXPECT_GT(dot(n, c), 0.0);  // away from the quad's centre
  }
  const MeshCheckReport check = check_volume_mesh(h.mesh);
  EXPECT_TRUE(check.ok());
  EXPECT_EQ(check.totals.non_conforming, 0u);
}

// The pyramid cap is fill, not layer: append_fill marks it region 1 beside the tets,
// the hex region 0.
TEST(FillEnvelope, TheCapJoinsTheFillsRegion) {
  HexTop h = hex_top();
  const FillEnvelope e = fill_envelope(h.envelope, h.ids, &h.mesh);
  ASSERT_EQ(e.n_caps, 1);
  FillResult fill;  // no tets: only the region of the cells already there is at stake
  fill.tets.points = e.surface.points;
  fill.stats.n_envelope_points = static_cast<std::int64_t>(e.surface.points.size());
  append_fill(fill, e.point_ids, &h.mesh);
  const DataArray* region = h.mesh.find_cell_array("region");
  ASSERT_NE(region, nullptr);
  ASSERT_EQ(region->values.size(), 2u);
  EXPECT_EQ(region->values[0], 0.0) << "the hex";
  EXPECT_EQ(region->values[1], 1.0) << "the cap";
}

TEST(FillEnvelope, DropsTrianglesNamingAMeshPointTwiceAndMergesSharedPoints) {
  HexTop h = hex_top();
  // A fifth envelope point (a fan column that did not grow) on mesh point 7, and the
  // strip half (6, 7, 7) it leaves.
  h.envelope.points.push_back(h.mesh.points[7]);
  h.ids.push_back(7);
  h.envelope.triangles.push_back({2, 3, 4});
  const FillEnvelope e = fill_envelope(h.envelope, h.ids, &h.mesh);
  EXPECT_EQ(e.n_caps, 1);
  EXPECT_EQ(e.point_ids, (std::vector<std::int64_t>{4, 5, 6, 7, 8}));
  EXPECT_EQ(e.surface.points.size(), 5u);
  EXPECT_EQ(e.surface.triangles.size(), 4u);
}

TEST(FillEnvelope, LeavesAnEnvelopeWithoutQuadTopsOrSharedPointsAsItIs) {
  // One wedge over the triangle (0,1,2): its top triangle is the envelope, its quads are
  // side faces, not envelope faces.
  VolumeMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  const std::int64_t wedge[6] = {0, 2, 1, 3, 5, 4};
  mesh.add_cell(CellType::kWedge, wedge);
  TriSurface envelope;
  envelope.points = {mesh.points[3], mesh.points[4], mesh.points[5]};
  envelope.triangles = {{0, 1, 2}};
  const FillEnvelope e = fill_envelope(envelope, {3, 4, 5}, &mesh);
  EXPECT_EQ(e.n_caps, 0);
  EXPECT_EQ(e.surface.triangles, envelope.triangles);
  EXPECT_EQ(e.surface.points, envelope.points);
  EXPECT_EQ(mesh.n_cells(), 1u);
  EXPECT_EQ(mesh.points.size(), 6u);
}

}  // namespace
}  // namespace blayer
