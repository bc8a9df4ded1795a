#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>

#include "blayer/core/errors.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/io/read_surface.h"
#include "blayer/io/vtk_io.h"
#include "temp_dir.h"

namespace blayer {
namespace {

using testing::TempDir;
using testing::tetra_off;

void expect_closed_tetra(const PreparedSurface& p) {
  EXPECT_EQ(p.surface.points.size(), 4u);
  EXPECT_EQ(p.surface.triangles.size(), 4u);
  EXPECT_TRUE(p.closed);
  EXPECT_NEAR(signed_volume(p.surface), 1.0 / 6.0, 1e-12);
}

TEST(ReadSurface, OffKeepsVertexOrderAndDoubleCoordinates) {
  TempDir dir;
  const std::string f = dir.write("t.off",
                                  "OFF\n4 4 0\n0.1234567890123456 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                  "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  const PolygonSoup soup = read_polygon_soup(f);
  ASSERT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.points[1], (Vec3{1, 0, 0}));
  EXPECT_EQ(soup.points[3], (Vec3{0, 0, 1}));
  // The file's digits survive beyond single precision (float keeps ~7 digits).
  EXPECT_NEAR(soup.points[0][0], 0.1234567890123456, 1e-15);
  ASSERT_EQ(soup.faces.size(), 4u);
  EXPECT_EQ(soup.faces[0], (std::vector<int>{0, 2, 1}));
}

TEST(ReadSurface, AFileOfSeveralMebibytesIsReadToItsLastByte) {
  // Files are read in blocks of 1 MiB: a 300 x 300 grid as OFF (about 5 MB) must come
  // back whole, its last point and face included.
  const int n = 300;
  std::string text = "OFF\n" + std::to_string(n * n) + " " + std::to_string(2 * (n - 1) * (n - 1)) + " 0\n";
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) text += std::to_string(i) + " " + std::to_string(j) + " 0.5\n";
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
      text += "3 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n";
      text += "3 " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
    }
  ASSERT_GT(text.size(), 4u << 20);
  TempDir dir;
  const PolygonSoup soup = read_polygon_soup(dir.write("grid.off", text));
  ASSERT_EQ(soup.points.size(), static_cast<std::size_t>(n * n));
  EXPECT_EQ(soup.points.back(), (Vec3{n - 1.0, n - 1.0, 0.5}));
  ASSERT_EQ(soup.faces.size(), static_cast<std::size_t>(2 * (n - 1) * (n - 1)));
  EXPECT_EQ(soup.faces.back(), (std::vector<int>{n * n - n - 2, n * n - 1, n * n - 2}));
}

TEST(ReadSurface, ObjIsRead) {
  TempDir dir;
  const std::string f =
      dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  expect_closed_tetra(load_surface(f, {}));
}

TEST(ReadSurface, AsciiStlIsReadAndVerticesMerged) {
  TempDir dir;
  const Vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int tris[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  std::string text = "solid t\n";
  for (const auto& t : tris) {
    text += "facet normal 0 0 0\nouter loop\n";
    for (int k : t)
      text += "vertex " + std::to_string(p[k][0]) + " " + std::to_string(p[k][1]) + " " + std::to_string(p[k][2]) + "\n";
    text += "endloop\nendfacet\n";
  }
  text += "endsolid t\n";
  expect_closed_tetra(load_surface(dir.write("t.stl", text), {}));
}

TEST(ReadSurface, BinaryStlIsRead) {
  TempDir dir;
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int tris[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  std::string bin(80, ' ');
  const std::uint32_t n = 4;
  bin.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    const float normal[3] = {0, 0, 0};
    bin.append(reinterpret_cast<const char*>(normal), 12);
    for (int k : t) bin.append(reinterpret_cast<const char*>(p[k]), 12);
    bin.append(2, '\0');
  }
  expect_closed_tetra(load_surface(dir.write("t.stl", bin), {}));
}

TEST(ReadSurface, AsciiPlyIsRead) {
  TempDir dir;
  const std::string f = dir.write("t.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  expect_closed_tetra(load_surface(f, {}));
}

TEST(ReadSurface, VtpRoundTripKeepsPointsAndTriangles) {
  TempDir dir;
  const PreparedSurface tet = load_surface(dir.write("t.off", tetra_off()), {});
  write_vtp(tet.surface, {}, {}, dir.file("t.vtp"));
  const PreparedSurface back = load_surface(dir.file("t.vtp"), {});
  EXPECT_EQ(back.surface.points, tet.surface.points);
  EXPECT_EQ(back.surface.triangles, tet.surface.triangles);
}

TEST(ReadSurface, LegacyVtkPolyDataIsRead) {
  TempDir dir;
  const std::string f = dir.write("t.vtk",
                                  "# vtk DataFile Version 3.0\ntetra\nASCII\nDATASET POLYDATA\nPOINTS 4 double\n"
                                  "0 0 0\n1 0 0\n0 1 0\n0 0 1\nPOLYGONS 4 16\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  expect_closed_tetra(load_surface(f, {}));
}

TEST(ReadSurface, GzipCompressedOffIsRead) {
  TempDir dir;
  const std::string plain = dir.write("t.off", tetra_off());
  ASSERT_EQ(std::system(("gzip -k " + plain).c_str()), 0);
  expect_closed_tetra(load_surface(plain + ".gz", {}));
}

void expect_input_error(const std::string& path, const std::string& fragment) {
  try {
    load_surface(path, {});
    ADD_FAILURE() << "no error for " << path;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
  }
}

TEST(ReadSurface, MissingFileIsAnInputError) {
  TempDir dir;
  expect_input_error(dir.file("nope.stl"), "no such file");
}

TEST(ReadSurface, EmptyFileIsAnInputError) {
  TempDir dir;
  expect_input_error(dir.write("e.off", ""), "empty");
}

TEST(ReadSurface, UnknownExtensionIsAnInputError) {
  TempDir dir;
  expect_input_error(dir.write("e.xyz", "1 2 3\n"), "unknown surface format");
}

TEST(ReadSurface, GarbageIsAnInputErrorNotACrash) {
  TempDir dir;
  expect_input_error(dir.write("g.off", "this is not a mesh\n\x01\x02\x03"), "g.off");
  expect_input_error(dir.write("g.vtp", "<VTKFile garbage"), "g.vtp");
  expect_input_error(dir.write("g.ply", "ply\ngarbage\n"), "g.ply");
}

}  // namespace
}  // namespace blayer
