// blayer writes .vtu files itself (io/src/vtu_writer.h), compressing blocks in
// parallel. The oracle is VTK's own writer in the same data mode (inline base64,
// 64-bit headers, the same compressor and level): every DataArray's text must be the
// same, byte for byte, on arrays of one block, of exactly whole blocks, of several runs
// of blocks, and empty ones, for both compressors. The one exception is by design:
// with zlib, floating-point arrays are stored (deflate level 0, which VTK's compressor
// cannot be set to), so for them the blocks must hold the same bytes as VTK's once
// inflated by VTK's own decompressor, in the same block layout, each block stored.
#include <gtest/gtest.h>

#include <vtkBase64Utilities.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkZLibDataCompressor.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "blayer/io/vtk_io.h"
#include "mixed_mesh.h"
#include "temp_dir.h"

namespace blayer {
namespace {

using testing::TempDir;

// The mesh as VTK's own writer writes it, built here independently of io/.
void write_with_vtk(const VolumeMesh& m, const std::string& path, VtkCompressor compressor) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Vec3& p : m.points) points->InsertNextPoint(p[0], p[1], p[2]);
  grid->SetPoints(points);
  vtkNew<vtkIdTypeArray> offsets, conn;
  for (std::int64_t o : m.offsets) offsets->InsertNextValue(o);
  for (std::int64_t c : m.connectivity) conn->InsertNextValue(c);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, conn);
  vtkNew<vtkUnsignedCharArray> types;
  for (CellType t : m.cell_types) types->InsertNextValue(static_cast<unsigned char>(t));
  grid->SetCells(types, cells);
  auto add = [](const DataArray& a, vtkFieldData* to) {
    vtkSmartPointer<vtkDataArray> arr;
    if (a.integer()) {
      arr = vtkSmartPointer<vtkIntArray>::New();
    } else if (a.single_precision()) {
      arr = vtkSmartPointer<vtkFloatArray>::New();
    } else {
      arr = vtkSmartPointer<vtkDoubleArray>::New();
    }
    arr->SetNumberOfComponents(a.n_components);
    arr->SetNumberOfTuples(static_cast<vtkIdType>(a.values.size() / a.n_components));
    for (std::size_t i = 0; i < a.values.size(); ++i) arr->SetVariantValue(static_cast<vtkIdType>(i), a.values[i]);
    arr->SetName(a.name.c_str());
    to->AddArray(arr);
  };
  for (const DataArray& a : m.point_data) add(a, grid->GetPointData());
  for (const DataArray& a : m.cell_data) add(a, grid->GetCellData());
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(grid);
  w->SetFileName(path.c_str());
  w->SetDataModeToBinary();
  if (compressor == VtkCompressor::kLz4) {
    w->SetCompressionLevel(5);
    w->SetCompressorTypeToLZ4();
  } else {
    w->SetCompressionLevel(1);
    w->SetCompressorTypeToZLib();
  }
  w->SetHeaderTypeToUInt64();
  ASSERT_EQ(w->Write(), 1);
}

struct ArrayText {
  std::string type;  // VTK's type name
  std::string text;  // base64
};

// The base64 text of every DataArray of a file, by name (VTK may follow it with
// information keys, which are not data).
std::map<std::string, ArrayText> array_texts(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string s = buf.str();
  std::map<std::string, ArrayText> out;
  for (std::size_t at = s.find("<DataArray"); at != std::string::npos; at = s.find("<DataArray", at + 1)) {
    const std::size_t type_at = s.find("type=\"", at) + 6;
    const std::size_t name_at = s.find("Name=\"", at) + 6;
    const std::string name = s.substr(name_at, s.find('"', name_at) - name_at);
    std::size_t text = s.find('>', at) + 1;
    while (std::isspace(static_cast<unsigned char>(s[text]))) ++text;
    std::size_t end = text;
    while (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end])) && s[end] != '<') ++end;
    out[name] = {s.substr(type_at, s.find('"', type_at) - type_at), s.substr(text, end - text)};
  }
  return out;
}

