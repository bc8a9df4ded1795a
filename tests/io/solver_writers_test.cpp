// Each solver writer on a small conforming mesh of hexes, pyramids and wedges (and one of
// tets), judged by the solvers' own tools and read back independently.
#include <cgnslib.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "blayer/core/errors.h"
#include "blayer/io/cgns_writer.h"
#include "blayer/io/msh_writer.h"
#include "blayer/io/openfoam_writer.h"
#include "blayer/io/solver_mesh.h"
#include "blayer/io/su2_writer.h"
#include "blayer/quality/mesh_check.h"
#include "grid_meshes.h"
#include "solver_tools.h"
#include "temp_dir.h"

namespace blayer {
namespace {

namespace fs = std::filesystem;
using testing::GridCell;
using testing::TempDir;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The mixed grid (3 x 2 x 3 cubes: a column of wedges, hexes and pyramids beside it) with
// the wedges' z = 0 triangles as the wall patch "floor" and every other face "sides".
constexpr std::size_t kFloorTriangles = 4;  // the wedge column's 1 x 2 cubes, two triangles each

SolverMesh patched(const VolumeMesh& m) {
  EXPECT_TRUE(check_volume_mesh(m).ok());
  PatchTriangles floor{"floor", PatchKind::kWall, {}};
  for (std::size_t c = 0; c < m.n_cells(); ++c) {
    const PointId* n = m.cell_nodes(c);
    if (m.cell_types[c] == CellType::kWedge && m.points[n[0]][2] == 0.0) floor.triangles.push_back({n[0], n[1], n[2]});
  }
  return make_solver_mesh(m, {floor}, "sides");
}

SolverMesh patched_mixed_grid() { return patched(testing::mixed_grid_mesh(3, 2, 3)); }

void expect_check_mesh_ok(const std::string& case_dir, const SolverMesh& s) {
  const testing::ToolRun run = testing::run_check_mesh(case_dir);
  ASSERT_EQ(run.exit_code, 0) << testing::describe_failure(run, "checkMesh", "openfoam");
  EXPECT_NE(run.output.find("Mesh OK."), std::string::npos) << run.output;
  EXPECT_EQ(testing::check_mesh_figure(run.output, "cells:"), long(s.cells.n_cells()));
  EXPECT_EQ(testing::check_mesh_figure(run.output, "hexahedra:"), long(s.n_cells_of(CellType::kHex)));
  EXPECT_EQ(testing::check_mesh_figure(run.output, "prisms:"), long(s.n_cells_of(CellType::kWedge)));
  EXPECT_EQ(testing::check_mesh_figure(run.output, "pyramids:"), long(s.n_cells_of(CellType::kPyramid)));
  EXPECT_EQ(testing::check_mesh_figure(run.output, "tetrahedra:"), long(s.n_cells_of(CellType::kTet)));
  std::map<std::string, long> expected;
  for (const BoundaryPatch& p : s.patches) expected[p.name] = long(p.size);
  EXPECT_EQ(testing::check_mesh_patches(run.output), expected);
}

std::string write_case(const SolverMesh& s, const TempDir& dir) {
  const std::string case_dir = dir.file("case");
  fs::create_directories(case_dir + "/constant/polyMesh");
  fs::create_directories(case_dir + "/system");
  write_openfoam_polymesh(s, case_dir + "/constant/polyMesh", "polyMesh");
  write_openfoam_system(case_dir + "/system", "system");
  return case_dir;
}

TEST(OpenFoamWriter, MixedGridIsMeshOkWithItsCellsAndPatches) {
  TempDir dir;
  const SolverMesh s = patched_mixed_grid();
  ASSERT_EQ(s.patches.size(), 2u);
  EXPECT_EQ(s.patches[0].size, kFloorTriangles);
  const std::string case_dir = write_case(s, dir);
  expect_check_mesh_ok(case_dir, s);
  const std::string boundary = read_text(case_dir + "/constant/polyMesh/boundary");
  EXPECT_NE(boundary.find("floor\n    {\n        type            wall;"), std::string::npos) << boundary;
  EXPECT_NE(boundary.find("sides\n    {\n        type            patch;"), std::string::npos) << boundary;
}

TEST(OpenFoamWriter, TetGridIsMeshOk) {
  TempDir dir;
  const SolverMesh s = patched(testing::grid_mesh(3, 2, 2, GridCell::kTets));
  expect_check_mesh_ok(write_case(s, dir), s);
}

TEST(OpenFoamWriter, PolyMeshPathsAreRecognised) {
  EXPECT_TRUE(is_openfoam_polymesh_path("run/wing/constant/polyMesh"));
  EXPECT_TRUE(is_openfoam_polymesh_path("run/wing/constant/polyMesh/"));
  EXPECT_FALSE(is_openfoam_polymesh_path("run/wing"));
  EXPECT_FALSE(is_openfoam_polymesh_path("run/polyMesh"));
  EXPECT_EQ(openfoam_polymesh_dir("run/wing/"), "run/wing/constant/polyMesh");
  EXPECT_EQ(openfoam_polymesh_dir("run/wing/constant/polyMesh/"), "run/wing/constant/polyMesh");
}

// What a CGNS file holds, read back with the CGNS library.
struct CgnsContent {
  std::map<std::string, std::pair<CGNS_ENUMT(ElementType_t), cgsize_t>> sections;  // name -> type, count
  std::map<std::string, CGNS_ENUMT(BCType_t)> bc_types;
  std::map<std::string, std::string> bc_families;
  std::map<std::string, cgsize_t> bc_sizes;
  std::size_t n_prisms_base_towards_top = 0, n_prisms = 0;
};

CgnsContent read_cgns(const std::string& path) {
  CgnsContent c;
  int fn = 0;
  EXPECT_EQ(cg_open(path.c_str(), CG_MODE_READ, &fn), CG_OK) << cg_get_error();
  char name[33];
  cgsize_t size[3];
  EXPECT_EQ(cg_zone_read(fn, 1, 1, name, size), CG_OK);
  std::vector<double> xyz[3];
  const char* coords[3] = {"CoordinateX", "CoordinateY", "CoordinateZ"};
  for (int d = 0; d < 3; ++d) {
    xyz[d].resize(size[0]);
    cgsize_t lo = 1, hi = size[0];
    EXPECT_EQ(cg_coord_read(fn, 1, 1, coords[d], CGNS_ENUMV(RealDouble), &lo, &hi, xyz[d].data()), CG_OK);
  }
  auto point = [&](cgsize_t id) { return Vec3{xyz[0][id - 1], xyz[1][id - 1], xyz[2][id - 1]}; };
  int n_sections = 0;
  cg_nsections(fn, 1, 1, &n_sections);
  for (int s = 1; s <= n_sections; ++s) {
    CGNS_ENUMT(ElementType_t) type;
    cgsize_t start, end;
    int n_boundary, parent;
    cg_section_read(fn, 1, 1, s, name, &type, &start, &end, &n_boundary, &parent);
    c.sections[name] = {type, end - start + 1};
    if (type != CGNS_ENUMV(PENTA_6)) continue;
    // SIDS: PENTA_6's face (N1, N3, N2) points out of the cell, so (N1, N2, N3) faces
    // the top triangle (N4, N5, N6).
    std::vector<cgsize_t> conn(6 * (end - start + 1));
    cg_elements_read(fn, 1, 1, s, conn.data(), nullptr);
    for (std::size_t e = 0; e < conn.size(); e += 6) {
      const Vec3 n = cross(point(conn[e + 1]) - point(conn[e]), point(conn[e + 2]) - point(conn[e]));
      const Vec3 top = (point(conn[e + 3]) + point(conn[e + 4]) + point(conn[e + 5])) / 3.0;
      const Vec3 base = (point(conn[e]) + point(conn[e + 1]) + point(conn[e + 2])) / 3.0;
      ++c.n_prisms;
      c.n_prisms_base_towards_top += dot(n, top - base) > 0;
    }
  }
  int n_bc = 0;
  cg_nbocos(fn, 1, 1, &n_bc);
  for (int b = 1; b <= n_bc; ++b) {
    CGNS_ENUMT(BCType_t) type;
    CGNS_ENUMT(PointSetType_t) set;
    cgsize_t n_points, normal_list_size;
    int normal_index, n_datasets;
    CGNS_ENUMT(DataType_t) normal_type;
    cg_boco_info(fn, 1, 1, b, name, &type, &set, &n_points, &normal_index, &normal_list_size, &normal_type, &n_datasets);
    c.bc_types[name] = type;
    cgsize_t range[2];
    cg_boco_read(fn, 1, 1, b, range, nullptr);
    c.bc_sizes[name] = range[1] - range[0] + 1;
    char family[33];
    cg_goto(fn, 1, "Zone_t", 1, "ZoneBC_t", 1, "BC_t", b, "end");
    if (cg_famname_read(family) == CG_OK) c.bc_families[name] = family;
  }
  cg_close(fn);
  return c;
}

TEST(CgnsWriter, MixedGridPassesCgnscheckAndReadsBackWithItsSectionsAndBoundaryConditions) {
  TempDir dir;
  const SolverMesh s = patched_mixed_grid();
  const std::string file = dir.file("grid.cgns");
  write_cgns(s, file, "grid.cgns");
  const testing::ToolRun run = testing::run_tool("cgnscheck " + testing::shell_quote(file));
  ASSERT_EQ(run.exit_code, 0) << testing::describe_failure(run, "cgnscheck", "cgns-convert");
  EXPECT_NE(run.output.find("checking complete"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("ERROR"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("WARNING"), std::string::npos) << run.output;

  const CgnsContent c = read_cgns(file);
  EXPECT_EQ(c.sections.at("Hexahedra").second, cgsize_t(s.n_cells_of(CellType::kHex)));
  EXPECT_EQ(c.sections.at("Pyramids").second, cgsize_t(s.n_cells_of(CellType::kPyramid)));
  EXPECT_EQ(c.sections.at("Prisms").second, cgsize_t(s.n_cells_of(CellType::kWedge)));
  EXPECT_EQ(c.sections.count("Tetrahedra"), 0u);
  EXPECT_EQ(c.sections.at("floor").first, CGNS_ENUMV(TRI_3));
  EXPECT_EQ(c.sections.at("sides_tri").first, CGNS_ENUMV(TRI_3));  // the sides have triangles and quads
  EXPECT_EQ(c.sections.at("sides_quad").first, CGNS_ENUMV(QUAD_4));
  EXPECT_EQ(c.sections.at("sides_tri").second + c.sections.at("sides_quad").second,
            cgsize_t(s.n_boundary_faces() - kFloorTriangles));
  EXPECT_EQ(c.bc_types.at("floor"), CGNS_ENUMV(BCWall));
  EXPECT_EQ(c.bc_types.at("sides"), CGNS_ENUMV(BCGeneral));
  EXPECT_EQ(c.bc_families.at("floor"), "floor");
  EXPECT_EQ(c.bc_sizes.at("floor"), cgsize_t(kFloorTriangles));
  EXPECT_EQ(c.bc_sizes.at("sides"), cgsize_t(s.n_boundary_faces() - kFloorTriangles));
  EXPECT_EQ(c.n_prisms_base_towards_top, c.n_prisms);
  EXPECT_GT(c.n_prisms, 0u);
}

TEST(MshWriter, GmshRereadsTheMixedGridAndGmshToFoamMakesAMeshOkCase) {
  TempDir dir;
  const SolverMesh s = patched_mixed_grid();
  const std::string file = dir.file("grid.msh");
  write_msh(s, file, "grid.msh");

  const testing::ToolRun gmsh =
      testing::run_tool("gmsh " + testing::shell_quote(file) + " -0 -o " + testing::shell_quote(dir.file("again.msh")));
  ASSERT_EQ(gmsh.exit_code, 0) << testing::describe_failure(gmsh, "gmsh", "gmsh");
  EXPECT_EQ(gmsh.output.find("Error"), std::string::npos) << gmsh.output;
  EXPECT_NE(gmsh.output.find(std::to_string(s.cells.points.size()) + " nodes"), std::string::npos) << gmsh.output;
  EXPECT_NE(gmsh.output.find(std::to_string(s.cells.n_cells() + s.n_boundary_faces()) + " elements"), std::string::npos)
      << gmsh.output;

  const std::string case_dir = dir.file("case");
  testing::write_openfoam_case_dicts(case_dir);
  const testing::ToolRun convert = testing::run_gmsh_to_foam(file, case_dir);
  ASSERT_EQ(convert.exit_code, 0) << testing::describe_failure(convert, "gmshToFoam", "openfoam");
  expect_check_mesh_ok(case_dir, s);
}

TEST(MshAndSu2Writers, MeshioReadsTheSameCellsByType) {
  TempDir dir;
  const SolverMesh s = patched_mixed_grid();
  write_msh(s, dir.file("grid.msh"), "grid.msh");
  write_su2(s, dir.file("grid.su2"), "grid.su2");
  std::size_t n_tri = 0;
  for (std::size_t f = s.faces.n_internal; f < s.faces.size(); ++f) n_tri += s.faces.n_nodes[f] == 3;
  for (const char* name : {"grid.msh", "grid.su2"}) {
    testing::ToolRun run;
    const std::map<std::string, long> n = testing::meshio_counts(dir.file(name), &run);
    ASSERT_EQ(run.exit_code, 0) << testing::describe_failure(run, "meshio", "python3-meshio");
    EXPECT_EQ(n.at("hexahedron"), long(s.n_cells_of(CellType::kHex))) << name;
    EXPECT_EQ(n.at("pyramid"), long(s.n_cells_of(CellType::kPyramid))) << name;
    EXPECT_EQ(n.at("wedge"), long(s.n_cells_of(CellType::kWedge))) << name;
    EXPECT_EQ(n.at("triangle"), long(n_tri)) << name;
    EXPECT_EQ(n.at("quad"), long(s.n_boundary_faces() - n_tri)) << name;
    EXPECT_EQ(n.at("points"), long(s.cells.points.size())) << name;
  }
}

TEST(Su2Writer, MarkersAreThePatchesWithTheirSizes) {
  TempDir dir;
  const SolverMesh s = patched_mixed_grid();
  write_su2(s, dir.file("grid.su2"), "grid.su2");
  const std::string text = read_text(dir.file("grid.su2"));
  EXPECT_NE(text.find("NMARK= 2\nMARKER_TAG= floor\nMARKER_ELEMS= 4\n"), std::string::npos);
  EXPECT_NE(text.find("MARKER_TAG= sides\nMARKER_ELEMS= " + std::to_string(s.n_boundary_faces() - 4) + "\n"),
            std::string::npos);
  EXPECT_NE(text.find("NELEM= " + std::to_string(s.cells.n_cells()) + "\n"), std::string::npos);
}

// /proc accepts no new files, not even from root, so writing there fails for real.
TEST(SolverWriters, AnUnwritableDirectoryIsAnIoErrorNamingTheTargetAndLeavesNothing) {
  const SolverMesh s = patched_mixed_grid();
  auto expect_io_error = [](const std::function<void()>& write, const std::string& target) {
    try {
      write();
      ADD_FAILURE() << "expected IoError for " << target;
    } catch (const IoError& e) {
      EXPECT_NE(std::string(e.what()).find(target), std::string::npos) << e.what();
    }
  };
  expect_io_error([&] { write_cgns(s, "/proc/blayer-test.cgns", "out.cgns"); }, "out.cgns");
  expect_io_error([&] { write_su2(s, "/proc/blayer-test.su2", "out.su2"); }, "out.su2");
  expect_io_error([&] { write_msh(s, "/proc/blayer-test.msh", "out.msh"); }, "out.msh");
  expect_io_error([&] { write_openfoam_polymesh(s, "/proc", "case/constant/polyMesh"); }, "case/constant/polyMesh");
  for (const char* p : {"/proc/blayer-test.cgns", "/proc/blayer-test.su2", "/proc/blayer-test.msh", "/proc/points"})
    EXPECT_FALSE(fs::exists(p)) << p;
}

}  // namespace
}  // namespace blayer
