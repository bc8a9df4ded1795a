// Every .vtu/.vtp blayer writes must be well-formed XML (ParaView's expat rejects
// anything else, e.g. raw appended binary) and the default .vtu must be readable by
// meshio, the converter users reach for. Both are checked with the real tools.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "blayer/io/vtk_io.h"
#include "external_tool.h"
#include "mixed_mesh.h"
#include "temp_dir.h"

namespace blayer {
namespace {

using testing::describe_failure;
using testing::run_tool;
using testing::shell_quote;
using testing::TempDir;
using testing::ToolRun;

// Asserts that xmllint parses `path` as well-formed XML.
void expect_well_formed_xml(const std::string& path) {
  const ToolRun run = run_tool("xmllint --noout " + shell_quote(path));
  EXPECT_EQ(run.exit_code, 0) << path << " is not well-formed XML:\n" << describe_failure(run, "xmllint", "libxml2-utils");
}

// The compressor named in the <VtkFile> element.
std::string compressor_of(const std::string& path) {
  std::ifstream in(path);
  std::string head(512, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const std::string key = "compressor=\"";
  const std::size_t at = head.find(key);
  if (at == std::string::npos) return "";
  return head.substr(at + key.size(), head.find('"', at + key.size()) - at - key.size());
}

TEST(VtkXmlOutput, DefaultCompressorIsZlib) {
  TempDir dir;
  write_vtu(testing::mixed_mesh(), dir.file("m.vtu"));
  write_vtp(TriSurface{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}}, {}, {}, dir.file("s.vtp"));
  EXPECT_EQ(compressor_of(dir.file("m.vtu")), "vtkZLibDataCompressor");
  EXPECT_EQ(compressor_of(dir.file("s.vtp")), "vtkZLibDataCompressor");
}

TEST(VtkXmlOutput, VtuWithEveryCellTypeAndArrayKindIsWellFormedXml) {
  TempDir dir;
  write_vtu(testing::mixed_mesh(), dir.file("m.vtu"));
  expect_well_formed_xml(dir.file("m.vtu"));
}

TEST(VtkXmlOutput, VtpWithPointAndCellArraysIsWellFormedXml) {
  TempDir dir;
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const DataArray normal{"normal", 3, std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, 1, 0.6, 0, 0.8}};
  const DataArray reason{"stop_reason", 1, ArrayValues(ValueType::kInt32, std::vector<double>{0, 1, 2, 3})};
  const DataArray visibility{"visibility", 1, ArrayValues(ValueType::kFloat32, std::vector<double>{0.5, 0.25, 1, 1.0 / 3.0})};
  const DataArray marker{"marker", 1, ArrayValues(ValueType::kInt32, std::vector<double>{1, 1, 2, 2})};
  write_vtp(s, {normal, reason, visibility}, {marker}, dir.file("s.vtp"));
  expect_well_formed_xml(dir.file("s.vtp"));
}

TEST(VtkXmlOutput, EmptyVtuAndVtpAreWellFormedXml) {
  TempDir dir;
  write_vtu(VolumeMesh{}, dir.file("empty.vtu"));
  write_vtp(TriSurface{}, {}, {}, dir.file("empty.vtp"));
  expect_well_formed_xml(dir.file("empty.vtu"));
  expect_well_formed_xml(dir.file("empty.vtp"));
}

TEST(VtkXmlOutput, Lz4VtuAndVtpAreWellFormedXml) {
  TempDir dir;
  const VtkWriteOptions lz4{VtkCompressor::kLz4};
  write_vtu(testing::mixed_mesh(), dir.file("m.vtu"), lz4);
  TriSurface s;
  s.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  s.triangles = {{0, 1, 2}};
  write_vtp(s, {{"layers", 1, ArrayValues(ValueType::kInt32, {1, 2, 3})}}, {{"marker", 1, ArrayValues(ValueType::kInt32, std::vector<double>{1})}},
            dir.file("s.vtp"), lz4);
  EXPECT_EQ(compressor_of(dir.file("m.vtu")), "vtkLZ4DataCompressor");
  EXPECT_EQ(compressor_of(dir.file("s.vtp")), "vtkLZ4DataCompressor");
  expect_well_formed_xml(dir.file("m.vtu"));
  expect_well_formed_xml(dir.file("s.vtp"));
}

// Prints what meshio read, one line per item, numbers as %.17g so that equal doubles
// print identically here and in the expectation below.
const char* const kMeshioSummary = R"(
import collections, sys
import meshio
m = meshio.read(sys.argv[1])
def numbers(a):
    return " ".join("%.17g" % float(v) for v in a.ravel())
conn = collections.defaultdict(list)
for block in m.cells:
    conn[block.type].extend(int(i) for row in block.data for i in row)
for t in sorted(conn):
    n = sum(len(b.data) for b in m.cells if b.type == t)
    print("cells", t, n, " ".join(str(i) for i in conn[t]))
print("points", len(m.points), numbers(m.points))
for name in sorted(m.point_data):
    a = m.point_data[name].reshape(len(m.points), -1)
    print("point_array", name, a.shape[1], numbers(a))
for name in sorted(m.cell_data):
    print("cell_array", name, sum(len(b) for b in m.cell_data[name]))
)";

std::string numbers(const std::vector<double>& values) {
  std::string s;
  char buf[32];
  for (double v : values) {
    std::snprintf(buf, sizeof buf, "%.17g", v);
    s += (s.empty() ? "" : " ") + std::string(buf);
  }
  return s;
}

