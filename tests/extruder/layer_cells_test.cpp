#include "blayer/extruder/layer_cells.h"
#include "blayer/quality/cell_metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "blayer/quality/cell_validity.h"

namespace blayer {
namespace {

// Wall triangle (a,b,c) counter-clockwise in the plane z = 0, so its right-hand normal
// (+z) points into the fluid; column tops one unit up. Point ids 0..2 bottoms, 3..5 tops.
const Vec3 kPts[6] = {{0, 0, 0}, {1, 0, 0}, {0.3, 0.9, 0}, {0, 0, 1}, {1, 0, 1}, {0.3, 0.9, 1}};

std::vector<Vec3> corners_of(const LayerCell& c, const Vec3* pts) {
  std::vector<Vec3> out;
  for (int i = 0; i < corner_count(c.type); ++i) out.push_back(pts[c.nodes[i]]);
  return out;
}

LayerCell make(std::array<bool, 3> g) {
  LayerCell c;
  EXPECT_TRUE(layer_cell({0, 1, 2}, {3, 4, 5}, g, &c));
  return c;
}

TEST(LayerCells, AllColumnsGrowingGiveAValidVtkWedge) {
  const LayerCell c = make({true, true, true});
  ASSERT_EQ(c.type, CellType::kWedge);
  const std::vector<Vec3> p = corners_of(c, kPts);
  EXPECT_TRUE(prism_is_valid(p.data()));
  EXPECT_EQ(cell_validity(CellType::kWedge, p.data()), Validity::kValid);
  // The wall triangle's own winding as the first cap would face the top: VTK reads that
  // as inverted. This pins the (a, c, b, a', c', b') order.
  const Vec3 wrong[6] = {kPts[0], kPts[1], kPts[2], kPts[3], kPts[4], kPts[5]};
  EXPECT_FALSE(prism_is_valid(wrong));
  EXPECT_EQ(cell_validity(CellType::kWedge, wrong), Validity::kInverted);
}

TEST(LayerCells, OneStoppedColumnGivesAValidPyramidWithTheStoppedPointAsApex) {
  for (int x = 0; x < 3; ++x) {
    std::array<bool, 3> g{true, true, true};
    g[x] = false;
    const LayerCell c = make(g);
    ASSERT_EQ(c.type, CellType::kPyramid);
    EXPECT_EQ(c.nodes[4], x);
    const std::vector<Vec3> p = corners_of(c, kPts);
    EXPECT_EQ(cell_validity(CellType::kPyramid, p.data()), Validity::kValid) << "stopped column " << x;
  }
}

TEST(LayerCells, TwoStoppedColumnsGiveAValidTet) {
  for (int z = 0; z < 3; ++z) {
    std::array<bool, 3> g{false, false, false};
    g[z] = true;
    const LayerCell c = make(g);
    ASSERT_EQ(c.type, CellType::kTet);
    const std::vector<Vec3> p = corners_of(c, kPts);
    EXPECT_EQ(cell_validity(CellType::kTet, p.data()), Validity::kValid) << "growing column " << z;
  }
}

TEST(LayerCells, NoGrowingColumnGivesNoCell) {
  LayerCell c;
  EXPECT_FALSE(layer_cell({0, 1, 2}, {3, 4, 5}, {false, false, false}, &c));
}

// Faces of a cell as sorted node sets.
std::vector<std::vector<std::int64_t>> faces(const LayerCell& c) {
  const auto& n = c.nodes;
  std::vector<std::vector<std::int64_t>> f;
  switch (c.type) {
    case CellType::kTet: f = {{n[0], n[1], n[2]}, {n[0], n[1], n[3]}, {n[1], n[2], n[3]}, {n[0], n[2], n[3]}}; break;
    case CellType::kPyramid:
      f = {{n[0], n[1], n[2], n[3]}, {n[0], n[1], n[4]}, {n[1], n[2], n[4]}, {n[2], n[3], n[4]}, {n[3], n[0], n[4]}};
      break;
    case CellType::kWedge:
      f = {{n[0], n[1], n[2]}, {n[3], n[4], n[5]}, {n[0], n[1], n[4], n[3]}, {n[1], n[2], n[5], n[4]},
           {n[2], n[0], n[3], n[5]}};
      break;
    case CellType::kHex: break;
  }
  for (auto& x : f) std::sort(x.begin(), x.end());
  return f;
}

TEST(LayerCells, NeighboursAgreeOnTheSharedSideFaceForEveryGrowthPattern) {
  // Triangles (0,1,2) and (0,3,1) share edge 0-1; tops are id + 10.
  for (int mask = 1; mask < 16; ++mask) {
    const bool g[4] = {bool(mask & 1), bool(mask & 2), bool(mask & 4), bool(mask & 8)};
    LayerCell c1, c2;
    const bool h1 = layer_cell({0, 1, 2}, {10, 11, 12}, {g[0], g[1], g[2]}, &c1);
    const bool h2 = layer_cell({0, 3, 1}, {10, 13, 11}, {g[0], g[3], g[1]}, &c2);
    auto on_edge = [](const LayerCell& c, bool has) {
      std::set<std::vector<std::int64_t>> out;
      if (!has) return out;
      const std::set<std::int64_t> edge{0, 1, 10, 11};
      for (const auto& f : faces(c))
        if (std::all_of(f.begin(), f.end(), [&](std::int64_t v) { return edge.count(v) > 0; })) out.insert(f);
      return out;
    };
    const auto f1 = on_edge(c1, h1), f2 = on_edge(c2, h2);
    SCOPED_TRACE(testing::Message() << "growth mask " << mask);
    if (g[0] || g[1]) {
      ASSERT_TRUE(h1 && h2);
      EXPECT_EQ(f1.size(), 1u);
      EXPECT_EQ(f1, f2);
    } else {
      EXPECT_TRUE(f1.empty());
      EXPECT_TRUE(f2.empty());
    }
  }
}

TEST(LayerCells, InvertedFlatAndTwistedPrismsAreRejected) {
  const LayerCell c = make({true, true, true});
  auto wedge = [&](const Vec3* pts) { return corners_of(c, pts); };
  // Tops below the wall: inverted.
  Vec3 down[6] = {kPts[0], kPts[1], kPts[2], {0, 0, -1}, {1, 0, -1}, {0.3, 0.9, -1}};
  EXPECT_FALSE(prism_is_valid(wedge(down).data()));
  // Zero height: flat.
  Vec3 flat[6] = {kPts[0], kPts[1], kPts[2], kPts[0], kPts[1], kPts[2]};
  EXPECT_FALSE(prism_is_valid(wedge(flat).data()));
  EXPECT_EQ(cell_validity(CellType::kWedge, wedge(flat).data()), Validity::kFlat);
  // Top cap mirrored (b' and c' swapped): every base tet is positive, the top cap is not.
  Vec3 twisted[6] = {kPts[0], kPts[1], kPts[2], kPts[3], kPts[5], kPts[4]};
  EXPECT_FALSE(prism_is_valid(wedge(twisted).data()));
  // Top cap tilted past wall vertex b: every top lies above the wall plane (the three
  // base-cap tets are positive) but b lies above the top cap's plane.
  Vec3 tilted[6] = {kPts[0], kPts[1], kPts[2], {0, 0, 0.1}, {-2, 0, 3}, {0.3, 0.9, 0.1}};
  EXPECT_FALSE(prism_is_valid(wedge(tilted).data()));
  // A pure shear keeps both caps parallel and the cell valid.
  Vec3 sheared[6] = {kPts[0], kPts[1], kPts[2], {3, 0, 0.1}, {4, 0, 0.1}, {3.3, 0.9, 0.1}};
  EXPECT_TRUE(prism_is_valid(wedge(sheared).data()));
}

TEST(LayerCells, CellsInLayerOrderHaveTheQualityModulesPositiveScaledJacobian) {
  // The metric is the quality module's; this pins that the layer cells' node order is
  // the one it expects: an equilateral right prism is ideal (1), a mirrored one negative.
  const double s = std::sqrt(3.0) / 2.0;
  const Vec3 eq[6] = {{0, 0, 0}, {1, 0, 0}, {0.5, s, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, s, 1}};
  const LayerCell c = make({true, true, true});
  EXPECT_NEAR(compute_cell_metrics(CellType::kWedge, corners_of(c, eq).data()).scaled_jacobian, 1.0, 1e-12);
  Vec3 down[6] = {kPts[0], kPts[1], kPts[2], {0, 0, -1}, {1, 0, -1}, {0.3, 0.9, -1}};
  EXPECT_LT(compute_cell_metrics(CellType::kWedge, corners_of(c, down).data()).scaled_jacobian, 0.0);
  for (const std::array<bool, 3> grows : {std::array<bool, 3>{true, true, false}, std::array<bool, 3>{true, false, false}}) {
    const LayerCell partial = make(grows);
    const std::vector<Vec3> p = corners_of(partial, eq);
    EXPECT_GT(compute_cell_metrics(partial.type, p.data()).scaled_jacobian, 0.0);
  }
}

// A closure wedge of a fan strip on a CAD block (bench/make_perforated_block.py, layer
// 7): its fan point y stopped near the wall, x grew on. The wedge is valid, but its face
// (1, 4, 5, 2) from y's tops to x's new ones, which the envelope keeps, has a reflex
// corner: no pyramid caps it, so a strip does not accept the cell. The same cell of a
// wall triangle, whose envelope faces are triangles, is accepted.
TEST(LayerCellAccepted, AStripCellWhoseEnvelopeQuadCannotBeCappedIsRefused) {
  LayerCell wedge;
  wedge.type = CellType::kWedge;
  wedge.nodes = {0, 1, 2, 3, 4, 5, 0, 0};
  const Vec3 corners[6] = {{0.73048793219317198, 1.6555480035868113, -0.018988924523485939},
                           {0.75818113439906998, 1.6490612851212991, -0.001230185052746917},
                           {0.72529128926883502, 1.6526382343654233, -0.024442098133800275},
                           {0.72938957676825156, 1.6555232643450211, -0.019558879059479506},
                           {0.75786607386101235, 1.6488794502448303, -0.00018987949182620238},
                           {0.72416738419325966, 1.652698575226996, -0.025256848962415108}};
  ASSERT_TRUE(cell_is_valid(CellType::kWedge, corners));
  LayerElement strip;
  strip.kind = ElementKind::kStrip;
  EXPECT_FALSE(layer_cell_accepted(strip, wedge, corners));
  LayerElement triangle;
  triangle.kind = ElementKind::kTriangle;
  EXPECT_TRUE(layer_cell_accepted(triangle, wedge, corners));
}

// A strip's hexahedron with a convex top is accepted. With a plane top that has a reflex
// corner the exact test already refuses it (a split of the top folds against a bottom
// node): the cap matters for tops that are not plane, as the wedge's face above.
TEST(LayerCellAccepted, AStripHexIsAcceptedWhenValidAndItsTopCanBeCapped) {
  LayerCell hex;
  hex.type = CellType::kHex;
  hex.nodes = {0, 1, 2, 3, 4, 5, 6, 7};
  Vec3 corners[8] = {{0, 0, 0}, {4, 0, 0}, {4, 1, 0}, {0, 1, 0}, {0, 0, 1}, {4, 0, 1}, {4, 1, 1}, {0, 1, 1}};
  LayerElement strip;
  strip.kind = ElementKind::kStrip;
  EXPECT_TRUE(layer_cell_accepted(strip, hex, corners));
  corners[6] = {4, 0.5, 1};  // top (0,0)(4,0)(4,0.5)(0,1): convex, still capped
  EXPECT_TRUE(layer_cell_accepted(strip, hex, corners));
  corners[4] = {2, 0.5, 1};  // top corner 4 inside the triangle of the others: reflex
  EXPECT_FALSE(cell_is_valid(CellType::kHex, corners));
  EXPECT_FALSE(layer_cell_accepted(strip, hex, corners));
}

}  // namespace
}  // namespace blayer