std::vector<unsigned char> base64_decoded(const std::string& text) {
  std::vector<unsigned char> out(text.size() / 4 * 3 + 3);
  const std::size_t n = vtkBase64Utilities::DecodeSafely(reinterpret_cast<const unsigned char*>(text.data()),
                                                         text.size(), out.data(), out.size());
  out.resize(n);
  return out;
}

// A compressed array's text taken apart: the header's words (block count, block size,
// last block size, compressed sizes) and the blocks, as stored and as inflated.
struct ZlibBlocks {
  std::vector<std::uint64_t> header;
  std::vector<std::vector<unsigned char>> compressed, inflated;
};

// Fails the test (rather than reading out of range) on text that is not such an array.
void zlib_blocks(const std::string& text, ZlibBlocks* b) {
  ASSERT_GE(text.size(), 12u);
  std::uint64_t n_blocks;
  std::memcpy(&n_blocks, base64_decoded(text.substr(0, 12)).data(), 8);
  ASSERT_LT(n_blocks, text.size());  // each block takes at least one character
  const std::size_t header_chars = 4 * ((8 * (3 + n_blocks) + 2) / 3);
  ASSERT_LE(header_chars, text.size());
  const std::vector<unsigned char> header = base64_decoded(text.substr(0, header_chars));
  b->header.resize(3 + n_blocks);
  ASSERT_GE(header.size(), 8 * b->header.size());
  std::memcpy(b->header.data(), header.data(), 8 * b->header.size());
  ASSERT_LE(b->header[1], 1u << 20);
  ASSERT_LE(b->header[2], b->header[1]);
  const std::vector<unsigned char> body = base64_decoded(text.substr(header_chars));
  vtkNew<vtkZLibDataCompressor> z;
  std::size_t at = 0;
  for (std::uint64_t i = 0; i < n_blocks; ++i) {
    const std::size_t size = b->header[3 + i];
    ASSERT_LE(size, body.size() - at) << "block " << i << " runs past the text";
    const std::size_t raw = i + 1 == n_blocks && b->header[2] != 0 ? b->header[2] : b->header[1];
    b->compressed.emplace_back(body.begin() + at, body.begin() + at + size);
    std::vector<unsigned char> out(raw);
    ASSERT_EQ(z->Uncompress(b->compressed.back().data(), size, out.data(), raw), raw) << "block " << i;
    b->inflated.push_back(out);
    at += size;
  }
  EXPECT_EQ(at, body.size());
}

// A stored zlib stream of n <= 32768 bytes: 2 header bytes, one stored deflate block
// (5 bytes of header, then the bytes), the 4-byte Adler-32 checksum. (zlib since 1.2.11
// stores a 32 KiB block whole, as Debian 12's 1.2.13 does; older versions split it.)
std::size_t stored_size(std::size_t n) { return n + 11; }

// Ours stores the floating-point blocks that VTK compresses (see the top).
void expect_same_stored_values(const std::string& name, const std::string& ours, const std::string& theirs) {
  ZlibBlocks a, b;
  zlib_blocks(ours, &a);
  zlib_blocks(theirs, &b);
  if (::testing::Test::HasFatalFailure()) return;
  ASSERT_EQ(a.header.size(), b.header.size()) << name;
  for (int w = 0; w < 3; ++w) EXPECT_EQ(a.header[w], b.header[w]) << name << " header word " << w;
  EXPECT_TRUE(a.inflated == b.inflated) << "array " << name << " holds other values than VTK's";
  for (std::size_t i = 0; i < a.compressed.size(); ++i)
    EXPECT_EQ(a.compressed[i].size(), stored_size(a.inflated[i].size())) << name << " block " << i << " is not stored";
}

void expect_same_arrays_as_vtk(const VolumeMesh& m, VtkCompressor compressor) {
  TempDir dir;
  VtkWriteOptions options;
  options.compressor = compressor;
  write_vtu(m, dir.file("ours.vtu"), options);
  write_with_vtk(m, dir.file("vtk.vtu"), compressor);
  const auto ours = array_texts(dir.file("ours.vtu"));
  const auto theirs = array_texts(dir.file("vtk.vtu"));
  ASSERT_GE(theirs.size(), 4u);  // at least Points, connectivity, offsets, types
  ASSERT_EQ(ours.size(), theirs.size());
  for (const auto& [name, array] : theirs) {
    ASSERT_TRUE(ours.count(name)) << name;
    EXPECT_EQ(ours.at(name).type, array.type) << name;
    if (compressor == VtkCompressor::kZlib && array.type.rfind("Float", 0) == 0) {
      expect_same_stored_values(name, ours.at(name).text, array.text);
      continue;
    }
    EXPECT_EQ(ours.at(name).text.size(), array.text.size()) << name;
    EXPECT_TRUE(ours.at(name).text == array.text) << "array " << name << " differs from VTK's";
  }
}

