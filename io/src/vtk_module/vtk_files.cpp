// The .vtp writer and the volume mesh reader of the VTK module (vtk_module.h).
#include "vtk_files.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdint>
#include <filesystem>
#include <limits>

#include "blayer/core/errors.h"
#include "vtu_writer.h"

namespace blayer::detail {

namespace {

// Arrays are handed to VTK without a copy (the writer only reads them), which
// keeps the peak memory of writing a large mesh close to the mesh itself.
template <class VtkArray, class T>
vtkSmartPointer<vtkDataArray> wrapped(const DataArray& a) {
  const std::vector<T>& values = a.values.as<T>();
  auto arr = vtkSmartPointer<VtkArray>::New();
  arr->SetNumberOfComponents(a.n_components);
  arr->SetArray(const_cast<T*>(values.data()), static_cast<vtkIdType>(values.size()), /*save=*/1);
  return arr;
}

vtkSmartPointer<vtkDataArray> to_vtk(const DataArray& a) {
  vtkSmartPointer<vtkDataArray> arr;
  switch (a.type()) {
    case ValueType::kInt32: arr = wrapped<vtkIntArray, std::int32_t>(a); break;
    case ValueType::kFloat32: arr = wrapped<vtkFloatArray, float>(a); break;
    case ValueType::kFloat64: arr = wrapped<vtkDoubleArray, double>(a); break;
  }
  arr->SetName(a.name.c_str());
  return arr;
}

// Points are shared with VTK without a copy: Vec3 is three contiguous doubles.
vtkSmartPointer<vtkPoints> to_vtk_points(const std::vector<Vec3>& pts) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  vtkNew<vtkDoubleArray> xyz;
  xyz->SetNumberOfComponents(3);
  if (!pts.empty())
    xyz->SetArray(const_cast<double*>(pts.data()->data()), static_cast<vtkIdType>(3 * pts.size()), /*save=*/1);
  auto points = vtkSmartPointer<vtkPoints>::New();
  if (!pts.empty()) points->SetData(xyz);
  return points;
}

template <class Writer>
void set_encoding(Writer* w, VtkCompressor compressor) {
  // Inline base64 keeps the file well-formed XML; appended raw data would not be (see
  // vtk_io.h), and appended base64 is no faster.
  w->SetDataModeToBinary();
  // The level is set first: SetCompressorType hands the writer's level to the new
  // compressor (levels: vtu_writer.h).
  if (compressor == VtkCompressor::kLz4) {
    w->SetCompressionLevel(kLz4Level);
    w->SetCompressorTypeToLZ4();
  } else {
    w->SetCompressionLevel(kZlibLevel);
    w->SetCompressorTypeToZLib();
  }
  // 64-bit block headers: arrays of more than 4 GiB (about 500M connectivity ids) stay
  // readable.
  w->SetHeaderTypeToUInt64();
}

// How a read array is kept: float and double as they are; integers as Int32 when every
// value fits (all of blayer's own), otherwise as doubles, which hold any integer up to
// 2^53 exactly (written back as Float64).
ValueType stored_type(int vtk_type, const std::vector<double>& values) {
  if (vtk_type == VTK_FLOAT) return ValueType::kFloat32;
  if (vtk_type == VTK_DOUBLE) return ValueType::kFloat64;
  for (double x : values)
    if (!(x >= std::numeric_limits<std::int32_t>::min() && x <= std::numeric_limits<std::int32_t>::max()))
      return ValueType::kFloat64;
  return ValueType::kInt32;
}

void copy_arrays(vtkFieldData* from, std::vector<DataArray>* to, const std::vector<char>* keep) {
  for (int i = 0; i < from->GetNumberOfArrays(); ++i) {
    vtkDataArray* arr = vtkDataArray::SafeDownCast(from->GetAbstractArray(i));
    if (!arr || !arr->GetName()) continue;
    std::vector<double> values;
    const int n_components = arr->GetNumberOfComponents();
    const vtkIdType n = arr->GetNumberOfTuples();
    for (vtkIdType t = 0; t < n; ++t) {
      if (keep && !(*keep)[t]) continue;
      for (int c = 0; c < n_components; ++c) values.push_back(arr->GetComponent(t, c));
    }
    to->push_back(DataArray{arr->GetName(), n_components, ArrayValues(stored_type(arr->GetDataType(), values), values)});
  }
}

}  // namespace

