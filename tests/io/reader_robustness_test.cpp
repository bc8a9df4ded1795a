// What each reader does with the files real exports and typos produce: non-numeric
// and out-of-range coordinates, headers that claim more than the file holds, indices
// that do not fit, truncated files. Every one is refused with a message naming the file,
// the line (text formats) and the element, or read exactly; never read as something else.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "blayer/core/errors.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/io/read_surface.h"
#include "temp_dir.h"

namespace blayer {
namespace {

using testing::TempDir;

// The message of the InputError that reading `path` throws ("" if none).
std::string read_error(const std::string& path) {
  try {
    read_polygon_soup(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string load_error(const std::string& path) {
  try {
    load_surface(path, {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

#define EXPECT_CONTAINS(text, fragment) EXPECT_NE((text).find(fragment), std::string::npos) << (text)

// A closed unit tetrahedron as ASCII STL; `first_corner` replaces the coordinates of the
// first corner of the first facet.
std::string tetra_stl(const std::string& first_corner = "0 0 0") {
  return "solid t\n"
         "facet normal 0 0 -1\nouter loop\nvertex " + first_corner + "\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\n"
         "facet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 0 1\nendloop\nendfacet\n"
         "facet normal 1 1 1\nouter loop\nvertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\n"
         "facet normal -1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\n"
         "endsolid t\n";
}

// ---- STL ---------------------------------------------------------------------------

TEST(ReaderRobustness, AsciiStlWithANonNumericCoordinateIsRefusedTheSameWayEveryTime) {
  TempDir dir;
  const std::string f = dir.write("inf.stl", tetra_stl("inf 0 0"));
  const std::string first = load_error(f);
  EXPECT_CONTAINS(first, f + ":4: facet 0, corner 0: 'inf' is not a finite number");
  for (int run = 0; run < 8; ++run) EXPECT_EQ(load_error(f), first) << "run " << run;
  EXPECT_CONTAINS(load_error(dir.write("abc.stl", tetra_stl("0 abc 0"))), "abc.stl:4: facet 0, corner 0: 'abc' is not a number");
  EXPECT_CONTAINS(load_error(dir.write("nan.stl", tetra_stl("0 0 nan"))), "'nan' is not a finite number");
}

TEST(ReaderRobustness, AsciiStlCoordinateBeyondFloatRangeIsRefusedAsSuch) {
  TempDir dir;
  EXPECT_CONTAINS(load_error(dir.write("big.stl", tetra_stl("1e39 0 0"))),
                  "'1e39' is outside the range of float (STL stores single precision)");
}

TEST(ReaderRobustness, AsciiStlMissingACornerOrEndingEarlyIsRefusedWithItsLine) {
  TempDir dir;
  std::string two_corners = tetra_stl();
  two_corners.erase(two_corners.find("vertex 0 1 0\n"), std::strlen("vertex 0 1 0\n"));
  EXPECT_CONTAINS(read_error(dir.write("two.stl", two_corners)), "two.stl:6: expected 'vertex x y z' (corner 2 of facet 0; STL facets are triangles)");
  const std::string full = tetra_stl();
  EXPECT_CONTAINS(read_error(dir.write("cut.stl", full.substr(0, full.find("endloop")))),
                  "unexpected end of file: expected 'endloop'");
}

TEST(ReaderRobustness, StlThatIsNeitherBinaryNorAsciiSaysWhy) {
  TempDir dir;
  std::string bin(84, '\0');
  bin[80] = 3;  // three facets claimed, none present
  EXPECT_CONTAINS(read_error(dir.write("b.stl", bin)),
                  "neither binary STL (its header's 3 facets need 234 bytes, the file has 84)");
}

TEST(ReaderRobustness, BinaryStlWithANanCornerIsRefusedNamingTheFacet) {
  TempDir dir;
  std::string bin(80, ' ');
  const std::uint32_t n = 1;
  bin.append(reinterpret_cast<const char*>(&n), 4);
  const float rec[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, std::nanf(""), 0};
  bin.append(reinterpret_cast<const char*>(rec), sizeof rec);
  bin.append(2, '\0');
  EXPECT_CONTAINS(read_error(dir.write("nan.stl", bin)), "nan.stl: facet 0, corner 2: coordinate nan is not a finite number");
}

TEST(ReaderRobustness, StlFacetsWithCoincidentCornersAreDroppedWithANote) {
  TempDir dir;
  std::string text = tetra_stl();
  text.insert(text.rfind("endsolid"), "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 0\nvertex 1 0 0\n"
                                      "endloop\nendfacet\n");
  const PreparedSurface p = load_surface(dir.write("t.stl", text), {});
  EXPECT_EQ(p.surface.triangles.size(), 4u);
  ASSERT_FALSE(p.notes.empty());
  EXPECT_CONTAINS(p.notes[0], "dropped 1 STL facets with two corners at the same point");
}

// ---- OFF ---------------------------------------------------------------------------

const char* kTetraOffBody =
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

TEST(ReaderRobustness, OffHeaderClaimingMoreVerticesThanTheFileHoldsFailsAtOnce) {
  TempDir dir;
  const std::string f = dir.write("claims.off", std::string("OFF\n1000000000000 4 0\n") + kTetraOffBody);
  EXPECT_CONTAINS(read_error(f), f + ":7: the header claims 1000000000000 vertices, the file holds 4 "
                                     "(this line is not a vertex: '3 0 2 1')");
}

TEST(ReaderRobustness, OffHeaderClaimingMoreFacesThanTheFileHoldsFailsAtTheEnd) {
  TempDir dir;
  EXPECT_CONTAINS(read_error(dir.write("faces.off", std::string("OFF\n4 4000000000 0\n") + kTetraOffBody)),
                  "the header claims 4000000000 faces, the file holds 4");
}

TEST(ReaderRobustness, OffCoordinatesBeyondFloatRangeAreReadAsDoubles) {
  TempDir dir;
  const PolygonSoup s = read_polygon_soup(dir.write(
      "e40.off", "OFF\n4 4 0\n0 0 0\n1e+40 0 0\n0 1e40 0\n0 0 1e+300\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"));
  ASSERT_EQ(s.points.size(), 4u);
  EXPECT_EQ(s.points[1][0], 1e40);
  EXPECT_EQ(s.points[2][1], 1e40);
  EXPECT_EQ(s.points[3][2], 1e300);
  ASSERT_EQ(s.faces.size(), 4u);  // the parse stays in step: faces are the file's
  EXPECT_EQ(s.faces[3], (std::vector<int>{0, 3, 2}));
}

TEST(ReaderRobustness, OffSurfaceScaledBeyondFloatRangeIsUsable) {
  TempDir dir;
  const PreparedSurface p = load_surface(
      dir.write("e40.off", "OFF\n4 4 0\n0 0 0\n1e+40 0 0\n0 1e40 0\n0 0 1e40\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"), {});
  EXPECT_TRUE(p.closed);
  EXPECT_NEAR(p.enclosed_volume / 1e120, 1.0 / 6.0, 1e-12);
}

TEST(ReaderRobustness, CoordinatesTooLargeToComputeWithAreRefusedNamingTheVertex) {
  TempDir dir;
  const std::string msg = load_error(
      dir.write("e300.off", "OFF\n4 4 0\n0 0 0\n1e+300 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"));
  EXPECT_CONTAINS(msg, "coordinates too large to compute with");
  EXPECT_CONTAINS(msg, "vertex 1 at (1e+300, 0, 0)");
}

// The limit itself: a tetrahedron reaching |x| = 1e75 is prepared with finite
// geometry (its volume, 1e225 / 6, included); one a hair beyond is refused.
TEST(ReaderRobustness, CoordinateMagnitudeLimitIsInclusive) {
  PolygonSoup tet{{{0, 0, 0}, {kMaxCoordinateMagnitude, 0, 0}, {0, kMaxCoordinateMagnitude, 0},
                   {0, 0, kMaxCoordinateMagnitude}},
                  {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
  const PreparedSurface p = prepare_surface(tet, "big.off", {});
  EXPECT_TRUE(std::isfinite(p.enclosed_volume));
  EXPECT_NEAR(p.enclosed_volume / 1e225, 1.0 / 6.0, 1e-12);
  tet.points[3][2] = std::nextafter(kMaxCoordinateMagnitude, 1e300);
  EXPECT_THROW(prepare_surface(tet, "big.off", {}), InputError);
}

TEST(ReaderRobustness, OffCoordinateBeyondDoubleRangeOrNonNumericIsRefusedWithItsLine) {
  TempDir dir;
  EXPECT_CONTAINS(read_error(dir.write("a.off", std::string("OFF\n4 4 0\n0 0 1e400\n") + (kTetraOffBody + 6))),
                  "a.off:3: vertex 0: '1e400' is outside the range of double");
  EXPECT_CONTAINS(read_error(dir.write("b.off", std::string("OFF\n4 4 0\n0 0 x\n") + (kTetraOffBody + 6))),
                  "b.off:3: vertex 0: 'x' is not a number");
}

TEST(ReaderRobustness, OffFaceListingFewerIndicesThanItsCountIsRefused) {
  TempDir dir;
  EXPECT_CONTAINS(read_error(dir.write("f.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 0 1 2\n")),
                  "f.off:7: face 0: says 5 vertices, the line lists 3");
  EXPECT_CONTAINS(read_error(dir.write("g.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 99999999999\n")),
                  "face 0: vertex index '99999999999' is not an integer in int range");
}

TEST(ReaderRobustness, OffVariantsAreReadOrRefusedByName) {
  TempDir dir;
  const PolygonSoup s = read_polygon_soup(dir.write(
      "c.off", "COFF\n4 4 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n0 0 1 9 9 9 255\n"
               "3 0 2 1\n3 0 1 3\n3 1 2 3 1 1 1\n3 0 3 2\n"));
  EXPECT_EQ(s.points.size(), 4u);
  EXPECT_EQ(s.points[3], (Vec3{0, 0, 1}));
  EXPECT_EQ(s.faces[2], (std::vector<int>{1, 2, 3}));
  EXPECT_CONTAINS(read_error(dir.write("b.off", "OFF BINARY\n")), "binary OFF is not supported");
  EXPECT_CONTAINS(read_error(dir.write("d.off", "4OFF\n1 0 0\n0 0 0 1\n")), "4OFF and nOFF");
}

// ---- OBJ ---------------------------------------------------------------------------

TEST(ReaderRobustness, ObjVertexThatIsNotANumberIsRefusedNotDropped) {
  TempDir dir;
  const std::string body = "v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
  EXPECT_CONTAINS(read_error(dir.write("a.obj", "v abc 0 0\n" + body)), "a.obj:1: vertex 0: 'abc' is not a number");
  EXPECT_CONTAINS(read_error(dir.write("i.obj", "v inf 0 0\n" + body)), "i.obj:1: vertex 0: 'inf' is not a finite number");
  const PolygonSoup s = read_polygon_soup(dir.write("b.obj", "v 1e300 0 0\n" + body));
  EXPECT_EQ(s.points[0][0], 1e300);
  EXPECT_EQ(s.faces.size(), 4u);
}

TEST(ReaderRobustness, ObjReferencesAreOneBasedRelativeOrWithTextureAndNormal) {
  TempDir dir;
  const PolygonSoup s = read_polygon_soup(dir.write(
      "r.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvn 0 0 1\nf 1/1/1 3//1 2/1\nf -4 -3 -1\n"
               "f 2 3 \\\n 4\n"));
  ASSERT_EQ(s.faces.size(), 3u);
  EXPECT_EQ(s.faces[0], (std::vector<int>{0, 2, 1}));
  EXPECT_EQ(s.faces[1], (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(s.faces[2], (std::vector<int>{1, 2, 3}));
  EXPECT_CONTAINS(read_error(dir.write("z.obj", "v 0 0 0\nf 0 1 1\n")), "z.obj:2: face 0: vertex reference 0");
  EXPECT_CONTAINS(read_error(dir.write("n.obj", "v 0 0 0\nf -1 -2 -1\n")), "reaches before the first vertex");
  EXPECT_CONTAINS(read_error(dir.write("h.obj", "v 0 0 0\nf 1 2 99999999999\n")),
                  "h.obj:2: face 0: vertex reference '99999999999' is not an integer in int range");
}

// ---- PLY ---------------------------------------------------------------------------

std::string ply_header(const std::string& format, const std::string& n_vertices, const std::string& type = "float") {
  return "ply\nformat " + format + " 1.0\nelement vertex " + n_vertices + "\nproperty " + type + " x\nproperty " +
         type + " y\nproperty " + type + " z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
}

TEST(ReaderRobustness, AsciiPlyHeaderClaimingMoreVerticesFailsAtOnce) {
  TempDir dir;
  EXPECT_CONTAINS(read_error(dir.write("v.ply", ply_header("ascii", "1000000000000") + kTetraOffBody)),
                  "the header claims 1000000000000 vertex elements, the file holds 4 (this line is not a vertex: '3 0 2 1')");
}

TEST(ReaderRobustness, AsciiPlyValuesFollowTheirDeclaredType) {
  TempDir dir;
  const std::string body = "0 0 0\n1e300 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
  EXPECT_CONTAINS(read_error(dir.write("f.ply", ply_header("ascii", "4") + body)),
                  "f.ply:11: vertex 1: property x: '1e300' is outside the range of float");
  const PolygonSoup s = read_polygon_soup(dir.write("d.ply", ply_header("ascii", "4", "double") + body));
  EXPECT_EQ(s.points[1][0], 1e300);
  EXPECT_EQ(s.faces[3], (std::vector<int>{0, 3, 2}));
}

TEST(ReaderRobustness, BinaryPlyCountsAreBoundedByTheBytesLeft) {
  TempDir dir;
  std::string body;
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  body.append(reinterpret_cast<const char*>(p), sizeof p);
  EXPECT_CONTAINS(read_error(dir.write("c.ply", ply_header("binary_little_endian", "5000000000") + body)),
                  "the header claims 5000000000 vertex elements of at least 12 bytes, the 48 bytes left hold at most 4");
  const unsigned char face[] = {200, 0, 0, 0, 0};  // a list of 200 ints, one present
  EXPECT_CONTAINS(read_error(dir.write("l.ply", ply_header("binary_little_endian", "4") + body +
                                                    std::string(reinterpret_cast<const char*>(face), 5))),
                  "face 0: list vertex_indices of 200 values runs past the end of the file");
}

// ---- legacy VTK ----------------------------------------------------------------------

const char* kVtkHead = "# vtk DataFile Version 3.0\ntetra\nASCII\nDATASET POLYDATA\n";

TEST(ReaderRobustness, LegacyVtkPolygonSizeThatDisagreesWithItsCellsIsRefusedNotACrash) {
  TempDir dir;
  EXPECT_CONTAINS(read_error(dir.write("s.vtk", std::string(kVtkHead) +
                                                    "POINTS 4 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                                    "POLYGONS 4 16000\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n")),
                  "POLYGONS claims 16000 integers, the file holds 16");
  EXPECT_CONTAINS(read_error(dir.write("p.vtk", std::string(kVtkHead) +
                                                    "POINTS 1000000000000 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                                    "POLYGONS 4 16\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n")),
                  "POINTS claims 1000000000000 points, the file holds 4 (then 'POLYGONS')");
}

TEST(ReaderRobustness, LegacyVtkVersion5OffsetsAndConnectivityAreRead) {
  TempDir dir;
  const PolygonSoup s = read_polygon_soup(dir.write(
      "v5.vtk", "# vtk DataFile Version 5.1\ntetra\nASCII\nDATASET POLYDATA\nPOINTS 4 float\n0 0 0 1 0 0 0 1 0\n"
                "0 0 1\nMETADATA\nINFORMATION 0\n\nPOLYGONS 5 12\nOFFSETS vtktypeint64\n0 3 6 9 12\n"
                "CONNECTIVITY vtktypeint64\n0 2 1 0 1 3 1 2 3 0 3 2\nCELL_DATA 4\nSCALARS x int 1\n"));
  ASSERT_EQ(s.points.size(), 4u);
  EXPECT_EQ(s.points[2], (Vec3{0, 1, 0}));
  ASSERT_EQ(s.faces.size(), 4u);
  EXPECT_EQ(s.faces[3], (std::vector<int>{0, 3, 2}));
}

// ---- VTP -----------------------------------------------------------------------------

TEST(ReaderRobustness, VtpThatVtkCannotParseIsAnErrorWithVtksReason) {
  TempDir dir;
  EXPECT_CONTAINS(read_error(dir.write("g.vtp", "<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"4\">")),
                  "g.vtp: cannot parse the .vtp file");
}

}  // namespace
}  // namespace blayer