// Stacked wedges on an n x n grid split into triangles: the connectivity of 2 n^2 L
// wedges spans several runs of 64 blocks when 96 n^2 L bytes exceed 2 MiB.
VolumeMesh stacked_wedges(int n, int layers) {
  VolumeMesh m;
  const int row = n + 1, plane = row * row;
  for (int k = 0; k <= layers; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.points.push_back({i + 0.01 * std::sin(j), j + 0.0, 0.1 * k + 0.001 * i});
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::int64_t a = k * plane + j * row + i, b = a + 1, c = a + row, d = c + 1;
        const std::int64_t w1[6] = {a, b, d, a + plane, b + plane, d + plane};
        const std::int64_t w2[6] = {a, d, c, a + plane, d + plane, c + plane};
        m.add_cell(CellType::kWedge, w1);
        m.add_cell(CellType::kWedge, w2);
      }
  DataArray height{"column_height", 1, std::vector<double>{}};
  for (const Vec3& p : m.points) height.values.push_back(p[2] / 3.0);
  DataArray layer{"layer", 1, ArrayValues(ValueType::kInt32)}, volume{"volume", 1, ArrayValues(ValueType::kFloat32, std::vector<double>{})};
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    layer.values.push_back(static_cast<double>(c / (2 * n * n)));
    volume.values.push_back(1.0 / (1.0 + static_cast<double>(c % 7)));
  }
  m.point_data = {height};
  m.cell_data = {layer, volume};
  return m;
}

TEST(VtuWriter, ArraysOfOneBlockAreVtksOwnText) {
  expect_same_arrays_as_vtk(testing::mixed_mesh(), VtkCompressor::kZlib);
  expect_same_arrays_as_vtk(testing::mixed_mesh(), VtkCompressor::kLz4);
}

TEST(VtuWriter, ArraysOfSeveralRunsOfBlocksAreVtksOwnText) {
  // 2 * 130^2 * 2 = 67,600 wedges: a connectivity of 3.2 MB, more than one run of 64
  // blocks of 32 KiB; the points (131^2 * 3) and the offsets several blocks each.
  const VolumeMesh m = stacked_wedges(130, 2);
  ASSERT_GT(m.connectivity.size() * 8, 64u * 32768u);
  expect_same_arrays_as_vtk(m, VtkCompressor::kZlib);
  expect_same_arrays_as_vtk(m, VtkCompressor::kLz4);
}

TEST(VtuWriter, ArraysOfWholeBlocksAreVtksOwnText) {
  // 8,192 cells: the Int32 and Float32 cell arrays fill exactly one block, whose
  // header names a last block of 0 bytes.
  VolumeMesh m = stacked_wedges(64, 1);
  ASSERT_EQ(m.n_cells(), 8192u);
  expect_same_arrays_as_vtk(m, VtkCompressor::kZlib);
  expect_same_arrays_as_vtk(m, VtkCompressor::kLz4);
}

TEST(VtuWriter, EmptyArraysAreVtksOwnText) {
  VolumeMesh m;
  m.point_data = {{"column_height", 1, ArrayValues(ValueType::kFloat64)}};
  m.cell_data = {{"layer", 1, ArrayValues(ValueType::kInt32)}};
  expect_same_arrays_as_vtk(m, VtkCompressor::kZlib);
}

TEST(VtuWriter, CellOffsetsThatDoNotMatchTheConnectivityAreRefusedBeforeAnyFile) {
  VolumeMesh m = testing::mixed_mesh();
  m.connectivity.pop_back();
  TempDir dir;
  EXPECT_THROW(write_vtu(m, dir.file("m.vtu")), std::logic_error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("m.vtu")));
}

}  // namespace
}  // namespace blayer
