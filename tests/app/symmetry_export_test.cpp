// A half model through the whole pipeline: found symmetry plane, layers, the fill of
// the half domain, the symmetry patch in the solver formats, and the plane tiled
// exactly by the symmetry faces and the body's cut.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "../io/solver_tools.h"
#include "../io/temp_dir.h"
#include "analytic_surfaces.h"
#include "blayer/io/mesh_faces.h"
#include "blayer/io/vtk_io.h"
#include "run_cli.h"

namespace blayer {
namespace {

using testing::run_blayer;
using testing::TempDir;

std::string off_text(const TriSurface& s) {
  std::ostringstream os;
  os.precision(17);
  os << "OFF\n" << s.points.size() << " " << s.triangles.size() << " 0\n";
  for (const Vec3& p : s.points) os << p[0] << " " << p[1] << " " << p[2] << "\n";
  for (const Triangle& t : s.triangles) os << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return os.str();
}

// The upper half of a latitude-longitude sphere as OFF text: open along z = 0.
std::string half_sphere_off() {
  return off_text(test_surfaces::cut_at_coordinate_plane(test_surfaces::uv_sphere(10, 20, 1.0, 0.0), 2));
}

// The cell count of blayer extrude's "check: N cells" line.
long cells_written(const std::string& out) {
  const std::size_t at = out.find("\ncheck: ");
  return at == std::string::npos ? -1 : std::stol(out.substr(at + 8));
}

// Area of a planar polygon face in the plane z = 0.
double area_in_z0(const VolumeMesh& m, const std::array<std::int64_t, 4>& nodes, int n) {
  double a = 0.0;
  for (int k = 0; k < n; ++k) {
    const Vec3& p = m.points[nodes[k]];
    const Vec3& q = m.points[nodes[(k + 1) % n]];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * std::fabs(a);
}

TEST(SymmetryExport, HalfSphereHybridTilesThePlaneAndPassesCheckMesh) {
  TempDir dir;
  const std::string surface = dir.write("half.off", half_sphere_off());
  const std::string vtu = dir.file("half.vtu");
  const auto r = run_blayer("extrude " + surface + " --layers 3 --first-height 0.01 --growth-ratio 1.2 --fill "
                            "--farfield-scale 4 -o " + vtu + " --boundary " + dir.file("b.vtp"),
                            dir.file(""));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("symmetry plane z = 0 (found)"), std::string::npos) << r.out;

  // Boundary faces in the plane: the layers' side faces over the cut and the fill's
  // plane facet. With the body's cut (the disk inside the wall's equator polygon) they
  // tile the half box's face on the plane.
  const VolumeMesh m = read_volume_mesh(vtu).mesh;
  const MeshFaces faces = build_mesh_faces(m);
  double symmetry_area = 0.0, lo_x = HUGE_VAL, hi_x = -HUGE_VAL, lo_y = HUGE_VAL, hi_y = -HUGE_VAL;
  int n_quads = 0;
  for (std::size_t f = faces.n_internal; f < faces.size(); ++f) {
    bool in_plane = true;
    for (int k = 0; k < faces.n_nodes[f]; ++k) in_plane = in_plane && m.points[faces.nodes[f][k]][2] == 0.0;
    if (!in_plane) continue;
    symmetry_area += area_in_z0(m, faces.nodes[f], faces.n_nodes[f]);
    n_quads += faces.n_nodes[f] == 4;
    for (int k = 0; k < faces.n_nodes[f]; ++k) {
      const Vec3& p = m.points[faces.nodes[f][k]];
      lo_x = std::min(lo_x, p[0]);
      hi_x = std::max(hi_x, p[0]);
      lo_y = std::min(lo_y, p[1]);
      hi_y = std::max(hi_y, p[1]);
    }
  }
  EXPECT_EQ(n_quads, 20 * 3) << "the layers' side quads over the 20 cut edges, 3 layers";
  // The cut: the regular 20-gon of radius 1 (the wall's equator).
  const double cut = 0.5 * 20 * std::sin(2 * M_PI / 20);
  const double box = (hi_x - lo_x) * (hi_y - lo_y);
  EXPECT_NEAR(symmetry_area + cut, box, 1e-9 * box);

  // The boundary file's marker-3 triangles are those faces: the facet's and the layers'
  // side quads as two halves each.
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(dir.file("b.vtp").c_str());
  reader->Update();
  vtkPolyData* b = reader->GetOutput();
  vtkDataArray* marker = b->GetCellData()->GetArray("marker");
  ASSERT_NE(marker, nullptr);
  double marked_area = 0.0;
  for (vtkIdType c = 0; c < b->GetNumberOfCells(); ++c) {
    if (marker->GetTuple1(c) != 3.0) continue;
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    b->GetCellPoints(c, n, ids);
    ASSERT_EQ(n, 3);
    double p[3][3];
    for (int k = 0; k < 3; ++k) b->GetPoint(ids[k], p[k]);
    ASSERT_TRUE(p[0][2] == 0.0 && p[1][2] == 0.0 && p[2][2] == 0.0) << "marker-3 triangle " << c << " off the plane";
    marked_area += 0.5 * std::fabs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]));
  }
  EXPECT_NEAR(marked_area + cut, box, 1e-9 * box);

  // The solver formats carry the symmetry patch; checkMesh accepts the mesh.
  const std::string case_dir = dir.file("case");
  const auto o = run_blayer("extrude " + surface + " --layers 3 --first-height 0.01 --growth-ratio 1.2 --fill "
                            "--farfield-scale 4 -o " + case_dir + "/constant/polyMesh",
                            dir.file(""));
  ASSERT_EQ(o.status, 0) << o.out << o.err;
  std::ifstream boundary(case_dir + "/constant/polyMesh/boundary");
  std::stringstream text;
  text << boundary.rdbuf();
  EXPECT_NE(text.str().find("symmetry"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("symmetryPlane"), std::string::npos) << text.str();
  const testing::ToolRun run = testing::run_check_mesh(case_dir);
  ASSERT_EQ(run.exit_code, 0) << testing::describe_failure(run, "checkMesh", "openfoam");
  EXPECT_NE(run.output.find("Mesh OK."), std::string::npos) << run.output;
  EXPECT_GT(testing::check_mesh_patches(run.output)["symmetry"], 0);
}