std::string numbers(const ArrayValues& values) {
  std::vector<double> v(values.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = values[i];
  return numbers(v);
}

// The summary kMeshioSummary should print for m.
std::string expected_summary(const VolumeMesh& m) {
  static const std::map<CellType, std::string> kMeshioName = {{CellType::kTet, "tetra"},
                                                                {CellType::kPyramid, "pyramid"},
                                                                {CellType::kWedge, "wedge"},
                                                                {CellType::kHex, "hexahedron"}};
  std::map<std::string, std::pair<int, std::string>> by_type;  // count, connectivity
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    auto& [count, conn] = by_type[kMeshioName.at(m.cell_types[c])];
    ++count;
    // meshio lists wedges in gmsh's prism order, whose base normal points towards the
    // top: VTK's (0,1,2,3,4,5) becomes (0,2,1,3,5,4).
    static const int kWedgeToMeshio[6] = {0, 2, 1, 3, 5, 4};
    const bool wedge = m.cell_types[c] == CellType::kWedge;
    for (std::int64_t k = 0; k < m.offsets[c + 1] - m.offsets[c]; ++k)
      conn += (conn.empty() ? "" : " ") + std::to_string(m.connectivity[m.offsets[c] + (wedge ? kWedgeToMeshio[k] : k)]);
  }
  std::string s;
  for (const auto& [type, count_conn] : by_type)
    s += "cells " + type + " " + std::to_string(count_conn.first) + " " + count_conn.second + "\n";
  std::vector<double> xyz;
  for (const Vec3& p : m.points) xyz.insert(xyz.end(), {p[0], p[1], p[2]});
  s += "points " + std::to_string(m.points.size()) + " " + numbers(xyz) + "\n";
  std::map<std::string, const DataArray*> point_arrays, cell_arrays;
  for (const DataArray& a : m.point_data) point_arrays[a.name] = &a;
  for (const DataArray& a : m.cell_data) cell_arrays[a.name] = &a;
  for (const auto& [name, a] : point_arrays)
    s += "point_array " + name + " " + std::to_string(a->n_components) + " " + numbers(a->values) + "\n";
  for (const auto& [name, a] : cell_arrays) s += "cell_array " + name + " " + std::to_string(m.n_cells()) + "\n";
  return s;
}

// Writes m as dir/m.vtu with the default options and checks what meshio reads from it.
void expect_meshio_reads(const VolumeMesh& m, const TempDir& dir) {
  write_vtu(m, dir.file("m.vtu"));
  const std::string script = dir.write("summary.py", kMeshioSummary);
  // Debian's interpreter: a python3 earlier on PATH may not see python3-meshio.
  const ToolRun run = run_tool("/usr/bin/python3 " + shell_quote(script) + " " + shell_quote(dir.file("m.vtu")));
  ASSERT_EQ(run.exit_code, 0) << "meshio cannot read the default .vtu:\n"
                              << describe_failure(run, "/usr/bin/python3", "python3-meshio");
  EXPECT_EQ(run.output, expected_summary(m));
}

TEST(VtkXmlOutput, MeshioReadsDefaultVtuWithCellCountsByTypeAndPointArrays) {
  TempDir dir;
  expect_meshio_reads(testing::mixed_mesh(), dir);
}

// n x n wall quads, two triangles each, extruded by `layers` unit-spaced prisms.
VolumeMesh prism_grid(int n, int layers) {
  VolumeMesh m;
  DataArray height{"column_height", 1, std::vector<double>{}};
  for (int k = 0; k <= layers; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        m.points.push_back({i / static_cast<double>(n), j / static_cast<double>(n), 0.1 * k + 0.01 * i});
        height.values.push_back(0.1 * layers + 0.001 * j);
      }
  auto id = [&](int k, int i, int j) { return (static_cast<std::int64_t>(k) * (n + 1) + j) * (n + 1) + i; };
  DataArray layer{"layer", 1, ArrayValues(ValueType::kInt32)};
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::int64_t lower[2][3] = {{id(k, i, j), id(k, i + 1, j + 1), id(k, i + 1, j)},
                                          {id(k, i, j), id(k, i, j + 1), id(k, i + 1, j + 1)}};
        for (const auto& t : lower) {
          const std::int64_t up = id(k + 1, 0, 0) - id(k, 0, 0);
          const std::int64_t wedge[6] = {t[0], t[1], t[2], t[0] + up, t[1] + up, t[2] + up};
          m.add_cell(CellType::kWedge, wedge);
          layer.values.push_back(k);
        }
      }
  m.point_data.push_back(std::move(height));
  m.cell_data.push_back(std::move(layer));
  return m;
}

// VTK compresses each array in 32 KiB blocks; 2,400 prisms make the connectivity
// (115 kB) and the points (42 kB) span several, with a short last block.
TEST(VtkXmlOutput, VtuWhoseArraysSpanSeveralCompressionBlocksIsWellFormedXmlAndReadByMeshio) {
  const VolumeMesh m = prism_grid(20, 3);
  ASSERT_GT(m.connectivity.size() * sizeof(std::int64_t), 3u * 32768u);
  TempDir dir;
  expect_meshio_reads(m, dir);
  expect_well_formed_xml(dir.file("m.vtu"));
}

}  // namespace
}  // namespace blayer
