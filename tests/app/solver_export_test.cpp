// `blayer extrude` writing each solver format on real cases (a layers-only cube, the
// sphere hybrid, an open plate), checked by the solvers' own tools: checkMesh on the
// polyMesh and on gmshToFoam of the MSH file, cgnscheck, gmsh, and meshio on SU2 and MSH.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "../io/solver_tools.h"
#include "../io/temp_dir.h"
#include "blayer/io/prepare_surface.h"
#include "run_cli.h"

namespace blayer {
namespace {

namespace fs = std::filesystem;
using testing::run_blayer;
using testing::TempDir;
using testing::ToolRun;

struct Extruded {
  std::map<std::string, long> cells;    // "wedge", "pyramid", "tetra", "hexahedron" as blayer's check counted them
  std::map<std::string, long> patches;  // name -> faces, as blayer printed them
  long n_boundary_faces = 0;
};

// Runs blayer extrude and reads its summary lines.
Extruded extrude(const std::string& args, const TempDir& dir) {
  const testing::CliRun r = run_blayer("extrude " + args, dir.file(""));
  EXPECT_EQ(r.status, 0) << args << "\n" << r.out << r.err;
  Extruded e;
  std::smatch m;
  if (std::regex_search(r.out, m,
                        std::regex("check: [0-9]+ cells \\(([0-9]+) wedges, ([0-9]+) pyramids, ([0-9]+) tets(, ([0-9]+) hexes)?\\)"))) {
    e.cells = {{"wedge", std::stol(m[1])}, {"pyramid", std::stol(m[2])}, {"tetra", std::stol(m[3])},
               {"hexahedron", m[5].matched ? std::stol(m[5]) : 0}};
  }
  const std::regex patch_re("(\\w+) \\(([0-9]+) faces\\)");
  const std::string line = r.out.substr(0, r.out.find("\ncheck:"));
  for (auto it = std::sregex_iterator(line.begin(), line.end(), patch_re); it != std::sregex_iterator(); ++it) {
    e.patches[(*it)[1]] = std::stol((*it)[2]);
    e.n_boundary_faces += std::stol((*it)[2]);
  }
  EXPECT_FALSE(e.cells.empty()) << r.out;
  return e;
}

std::string case_config(const std::string& name) {
  return testing::shell_quote(std::string(BLAYER_CASES_DIR) + "/" + name + "/case.toml");
}

long surface_triangles(const std::string& path) { return long(load_surface(path, {}).surface.triangles.size()); }

void expect_check_mesh(const std::string& case_dir, const Extruded& e) {
  const ToolRun run = testing::run_check_mesh(case_dir);
  ASSERT_EQ(run.exit_code, 0) << testing::describe_failure(run, "checkMesh", "openfoam");
  EXPECT_NE(run.output.find("Mesh OK."), std::string::npos) << run.output;
  EXPECT_EQ(testing::check_mesh_figure(run.output, "prisms:"), e.cells.at("wedge"));
  EXPECT_EQ(testing::check_mesh_figure(run.output, "pyramids:"), e.cells.at("pyramid"));
  EXPECT_EQ(testing::check_mesh_figure(run.output, "tetrahedra:"), e.cells.at("tetra"));
  EXPECT_EQ(testing::check_mesh_figure(run.output, "hexahedra:"), e.cells.at("hexahedron"));
  EXPECT_EQ(testing::check_mesh_patches(run.output), e.patches);
}

void expect_meshio_counts(const std::string& file, const Extruded& e) {
  ToolRun run;
  std::map<std::string, long> n = testing::meshio_counts(file, &run);
  ASSERT_EQ(run.exit_code, 0) << testing::describe_failure(run, "meshio", "python3-meshio");
  for (const auto& [type, count] : e.cells) EXPECT_EQ(count ? n[type] : 0, count) << file << " " << type;
  EXPECT_EQ(n["triangle"] + n["quad"], e.n_boundary_faces) << file;
}

// The cases: a layers-only cube with fans (8 layers of wedges, hexes on the edges, tets at
// the corners) and the sphere hybrid (wedges and tets).
struct ExportCase {
  const char* name;
  const char* extra_args;
  const char* wall_surface;  // relative to the cases directory
  std::vector<std::string> patch_names;
};

const ExportCase kCube{"014_cube_fans", "", "003_cube/surface.stl", {"bl_outer", "wall"}};
const ExportCase kSphereHybrid{"011_sphere_hybrid", "", "002_sphere/surface.stl", {"farfield", "wall"}};

void expect_patches(const Extruded& e, const ExportCase& c) {
  std::vector<std::string> names;
  for (const auto& [name, n] : e.patches) names.push_back(name);
  EXPECT_EQ(names, c.patch_names);
  EXPECT_EQ(e.patches.at("wall"), surface_triangles(std::string(BLAYER_CASES_DIR) + "/" + c.wall_surface));
}

class SolverExport : public ::testing::TestWithParam<ExportCase> {};

TEST_P(SolverExport, OpenFoamCaseIsMeshOkWithTheCellsAndPatches) {
  TempDir dir;
  const Extruded e = extrude("--config " + case_config(GetParam().name) + " --format openfoam -o " +
                                 testing::shell_quote(dir.file("case")),
                             dir);
  expect_patches(e, GetParam());
  expect_check_mesh(dir.file("case"), e);
}

TEST_P(SolverExport, MshIsReadByGmshMeshioAndGmshToFoam) {
  TempDir dir;
  const std::string msh = dir.file("mesh.msh");
  const Extruded e = extrude("--config " + case_config(GetParam().name) + " -o " + testing::shell_quote(msh), dir);
  expect_patches(e, GetParam());
  const ToolRun gmsh = testing::run_tool("gmsh " + testing::shell_quote(msh) + " -0 -o " +
                                         testing::shell_quote(dir.file("again.msh")));
  ASSERT_EQ(gmsh.exit_code, 0) << testing::describe_failure(gmsh, "gmsh", "gmsh");
  EXPECT_EQ(gmsh.output.find("Error"), std::string::npos) << gmsh.output;
  long n_cells = 0;
  for (const auto& [type, n] : e.cells) n_cells += n;
  EXPECT_NE(gmsh.output.find(std::to_string(n_cells + e.n_boundary_faces) + " elements"), std::string::npos)
      << gmsh.output;
  expect_meshio_counts(msh, e);
  expect_meshio_counts(dir.file("again.msh"), e);  // as gmsh wrote it back

  testing::write_openfoam_case_dicts(dir.file("case"));
  const ToolRun convert = testing::run_gmsh_to_foam(msh, dir.file("case"));
  ASSERT_EQ(convert.exit_code, 0) << testing::describe_failure(convert, "gmshToFoam", "openfoam");
  expect_check_mesh(dir.file("case"), e);
}

TEST_P(SolverExport, Su2IsReadByMeshioWithTheMarkers) {
  TempDir dir;
  const std::string su2 = dir.file("mesh.su2");
  const Extruded e = extrude("--config " + case_config(GetParam().name) + " -o " + testing::shell_quote(su2), dir);
  expect_patches(e, GetParam());
  expect_meshio_counts(su2, e);
  const std::string text = testing::slurp(su2);
  for (const auto& [name, n] : e.patches)
    EXPECT_NE(text.find("MARKER_TAG= " + name + "\nMARKER_ELEMS= " + std::to_string(n) + "\n"), std::string::npos)
        << name;
}

TEST_P(SolverExport, CgnsPassesCgnscheck) {
  TempDir dir;
  const std::string cgns = dir.file("mesh.cgns");
  const Extruded e = extrude("--config " + case_config(GetParam().name) + " -o " + testing::shell_quote(cgns), dir);
  expect_patches(e, GetParam());
  const ToolRun run = testing::run_tool("cgnscheck " + testing::shell_quote(cgns));
  ASSERT_EQ(run.exit_code, 0) << testing::describe_failure(run, "cgnscheck", "cgns-convert");
  EXPECT_NE(run.output.find("checking complete"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("ERROR"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("WARNING"), std::string::npos) << run.output;
  for (const auto& [name, n] : e.patches) EXPECT_NE(run.output.find("checking BC \"" + name + "\""), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Cases, SolverExport, ::testing::Values(kCube, kSphereHybrid),
                         [](const auto& info) { return std::string(info.param.name).substr(4); });

// A flat 4 x 4 plate: open, so the layers have side faces over its 16 boundary edges.
std::string plate_off() {
  std::ostringstream os;
  os << "OFF\n25 32 0\n";
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 4; ++i) os << i * 0.25 << ' ' << j * 0.25 << " 0\n";
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const int a = j * 5 + i, b = a + 1, c = a + 6, d = a + 5;
      os << "3 " << a << ' ' << b << ' ' << c << "\n3 " << a << ' ' << c << ' ' << d << '\n';
    }
  return os.str();
}

TEST(SolverExportOpenSurface, SideFacesOverTheOpenBoundaryAreTheirOwnPatch) {
  TempDir dir;
  const std::string plate = dir.write("plate.off", plate_off());
  const Extruded e = extrude(testing::shell_quote(plate) + " --allow-open --layers 3 --first-height 0.01 "
                                 "--format openfoam -o " + testing::shell_quote(dir.file("case")),
                             dir);
  EXPECT_EQ(e.patches.at("wall"), 32);
  EXPECT_EQ(e.patches.at("bl_outer"), 32);
  EXPECT_EQ(e.patches.at("bl_side"), 16 * 3);  // 16 boundary edges, 3 layers of quads over each
  expect_check_mesh(dir.file("case"), e);
}

TEST(SolverExportFiles, RerunningIntoACaseReplacesThePolyMeshAndKeepsTheUsersSystemFiles) {
  TempDir dir;
  const std::string case_dir = dir.file("case");
  extrude("--config " + case_config("003_cube") + " --format openfoam -o " + testing::shell_quote(case_dir), dir);
  std::ofstream(case_dir + "/system/controlDict", std::ios::app) << "// the user's own setting\n";
  std::ofstream(case_dir + "/constant/polyMesh/stale") << "from an earlier mesh\n";
  const Extruded e = extrude("--config " + case_config("011_sphere_hybrid") + " -o " +
                                 testing::shell_quote(case_dir + "/constant/polyMesh"),
                             dir);
  EXPECT_FALSE(fs::exists(case_dir + "/constant/polyMesh/stale"));
  EXPECT_NE(testing::slurp(case_dir + "/system/controlDict").find("the user's own setting"), std::string::npos);
  expect_check_mesh(case_dir, e);
  int n_entries = 0;
  for (auto it = fs::directory_iterator(case_dir + "/constant"); it != fs::directory_iterator(); ++it) ++n_entries;
  EXPECT_EQ(n_entries, 1);  // polyMesh alone: no temporary or old directory left
}

// A failed run: exit 1 with an error naming the output, nothing new in the directory.
void expect_failure_leaves_nothing(const std::string& args, const TempDir& dir, const std::string& fragment) {
  const int before = dir.entries();
  const testing::CliRun r = run_blayer("extrude " + args, dir.file(""));
  EXPECT_EQ(r.status, 1) << args << "\n" << r.out << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
  EXPECT_EQ(dir.entries(), before) << args;
}

TEST(SolverExportFiles, AnOccupiedOrUnwritableTargetFailsAndLeavesNothing) {
  TempDir dir;
  const std::string cube = case_config("003_cube");
  for (const char* name : {"mesh.cgns", "mesh.su2", "mesh.msh"}) {
    fs::create_directory(dir.file(name));  // a directory where the file should go
    expect_failure_leaves_nothing("--config " + cube + " -o " + testing::shell_quote(dir.file(name)), dir, name);
    EXPECT_TRUE(fs::is_empty(dir.file(name))) << name;
  }
  fs::create_directories(dir.file("case/constant"));
  std::ofstream(dir.file("case/constant/polyMesh")) << "not a directory\n";
  expect_failure_leaves_nothing("--config " + cube + " -o " + testing::shell_quote(dir.file("case/constant/polyMesh")),
                                dir, "polyMesh");
  EXPECT_EQ(testing::slurp(dir.file("case/constant/polyMesh")), "not a directory\n");
  // /proc takes no new files, even from root.
  for (const char* target : {"/proc/blayer-test.cgns", "/proc/blayer-test.su2", "/proc/blayer-test.msh"}) {
    expect_failure_leaves_nothing("--config " + cube + " -o " + target, dir, target);
    EXPECT_FALSE(fs::exists(target));
  }
}

TEST(SolverExportFiles, AFormatThatDisagreesWithTheNameIsAnError) {
  TempDir dir;
  const std::string cube = case_config("003_cube");
  expect_failure_leaves_nothing("--config " + cube + " -o " + testing::shell_quote(dir.file("m.su2")) + " --format msh",
                                dir, "--format msh needs an output ending in .msh");
  expect_failure_leaves_nothing("--config " + cube + " -o " + testing::shell_quote(dir.file("m.txt")), dir,
                                "cannot tell the mesh format");
  expect_failure_leaves_nothing("--config " + cube + " -o " + testing::shell_quote(dir.file("m.cgns")) +
                                    " --format openfoam",
                                dir, "--format openfoam writes a directory");
  expect_failure_leaves_nothing("--config " + cube + " -o " + testing::shell_quote(dir.file("m.vtu")) +
                                    " --format stl",
                                dir, "--format");
}

TEST(VtkCompressor, Lz4IsWrittenWhenAskedAndZlibByDefault) {
  TempDir dir;
  const std::string cube = case_config("003_cube");
  extrude("--config " + cube + " -o " + testing::shell_quote(dir.file("z.vtu")), dir);
  extrude("--config " + cube + " --vtk-compressor lz4 -o " + testing::shell_quote(dir.file("l.vtu")) + " --envelope " +
              testing::shell_quote(dir.file("l.vtp")),
          dir);
  EXPECT_NE(testing::slurp(dir.file("z.vtu")).find("vtkZLibDataCompressor"), std::string::npos);
  EXPECT_NE(testing::slurp(dir.file("l.vtu")).find("vtkLZ4DataCompressor"), std::string::npos);
  EXPECT_NE(testing::slurp(dir.file("l.vtp")).find("vtkLZ4DataCompressor"), std::string::npos);
  const testing::CliRun check = run_blayer("check " + testing::shell_quote(dir.file("l.vtu")), dir.file(""));
  EXPECT_EQ(check.status, 0) << check.out << check.err;
  expect_failure_leaves_nothing("--config " + cube + " --vtk-compressor gzip -o " +
                                    testing::shell_quote(dir.file("g.vtu")),
                                dir, "expected one of zlib|lz4");
}

}  // namespace
}  // namespace blayer