// The half model is meshed for half the cost of the full one: its fill must not be
// denser along the plane than the mirrored model's, where no boundary lies (the plane
// facet is sized for that, src/half_domain.h). Measured with the CLI: 0.41 to 0.43 at
// farfield scales 4, 4.001 and 3.999; with the facet sized by the plain field, 0.54.
// TetGen's count moves by a few per cent with any change of its input, hence the bounds
// rather than a figure.
TEST(SymmetryExport, AHalfSpheresFillHasAboutHalfTheCellsOfTheFullSpheres) {
  TempDir dir;
  const std::string half = dir.write("half.off", half_sphere_off());
  const std::string full = dir.write("full.off", off_text(test_surfaces::uv_sphere(10, 20, 1.0, 0.0)));
  const std::string law = " --layers 3 --first-height 0.02 --growth-ratio 1.2 --fill --farfield-scale 4 -o ";
  const auto h = run_blayer("extrude " + half + law + dir.file("half.vtu"), dir.file(""));
  const auto f = run_blayer("extrude " + full + law + dir.file("full.vtu"), dir.file(""));
  ASSERT_EQ(h.status, 0) << h.out << h.err;
  ASSERT_EQ(f.status, 0) << f.out << f.err;
  const double ratio = double(cells_written(h.out)) / double(cells_written(f.out));
  EXPECT_LE(ratio, 0.51) << h.out << f.out;
  EXPECT_GE(ratio, 0.35) << h.out << f.out;
}

}  // namespace
}  // namespace blayer
