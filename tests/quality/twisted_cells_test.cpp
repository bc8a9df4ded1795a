// `inverted` counts what VTK, Gmsh and ParaView count (a negative corner Jacobian);
// `twisted` counts the wedges whose corners are all fine but whose quad faces are so
// twisted that some split into tetrahedra folds. Both fail the check.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "blayer/quality/cell_metrics.h"
#include "blayer/quality/mesh_check.h"
#include "separate_wedges.h"
#include "test_cells.h"

namespace blayer {
namespace {

// Top cap of a right prism over the unit equilateral triangle, rotated by `angle` about
// the column axis through its centroid (VTK wedge order).
std::vector<Vec3> twisted_prism(double angle) {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, std::sqrt(3.0) / 2, 0};
  std::vector<Vec3> p{a, c, b, a, c, b};
  const Vec3 centre = (a + b + c) / 3.0;
  for (int i = 3; i < 6; ++i) {
    const Vec3 d = p[i] - centre;
    p[i] = centre + Vec3{std::cos(angle) * d[0] - std::sin(angle) * d[1], std::sin(angle) * d[0] + std::cos(angle) * d[1],
                         1.0};
  }
  return p;
}

TEST(TwistedCells, AHalfTurnTwistIsTwistedWithEveryCornerJacobianPositive) {
  const std::vector<Vec3> p = twisted_prism(M_PI);
  EXPECT_EQ(cell_validity(CellType::kWedge, p.data()), Validity::kTwisted);
  EXPECT_GT(compute_cell_metrics(CellType::kWedge, p.data()).scaled_jacobian, 0.0);
}

TEST(TwistedCells, ASmallTwistIsValidAndAMirroredPrismInvertedWithANegativeCornerJacobian) {
  const std::vector<Vec3> small = twisted_prism(10.0 * M_PI / 180.0);
  EXPECT_EQ(cell_validity(CellType::kWedge, small.data()), Validity::kValid);
  const std::vector<Vec3> mirrored = test::mirrored(test::right_prism());
  EXPECT_EQ(cell_validity(CellType::kWedge, mirrored.data()), Validity::kInverted);
  EXPECT_LT(compute_cell_metrics(CellType::kWedge, mirrored.data()).scaled_jacobian, 0.0);
}

// Oracle over a sweep of twist angles: the class follows from the signs of the corner
// Jacobians (metric) and of the split tets, evaluated separately in double (an angle
// whose split tet is within rounding of zero is left to the exact predicate).
TEST(TwistedCells, ClassesAgreeWithCornerJacobianSignsOverATwistSweep) {
  int seen[4] = {0, 0, 0, 0};
  for (int deg = 0; deg <= 180; deg += 5) {
    const std::vector<Vec3> p = twisted_prism(deg * M_PI / 180.0);
    const Validity v = cell_validity(CellType::kWedge, p.data());
    ++seen[static_cast<int>(v)];
    const double jac = compute_cell_metrics(CellType::kWedge, p.data()).scaled_jacobian;
    std::size_t n = 0;
    const std::array<int, 4>* tets = validity_tets(CellType::kWedge, &n);
    double split_min = HUGE_VAL;
    for (std::size_t i = corner_tet_count(CellType::kWedge); i < n; ++i) {
      const auto& t = tets[i];
      split_min = std::min(split_min, dot(p[t[1]] - p[t[0]], cross(p[t[2]] - p[t[0]], p[t[3]] - p[t[0]])));
    }
    ASSERT_GT(jac, 1e-9) << deg << " deg: a pure twist keeps every corner positive";
    if (std::abs(split_min) < 1e-12) continue;  // a split tet through zero: doubles cannot tell the side
    EXPECT_EQ(v, split_min < 0 ? Validity::kTwisted : Validity::kValid) << deg << " deg";
  }
  EXPECT_GT(seen[0], 0);
  EXPECT_GT(seen[3], 0);
}

TEST(TwistedCells, TheCheckCountsTwistedAndInvertedApartAndBothFail) {
  const VolumeMesh m =
      test::separate_wedges({test::right_prism(), twisted_prism(M_PI), test::mirrored(test::right_prism()), twisted_prism(M_PI)});
  const MeshCheckReport r = check_volume_mesh(m);
  EXPECT_EQ(r.totals.inverted, 1u);
  EXPECT_EQ(r.totals.twisted, 2u);
  EXPECT_EQ(r.totals.flat, 0u);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.flags[0], 0);
  EXPECT_TRUE(has_flag(r.flags[1], CellCheckFlag::kTwisted));
  EXPECT_FALSE(has_flag(r.flags[1], CellCheckFlag::kInverted));
  EXPECT_TRUE(has_flag(r.flags[2], CellCheckFlag::kInverted));
  EXPECT_EQ(r.validity[1], Validity::kTwisted);
  ASSERT_EQ(r.layers.size(), 4u);
  EXPECT_EQ(r.layers[3].counts.twisted, 1u);
  const nlohmann::json j = check_report_to_json(r);
  EXPECT_EQ(j["inverted"], 1);
  EXPECT_EQ(j["twisted"], 2);
  EXPECT_EQ(j["flat"], 0);
  EXPECT_EQ(j["ok"], false);
  EXPECT_EQ(j["layers"][1]["twisted"], 1);
  const std::string text = format_check_report(r);
  EXPECT_NE(text.find("inverted: 1  twisted: 2  flat: 0"), std::string::npos) << text;
  // The failing-cell extract keeps the twisted ones.
  EXPECT_EQ(extract_bad_cells(m, r).n_cells(), 3u);
}

TEST(TwistedCells, AMeshWithOnlyATwistedCellFailsTheCheck) {
  const MeshCheckReport r = check_volume_mesh(test::separate_wedges({twisted_prism(M_PI)}));
  EXPECT_EQ(r.totals.inverted, 0u);
  EXPECT_EQ(r.totals.twisted, 1u);
  EXPECT_FALSE(r.ok());
}

}  // namespace
}  // namespace blayer
