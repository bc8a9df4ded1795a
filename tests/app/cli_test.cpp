#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>

#include "../io/temp_dir.h"
#include "run_cli.h"

namespace blayer {
namespace {

using testing::run_blayer;
using testing::TempDir;
using testing::tetra_off;

// A bad-input run: exit 1, a message on stderr starting with "error:" that contains
// `fragment`, no signal, and no output file left behind.
void expect_clean_failure(const std::string& args, const TempDir& dir, const std::string& output,
                          const std::string& fragment) {
  const auto r = run_blayer(args, dir.file(""));
  EXPECT_EQ(r.signal, 0) << args;
  EXPECT_EQ(r.status, 1) << args << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("error:", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(output)) << output;
}

TEST(Cli, HelpOfEveryCommandExitsZero) {
  TempDir dir;
  for (const char* cmd : {"--help", "normals --help", "extrude --help", "check --help"}) {
    const auto r = run_blayer(cmd, dir.file(""));
    EXPECT_EQ(r.status, 0) << cmd;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << cmd;
  }
}

TEST(Cli, ExtrudeHelpListsTheGrowthParameters) {
  TempDir dir;
  const auto r = run_blayer("extrude --help", dir.file(""));
  for (const char* opt : {"--layers", "--first-height", "--growth-ratio", "--total-thickness", "--side", "--config"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

TEST(Cli, UnknownOptionIsAnError) {
  TempDir dir;
  dir.write("t.off", tetra_off());
  expect_clean_failure("normals " + dir.file("t.off") + " -o " + dir.file("n.vtp") + " --frobnicate", dir,
                       dir.file("n.vtp"), "--frobnicate");
}

TEST(Cli, MalformedNumberIsAnError) {
  TempDir dir;
  dir.write("t.off", tetra_off());
  expect_clean_failure("extrude " + dir.file("t.off") + " -o " + dir.file("o.vtu") + " --layers ten", dir,
                       dir.file("o.vtu"), "--layers: expected an integer");
}

TEST(Cli, UnknownConfigKeyIsAnError) {
  TempDir dir;
  dir.write("t.off", tetra_off());
  dir.write("case.toml", "input = \"t.off\"\nlayer = 3\n");
  expect_clean_failure("normals --config " + dir.file("case.toml") + " -o " + dir.file("n.vtp"), dir,
                       dir.file("n.vtp"), "unknown key 'layer'");
}

TEST(Cli, BadSurfaceFailsWithTheFileAndElementNamedAndNoOutput) {
  TempDir dir;
  // Tetrahedron with two faces missing: a hole whose rim is not planar (a planar one
  // would be a half model's cut).
  dir.write("hole.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n");
  expect_clean_failure("normals " + dir.file("hole.off") + " -o " + dir.file("n.vtp"), dir, dir.file("n.vtp"),
                       "hole.off");
  expect_clean_failure("extrude " + dir.file("hole.off") + " -o " + dir.file("o.vtu"), dir, dir.file("o.vtu"),
                       "open boundary edges");
}

TEST(Cli, GarbageInputNeverCrashes) {
  TempDir dir;
  dir.write("g.stl", "solid x\nfacet normal nan nan\n\x01\x02 vertex 1e999 2 3\n");
  dir.write("g.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n3 0 1 2\n");
  dir.write("g.obj", "v 0 0 0\nf 1 2 3\n");
  for (const char* f : {"g.stl", "g.off", "g.obj"}) {
    const auto r = run_blayer(std::string("extrude ") + dir.file(f) + " -o " + dir.file("o.vtu"), dir.file(""));
    EXPECT_EQ(r.signal, 0) << f;
    EXPECT_EQ(r.status, 1) << f << r.err;
    EXPECT_EQ(r.err.rfind("error:", 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("o.vtu")));
  }
}

TEST(Cli, NormalsWritesTheContractArraysInInputOrder) {
  TempDir dir;
  dir.write("t.off", tetra_off());
  const auto r = run_blayer("normals " + dir.file("t.off") + " -o " + dir.file("n.vtp"), dir.file(""));
  ASSERT_EQ(r.status, 0) << r.err;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(dir.file("n.vtp").c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  ASSERT_EQ(poly->GetNumberOfPoints(), 4);
  EXPECT_EQ(poly->GetNumberOfPolys(), 4);
  double p[3];
  poly->GetPoint(1, p);
  EXPECT_EQ(p[0], 1.0);
  for (const char* name : {"normal", "visibility", "normality_deg", "normal_status"})
    EXPECT_NE(poly->GetPointData()->GetArray(name), nullptr) << name;
  vtkDataArray* n = poly->GetPointData()->GetArray("normal");
  ASSERT_EQ(n->GetNumberOfComponents(), 3);
  for (vtkIdType i = 0; i < 4; ++i) {
    double v[3];
    n->GetTuple(i, v);
    EXPECT_NEAR(v[0] * v[0] + v[1] * v[1] + v[2] * v[2], 1.0, 1e-12);
  }
  // Vertex 0 is the corner at the origin of an outward tetrahedron: its normal points
  // away from the body, into the negative octant.
  double v0[3];
  n->GetTuple(0, v0);
  EXPECT_LT(v0[0], 0.0);
  EXPECT_LT(v0[1], 0.0);
  EXPECT_LT(v0[2], 0.0);
}

TEST(Cli, ConfigFileIsReadAndCommandLineOverridesIt) {
  TempDir dir;
  dir.write("t.off", tetra_off());
  dir.write("case.toml", "input = \"t.off\"\nmethod = \"unit\"\n");
  auto r = run_blayer("normals --config " + dir.file("case.toml") + " -o " + dir.file("n.vtp"), dir.file(""));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("method unit"), std::string::npos) << r.out;
  r = run_blayer("normals --config " + dir.file("case.toml") + " --method angle -o " + dir.file("n.vtp"),
                 dir.file(""));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("method angle"), std::string::npos) << r.out;
}

TEST(Cli, CheckOfAMissingMeshIsAnInputError) {
  TempDir dir;
  const auto r = run_blayer("check " + dir.file("none.vtu"), dir.file(""));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind("error:", 0), 0u) << r.err;
}

}  // namespace
}  // namespace blayer

namespace blayer {
namespace {

// One prism as legacy VTK text; `top_z` below 0 puts the top cap under the base.
std::string one_prism_vtk(double top_z) {
  std::string pts = "0 0 0\n1 0 0\n0 1 0\n0 0 " + std::to_string(top_z) + "\n1 0 " + std::to_string(top_z) +
                    "\n0 1 " + std::to_string(top_z) + "\n";
  return "# vtk DataFile Version 3.0\np\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 6 double\n" + pts +
         "CELLS 1 7\n6 0 2 1 3 5 4\nCELL_TYPES 1\n13\n";
}

TEST(CliCheck, ValidMeshExitsZeroAndWritesJson) {
  TempDir dir;
  dir.write("ok.vtk", one_prism_vtk(0.5));
  const auto r = run_blayer("check " + dir.file("ok.vtk") + " --json " + dir.file("r.json"), dir.file(""));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  const std::string json = testing::slurp(dir.file("r.json"));
  for (const char* key : {"\"cells\"", "\"wedge\"", "\"inverted\"", "\"flat\"", "\"non_conforming\"",
                          "\"min_scaled_jacobian\""})
    EXPECT_NE(json.find(key), std::string::npos) << key;
}

TEST(CliCheck, InvertedMeshExitsTwoAndWritesTheBadCells) {
  TempDir dir;
  dir.write("inv.vtk", one_prism_vtk(-0.5));
  const auto r = run_blayer("check " + dir.file("inv.vtk") + " --bad " + dir.file("bad.vtu"), dir.file(""));
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.out.find("INVALID"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir.file("bad.vtu")));
}

// Every input check through the executable: exit 1, "error:", the file named, and no
// output file.
TEST(CliExtrude, EveryInputProblemFailsCleanlyWithoutOutput) {
  const std::string tet_pts = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"nan.off", "OFF\n4 4 0\n0 0 0\n1 0 0\nnan 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
      {"range.off", "OFF\n4 4 0\n" + tet_pts + "3 0 2 1\n3 0 1 3\n3 1 2 9\n3 0 3 2\n"},
      {"dup.off", "OFF\n4 5 0\n" + tet_pts + "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 1 0 2\n"},
      {"degenerate.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n2 0 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
      {"flipped_face.off", "OFF\n4 4 0\n" + tet_pts + "3 0 2 1\n3 0 1 3\n3 1 3 2\n3 0 3 2\n"},
      {"fin.off", "OFF\n5 5 0\n" + tet_pts + "0.3 -1 0.3\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 0 1 4\n"},
      {"unused.off", "OFF\n5 4 0\n" + tet_pts + "9 9 9\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"},
      {"bowtie.off",
       "OFF\n7 8 0\n" + tet_pts +
           "-1 0 0\n0 -1 0\n0 0 -1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n3 0 4 5\n3 0 6 4\n3 4 6 5\n3 0 5 6\n"},
      {"empty.stl", ""},
  };
  for (const auto& [name, text] : bad) {
    TempDir dir;
    dir.write(name, text);
    const auto r = run_blayer("extrude " + dir.file(name) + " -o " + dir.file("o.vtu") + " --envelope " +
                                  dir.file("e.vtp") + " --report " + dir.file("r.json"),
                              dir.file(""));
    EXPECT_EQ(r.signal, 0) << name;
    EXPECT_EQ(r.status, 1) << name << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("error:", 0), 0u) << name << ": " << r.err;
    EXPECT_NE(r.err.find(name), std::string::npos) << r.err;
    EXPECT_EQ(dir.entries(), 1) << name << ": output left behind";
  }
}

}  // namespace
}  // namespace blayer

