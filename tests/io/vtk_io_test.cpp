#include <gtest/gtest.h>
#include <vtkCellValidator.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "blayer/core/errors.h"
#include "blayer/io/vtk_io.h"
#include "blayer/quality/cell_validity.h"
#include "temp_dir.h"

namespace blayer {
namespace {

using testing::TempDir;

// One prism on the wall triangle (a,b,c) = (0,1,2) whose normal (+z) points into the
// fluid, extruded by 0.5 along +z to (3,4,5), written in VTK order (a,c,b,a',c',b').
VolumeMesh one_prism() {
  VolumeMesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5}};
  const std::int64_t wedge[6] = {0, 2, 1, 3, 5, 4};
  m.add_cell(CellType::kWedge, wedge);
  m.cell_data.push_back({"layer", 1, true, {0}});
  m.point_data.push_back({"normal", 3, false, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}});
  return m;
}

vtkCellValidator::State validate_first_cell(const std::string& path) {
  vtkNew<vtkXMLUnstructuredGridReader> r;
  r->SetFileName(path.c_str());
  r->Update();
  vtkNew<vtkGenericCell> cell;
  r->GetOutput()->GetCell(0, cell);
  return vtkCellValidator::Check(cell, 1e-12);
}

TEST(VtkIo, WedgeWrittenInVtkOrderIsValidForVtkAndForBlayer) {
  TempDir dir;
  const VolumeMesh m = one_prism();
  write_vtu(m, dir.file("p.vtu"));
  EXPECT_EQ(validate_first_cell(dir.file("p.vtu")), vtkCellValidator::State::Valid);
  Vec3 c[6];
  for (int k = 0; k < 6; ++k) c[k] = m.points[m.connectivity[k]];
  EXPECT_TRUE(prism_is_valid(c));
}

TEST(VtkIo, WedgeInWallWindingIsRejectedByVtk) {
  // The wall triangle's own winding (a,b,c,a',b',c') is the mirror image: VTK must flag
  // it, which pins that our writer's order is the one VTK expects.
  TempDir dir;
  VolumeMesh m = one_prism();
  m.connectivity = {0, 1, 2, 3, 4, 5};
  write_vtu(m, dir.file("bad.vtu"));
  EXPECT_NE(validate_first_cell(dir.file("bad.vtu")), vtkCellValidator::State::Valid);
}

TEST(VtkIo, VtuRoundTripKeepsPointsCellsAndArrays) {
  TempDir dir;
  const VolumeMesh m = one_prism();
  write_vtu(m, dir.file("p.vtu"));
  const VolumeMeshFile back = read_volume_mesh(dir.file("p.vtu"));
  EXPECT_EQ(back.mesh.points, m.points);
  EXPECT_EQ(back.mesh.connectivity, m.connectivity);
  EXPECT_EQ(back.mesh.cell_types, m.cell_types);
  const DataArray* layer = back.mesh.find_cell_array("layer");
  ASSERT_NE(layer, nullptr);
  EXPECT_TRUE(layer->integer);
  EXPECT_EQ(layer->values, m.cell_data[0].values);
  const DataArray* normal = back.mesh.find_point_array("normal");
  ASSERT_NE(normal, nullptr);
  EXPECT_EQ(normal->n_components, 3);
}

TEST(VtkIo, WritingIntoAMissingDirectoryFailsAndLeavesNothing) {
  TempDir dir;
  EXPECT_THROW(write_vtu(one_prism(), dir.file("missing/p.vtu")), IoError);
  EXPECT_EQ(dir.entries(), 0);
}

TEST(VtkIo, SuccessfulWriteLeavesNoTemporaryFile) {
  TempDir dir;
  write_vtu(one_prism(), dir.file("p.vtu"));
  EXPECT_EQ(dir.entries(), 1);
}

TEST(VtkIo, ReadingSkipsBoundaryTrianglesAndRejectsUnsupportedCells) {
  TempDir dir;
  const std::string f = dir.write("m.vtk",
                                  "# vtk DataFile Version 3.0\nm\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
                                  "0 0 0\n1 0 0\n0 1 0\n0 0 1\nCELLS 2 9\n4 0 1 2 3\n3 0 1 2\nCELL_TYPES 2\n10\n5\n");
  const VolumeMeshFile m = read_volume_mesh(f);
  EXPECT_EQ(m.mesh.n_cells(), 1u);
  EXPECT_EQ(m.n_skipped_lower_dimension, 1);
  const std::string q = dir.write("q.vtk",
                                  "# vtk DataFile Version 3.0\nm\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
                                  "0 0 0\n1 0 0\n0 1 0\n0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n71\n");
  try {
    read_volume_mesh(q);
    ADD_FAILURE() << "accepted an unsupported cell";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell 0 has VTK type 71"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace blayer
