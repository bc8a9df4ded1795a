// Independent cross-checks against VTK 9.1: node-order conventions against
// vtkCellValidator::Check, scaled Jacobians against vtkMeshQuality (verdict) where VTK
// has the metric. VTK 9.1 has no wedge or pyramid scaled Jacobian, so pyramids and
// wedges are pinned by the validator only.
#include <gtest/gtest.h>

#include <vtkCellValidator.h>
#include <vtkHexahedron.h>
#include <vtkMeshQuality.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPyramid.h>
#include <vtkSmartPointer.h>
#include <vtkTetra.h>
#include <vtkWedge.h>

#include <random>
#include <vector>

#include "blayer/quality/cell_metrics.h"
#include "blayer/quality/cell_validity.h"
#include "test_cells.h"

namespace blayer {
namespace {

// vtkCellValidator's tolerance for its convexity and intersection tests; far below the
// unit-size cells used here, far above rounding.
constexpr double kValidatorTol = 1e-9;
// Same formula evaluated in a different order: agreement to a few ulps of values <= 1.
constexpr double kVerdictTol = 1e-12;

template <typename Cell>
void fill(Cell* cell, const std::vector<Vec3>& p) {
  cell->GetPoints()->SetNumberOfPoints(static_cast<vtkIdType>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) {
    cell->GetPoints()->SetPoint(static_cast<vtkIdType>(i), p[i].data());
    cell->GetPointIds()->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
  }
}

template <typename Cell>
vtkCellValidator::State vtk_state(const std::vector<Vec3>& p) {
  vtkNew<Cell> cell;
  fill(cell.Get(), p);
  return vtkCellValidator::Check(cell.Get(), kValidatorTol);
}

TEST(VtkCrossCheck, WallTriangleExtrudedAsACBIsAValidVtkWedgeAndOurs) {
  // Wall triangle a=(0,0,0), b=(1,0,0), c=(0,1,0): normal +z, toward the top.
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0}, up{0, 0, 0.3};
  const std::vector<Vec3> acb{a, c, b, a + up, c + up, b + up};
  EXPECT_EQ(vtk_state<vtkWedge>(acb), vtkCellValidator::State::Valid);
  EXPECT_EQ(cell_validity(CellType::kWedge, acb.data()), Validity::kValid);
  // The wall's own winding is what VTK rejects, and so do we.
  const std::vector<Vec3> abc{a, b, c, a + up, b + up, c + up};
  EXPECT_NE(vtk_state<vtkWedge>(abc), vtkCellValidator::State::Valid);
  EXPECT_EQ(cell_validity(CellType::kWedge, abc.data()), Validity::kInverted);
}

TEST(VtkCrossCheck, ReferenceCellsAgreeWithTheValidatorInBothOrientations) {
  // VTK 9.1's validator does not look at a tet's orientation (a mirrored tet passes),
  // so tets are pinned by TetScaledJacobian's sign below instead.
  EXPECT_EQ(vtk_state<vtkTetra>(test::unit_tet()), vtkCellValidator::State::Valid);
  EXPECT_EQ(vtk_state<vtkPyramid>(test::unit_pyramid()), vtkCellValidator::State::Valid);
  EXPECT_NE(vtk_state<vtkPyramid>(test::mirrored(test::unit_pyramid())), vtkCellValidator::State::Valid);
  EXPECT_EQ(vtk_state<vtkHexahedron>(test::unit_hex()), vtkCellValidator::State::Valid);
  EXPECT_NE(vtk_state<vtkHexahedron>(test::mirrored(test::unit_hex())), vtkCellValidator::State::Valid);
  EXPECT_EQ(vtk_state<vtkWedge>(test::right_prism()), vtkCellValidator::State::Valid);
  EXPECT_NE(vtk_state<vtkWedge>(test::mirrored(test::right_prism())), vtkCellValidator::State::Valid);
}

vtkSmartPointer<vtkTetra> tet_cell(const std::vector<Vec3>& p) {
  auto tet = vtkSmartPointer<vtkTetra>::New();
  fill(tet.Get(), p);
  return tet;
}

std::vector<Vec3> jittered(std::vector<Vec3> p, std::mt19937_64& rng, double amount) {
  std::uniform_real_distribution<double> d(-amount, amount);
  for (Vec3& v : p)
    for (double& x : v) x += d(rng);
  return p;
}

TEST(VtkCrossCheck, TetScaledJacobianMatchesVtkMeshQuality) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<Vec3> p = jittered(test::unit_tet(), rng, 0.4);
    vtkNew<vtkTetra> tet;
    fill(tet.Get(), p);
    const double vtk = vtkMeshQuality::TetScaledJacobian(tet.Get());
    EXPECT_NEAR(compute_cell_metrics(CellType::kTet, p.data()).scaled_jacobian, vtk, kVerdictTol) << trial;
    EXPECT_NEAR(compute_cell_metrics(CellType::kTet, p.data()).volume, vtkMeshQuality::TetVolume(tet.Get()),
                kVerdictTol) << trial;
  }
}

TEST(VtkCrossCheck, HexScaledJacobianMatchesVtkMeshQuality) {
  std::mt19937_64 rng(11);
  int negative = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const std::vector<Vec3> p = jittered(test::unit_hex(), rng, 0.35);
    vtkNew<vtkHexahedron> hex;
    fill(hex.Get(), p);
    const double vtk = vtkMeshQuality::HexScaledJacobian(hex.Get());
    const CellMetrics m = compute_cell_metrics(CellType::kHex, p.data());
    EXPECT_NEAR(m.scaled_jacobian, vtk, kVerdictTol) << trial;
    negative += m.scaled_jacobian < 0;
  }
  // Strong jitter: some hexes fold, so the comparison covers negative values too.
  EXPECT_GT(negative, 0);
}

TEST(VtkCrossCheck, AffineHexVolumeMatchesVtkMeshQuality) {
  // verdict's hex volume is the centre Jacobian, exact only for affine hexes; ours
  // integrates the trilinear map, so the two are compared where both are exact.
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> d(-0.4, 0.4);
  for (int trial = 0; trial < 50; ++trial) {
    double a[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a[i][j] = (i == j ? 1.0 : 0.0) + d(rng);
    std::vector<Vec3> p = test::unit_hex();
    for (Vec3& v : p) v = {dot({a[0][0], a[0][1], a[0][2]}, v) + 3.0, dot({a[1][0], a[1][1], a[1][2]}, v),
                           dot({a[2][0], a[2][1], a[2][2]}, v)};
    vtkNew<vtkHexahedron> hex;
    fill(hex.Get(), p);
    EXPECT_NEAR(compute_cell_metrics(CellType::kHex, p.data()).volume, vtkMeshQuality::HexVolume(hex.Get()),
                kVerdictTol) << trial;
  }
}

TEST(VtkCrossCheck, TetScaledJacobianSignMatchesOurValidity) {
  EXPECT_GT(vtkMeshQuality::TetScaledJacobian(tet_cell(test::unit_tet()).Get()), 0.0);
  EXPECT_EQ(cell_validity(CellType::kTet, test::unit_tet().data()), Validity::kValid);
  EXPECT_LT(vtkMeshQuality::TetScaledJacobian(tet_cell(test::mirrored(test::unit_tet())).Get()), 0.0);
  EXPECT_EQ(cell_validity(CellType::kTet, test::mirrored(test::unit_tet()).data()), Validity::kInverted);
}

}  // namespace
}  // namespace blayer
