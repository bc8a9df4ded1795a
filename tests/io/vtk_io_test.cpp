#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellValidator.h>
#include <vtkDoubleArray.h>
#include <vtkGenericCell.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "blayer/core/errors.h"
#include "blayer/io/vtk_io.h"
#include "blayer/quality/cell_validity.h"
#include "mixed_mesh.h"
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
  m.cell_data.push_back({"layer", 1, ArrayValues(ValueType::kInt32, std::vector<double>{0})});
  m.point_data.push_back({"normal", 3, std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}});
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
  EXPECT_TRUE(layer->integer());
  EXPECT_EQ(layer->values, m.cell_data[0].values);
  const DataArray* normal = back.mesh.find_point_array("normal");
  ASSERT_NE(normal, nullptr);
  EXPECT_EQ(normal->n_components, 3);
}

void expect_same_mesh(const VolumeMesh& back, const VolumeMesh& m) {
  EXPECT_EQ(back.points, m.points);
  EXPECT_EQ(back.cell_types, m.cell_types);
  EXPECT_EQ(back.offsets, m.offsets);
  EXPECT_EQ(back.connectivity, m.connectivity);
}

void expect_round_trip_keeps_every_cell_type_and_array_kind(const VtkWriteOptions& options) {
  TempDir dir;
  const VolumeMesh m = testing::mixed_mesh();
  write_vtu(m, dir.file("m.vtu"), options);
  const VolumeMeshFile back = read_volume_mesh(dir.file("m.vtu"));
  EXPECT_EQ(back.n_skipped_lower_dimension, 0);
  expect_same_mesh(back.mesh, m);
  for (const DataArray& a : m.point_data) {
    const DataArray* b = back.mesh.find_point_array(a.name);
    ASSERT_NE(b, nullptr) << a.name;
    EXPECT_EQ(b->n_components, a.n_components) << a.name;
    EXPECT_EQ(b->integer(), a.integer()) << a.name;
    EXPECT_EQ(b->values, a.values) << a.name;
  }
  for (const DataArray& a : m.cell_data) {
    const DataArray* b = back.mesh.find_cell_array(a.name);
    ASSERT_NE(b, nullptr) << a.name;
    EXPECT_EQ(b->integer(), a.integer()) << a.name;
    ASSERT_EQ(b->values.size(), a.values.size()) << a.name;
    // Float32 arrays come back rounded to float, integer and Float64 arrays exactly.
    for (std::size_t i = 0; i < a.values.size(); ++i)
      EXPECT_EQ(b->values[i], a.single_precision() ? static_cast<double>(static_cast<float>(a.values[i])) : a.values[i])
          << a.name << "[" << i << "]";
  }
}

TEST(VtkIo, VtuRoundTripKeepsEveryCellTypeAndArrayKind) {
  expect_round_trip_keeps_every_cell_type_and_array_kind(VtkWriteOptions{});
}

TEST(VtkIo, Lz4VtuRoundTripKeepsEveryCellTypeAndArrayKind) {
  expect_round_trip_keeps_every_cell_type_and_array_kind(VtkWriteOptions{VtkCompressor::kLz4});
}

// Files written before the output became inline base64: appended raw binary (not XML
// that a strict parser accepts), LZ4-compressed, 64-bit headers. VTK's reader still reads
// them, and so must read_volume_mesh.
void write_appended_raw_lz4(const VolumeMesh& m, const std::string& path) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Vec3& p : m.points) points->InsertNextPoint(p.data());
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->AllocateExact(static_cast<vtkIdType>(m.n_cells()), static_cast<vtkIdType>(m.connectivity.size()));
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    std::vector<vtkIdType> ids(m.connectivity.begin() + m.offsets[c], m.connectivity.begin() + m.offsets[c + 1]);
    grid->InsertNextCell(static_cast<int>(m.cell_types[c]), static_cast<vtkIdType>(ids.size()), ids.data());
  }
  vtkNew<vtkIntArray> layer;
  layer->SetName("layer");
  for (std::size_t c = 0; c < m.n_cells(); ++c) layer->InsertNextValue(static_cast<int>(m.find_cell_array("layer")->values[c]));
  grid->GetCellData()->AddArray(layer);
  vtkNew<vtkDoubleArray> normal;
  normal->SetName("normal");
  normal->SetNumberOfComponents(3);
  for (double v : m.find_point_array("normal")->values.as<double>()) normal->InsertNextValue(v);
  grid->GetPointData()->AddArray(normal);
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(grid);
  w->SetFileName(path.c_str());
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();
  w->SetCompressorTypeToLZ4();
  w->SetHeaderTypeToUInt64();
  ASSERT_EQ(w->Write(), 1);
}

TEST(VtkIo, ReadsOlderVtuWithAppendedRawLz4Data) {
  TempDir dir;
  const VolumeMesh m = testing::mixed_mesh();
  write_appended_raw_lz4(m, dir.file("old.vtu"));
  const VolumeMeshFile back = read_volume_mesh(dir.file("old.vtu"));
  expect_same_mesh(back.mesh, m);
  const DataArray* layer = back.mesh.find_cell_array("layer");
  ASSERT_NE(layer, nullptr);
  EXPECT_EQ(layer->values, m.find_cell_array("layer")->values);
  const DataArray* normal = back.mesh.find_point_array("normal");
  ASSERT_NE(normal, nullptr);
  EXPECT_EQ(normal->values, m.find_point_array("normal")->values);
}

TEST(VtkIo, ReadArraysKeepTheirPrecisionAndIntegersPastInt32StayExact) {
  TempDir dir;
  const std::string f = dir.write("a.vtk",
                                  "# vtk DataFile Version 3.0\nm\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
                                  "0 0 0\n1 0 0\n0 1 0\n0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n"
                                  "CELL_DATA 1\nFIELD FieldData 3\nsmall 1 1 long\n7\nbig 1 1 long\n3000000000\n"
                                  "third 1 1 float\n0.333333343\n");
  const VolumeMeshFile m = read_volume_mesh(f);
  const DataArray* small = m.mesh.find_cell_array("small");
  const DataArray* big = m.mesh.find_cell_array("big");
  const DataArray* third = m.mesh.find_cell_array("third");
  ASSERT_TRUE(small && big && third);
  EXPECT_EQ(small->values, ArrayValues(std::vector<std::int32_t>{7}));
  EXPECT_EQ(big->values, ArrayValues(std::vector<double>{3e9}));
  EXPECT_EQ(third->values, ArrayValues(std::vector<float>{1.0f / 3.0f}));
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