namespace blayer {
namespace {

TEST(CliExtrude, HybridBoundaryFileMarksWallAndFarfield) {
  TempDir dir;
  const std::string cube = std::string(BLAYER_CASES_DIR) + "/003_cube/surface.stl";
  const auto r = run_blayer("extrude " + cube + " -o " + dir.file("m.vtu") + " --layers 2 --first-height 0.02" +
                                " --fill --farfield-scale 3 --boundary " + dir.file("b.vtp"),
                            dir.file(""));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(dir.file("b.vtp").c_str());
  reader->Update();
  vtkDataArray* marker = reader->GetOutput()->GetCellData()->GetArray("marker");
  ASSERT_NE(marker, nullptr);
  int wall = 0, farfield = 0;
  for (vtkIdType i = 0; i < marker->GetNumberOfTuples(); ++i) {
    const int m = static_cast<int>(marker->GetTuple1(i));
    wall += m == 1;
    farfield += m == 2;
  }
  EXPECT_EQ(wall, 972);  // the cube's wall triangles
  EXPECT_GE(farfield, 12);  // at least two triangles per box face
  EXPECT_EQ(wall + farfield, marker->GetNumberOfTuples());
  // Every triangle faces out of the domain, so the divergence theorem gives the volume
  // of the box less the unit cube: positive, and at the wall the normals point into the
  // cube (towards its centre, the mean of its corners).
  vtkPolyData* b = reader->GetOutput();
  double centre[3] = {0, 0, 0};
  int n_corners = 0;
  for (vtkIdType i = 0; i < b->GetNumberOfCells(); ++i) {
    if (marker->GetTuple1(i) != 1) continue;
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    b->GetCellPoints(i, n, ids);
    for (int k = 0; k < 3; ++k, ++n_corners)
      for (int a = 0; a < 3; ++a) centre[a] += b->GetPoint(ids[k])[a];
  }
  for (double& c : centre) c /= n_corners;
  double volume = 0.0;
  int wall_into_body = 0;
  for (vtkIdType i = 0; i < b->GetNumberOfCells(); ++i) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    b->GetCellPoints(i, n, ids);
    double p[3][3];
    for (int k = 0; k < 3; ++k) {
      b->GetPoint(ids[k], p[k]);
      for (int a = 0; a < 3; ++a) p[k][a] -= centre[a];
    }
    const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double v[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    volume += (p[0][0] * c[0] + p[0][1] * c[1] + p[0][2] * c[2]) / 6.0;
    const double centre_dot = (p[0][0] + p[1][0] + p[2][0]) * c[0] + (p[0][1] + p[1][1] + p[2][1]) * c[1] +
                              (p[0][2] + p[1][2] + p[2][2]) * c[2];
    if (marker->GetTuple1(i) == 1 && centre_dot < 0) ++wall_into_body;
  }
  EXPECT_EQ(wall_into_body, 972);
  EXPECT_GT(volume, 1.0);
}

TEST(CliExtrude, NoHeightGivenUsesTheDefaultFirstHeightAndSaysSo) {
  TempDir dir;
  const std::string cube = std::string(BLAYER_CASES_DIR) + "/003_cube/surface.stl";
  const auto r = run_blayer("extrude " + cube + " -o " + dir.file("m.vtu") + " --layers 2", dir.file(""));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("note: no height given: first-height = 0.00034641 (2e-4 x bounding-box diagonal)"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace blayer