void write_vtp_file(const TriSurface& s, const std::vector<DataArray>& point_data,
                    const std::vector<DataArray>& cell_data, const std::string& file, const std::string& target,
                    VtkCompressor compressor) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(to_vtk_points(s.points));
  vtkNew<vtkCellArray> tris;
  tris->AllocateExact(static_cast<vtkIdType>(s.triangles.size()), static_cast<vtkIdType>(3 * s.triangles.size()));
  for (const Triangle& t : s.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    tris->InsertNextCell(3, ids);
  }
  poly->SetPolys(tris);
  for (const DataArray& a : point_data) poly->GetPointData()->AddArray(to_vtk(a));
  for (const DataArray& a : cell_data) poly->GetCellData()->AddArray(to_vtk(a));
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(poly);
  w->SetFileName(file.c_str());
  set_encoding(w.Get(), compressor);
  if (w->Write() != 1 || w->GetErrorCode() != 0) throw IoError(target + ": cannot write the file");
}

VolumeMeshFile read_volume_mesh_with_vtk(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path + ": no such file");
  if (std::filesystem::file_size(path, ec) == 0) throw InputError(path + ": the file is empty");
  const std::string ext = std::filesystem::path(path).extension().string();
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  if (ext == ".vtu") {
    vtkNew<vtkXMLUnstructuredGridReader> r;
    if (!r->CanReadFile(path.c_str())) throw InputError(path + ": not a VTK XML unstructured grid (.vtu)");
    r->SetFileName(path.c_str());
    r->Update();
    if (r->GetErrorCode() != 0) throw InputError(path + ": cannot parse the .vtu file");
    grid = r->GetOutput();
  } else if (ext == ".vtk") {
    vtkNew<vtkUnstructuredGridReader> r;
    r->SetFileName(path.c_str());
    if (!r->IsFileUnstructuredGrid()) throw InputError(path + ": not a legacy VTK unstructured grid");
    r->Update();
    grid = r->GetOutput();
  } else {
    throw InputError(path + ": unknown volume mesh format '" + ext + "' (expected .vtu or .vtk)");
  }
  if (!grid || grid->GetNumberOfPoints() == 0) throw InputError(path + ": the mesh has no points");
  require_indexable_points(static_cast<std::size_t>(grid->GetNumberOfPoints()), path);

  VolumeMeshFile out;
  VolumeMesh& m = out.mesh;
  m.points.resize(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) grid->GetPoint(i, m.points[i].data());
  const vtkIdType nc = grid->GetNumberOfCells();
  std::vector<char> keep(nc, 0);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < nc; ++c) {
    const int type = grid->GetCellType(c);
    if (type == VTK_TETRA || type == VTK_PYRAMID || type == VTK_WEDGE || type == VTK_HEXAHEDRON) {
      grid->GetCellPoints(c, ids);
      std::int64_t nodes[8];
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) nodes[k] = ids->GetId(k);
      m.add_cell(static_cast<CellType>(type), nodes);
      keep[c] = 1;
    } else if (type == VTK_VERTEX || type == VTK_POLY_VERTEX || type == VTK_LINE || type == VTK_POLY_LINE ||
               type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_POLYGON || type == VTK_TRIANGLE_STRIP ||
               type == VTK_EMPTY_CELL) {
      ++out.n_skipped_lower_dimension;
    } else {
      throw InputError(path + ": cell " + std::to_string(c) + " has VTK type " + std::to_string(type) +
                       ", which is not supported (linear tet, pyramid, wedge and hexahedron are)");
    }
  }
  copy_arrays(grid->GetPointData(), &m.point_data, nullptr);
  copy_arrays(grid->GetCellData(), &m.cell_data, &keep);
  return out;
}

}  // namespace blayer::detail
