// The solver-acceptance measures against OpenFOAM's own: small meshes with distorted
// cells are written as polyMesh and judged by checkMesh -allGeometry; its maxima,
// minima and error counts must be what the measures give on every face of the mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "../io/grid_meshes.h"
#include "../io/solver_tools.h"
#include "../io/temp_dir.h"
#include "blayer/io/mesh_faces.h"
#include "blayer/io/openfoam_writer.h"
#include "blayer/io/solver_mesh.h"
#include "blayer/quality/cell_validity.h"
#include "blayer/quality/solver_acceptance.h"
#include "lcg.h"

namespace blayer {
namespace {

using testing::GridCell;

// What checkMesh reports (on the mesh as a whole), computed here face by face.
struct Figures {
  double max_skewness = 0.0;
  double max_non_orthogonality = 0.0;
  double min_flatness = 1.0;
  long n_skew = 0;           // faces over checkMesh's skewness limit 4
  long n_severe = 0;         // internal faces over 70 degrees, below 90
  long n_non_orth_errors = 0; // internal faces at 90 degrees or more
  long n_pyramid_errors = 0; // per face and side, as checkMesh counts them
  long n_face_tet_errors = 0;
};

PolyFace face_points(const VolumeMesh& m, const MeshFaces& faces, std::size_t f) {
  PolyFace p;
  p.n = faces.n_nodes[f];
  for (int k = 0; k < p.n; ++k) p.p[k] = m.points[faces.nodes[f][k]];
  return p;
}

std::vector<Vec3> cell_centres(const VolumeMesh& m) {
  std::vector<Vec3> c(m.n_cells());
  for (std::size_t i = 0; i < m.n_cells(); ++i) {
    Vec3 corners[8];
    for (int k = 0; k < corner_count(m.cell_types[i]); ++k) corners[k] = m.points[m.connectivity[m.offsets[i] + k]];
    PolyFace f[6];
    FaceGeometry g[6];
    const int n = cell_poly_faces(m.cell_types[i], corners, f);
    for (int k = 0; k < n; ++k) g[k] = face_geometry(f[k]);
    c[i] = cell_geometry(g, n).centre;
  }
  return c;
}

Figures measure(const VolumeMesh& m) {
  const MeshFaces faces = build_mesh_faces(m);
  const std::vector<Vec3> centre = cell_centres(m);
  Figures fig;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const PolyFace p = face_points(m, faces, f);
    const FaceGeometry g = face_geometry(p);
    const Vec3& own = centre[faces.owner[f]];
    const bool internal = faces.neighbour[f] >= 0;
    const Vec3& nei = internal ? centre[faces.neighbour[f]] : own;
    const double skew = internal ? face_skewness(p, g, own, nei) : boundary_face_skewness(p, g, own);
    fig.max_skewness = std::max(fig.max_skewness, skew);
    fig.n_skew += skew > 4.0;
    fig.min_flatness = std::min(fig.min_flatness, face_flatness(p, g));
    fig.n_pyramid_errors += !(face_pyramid_volume(g, own) > 0.0);
    if (internal) {
      const double non_orth = face_non_orthogonality_deg(g, own, nei);
      fig.max_non_orthogonality = std::max(fig.max_non_orthogonality, non_orth);
      // checkMesh's error is a cosine below SMALL = 1e-15.
      const bool error = !(dot(nei - own, g.area) / (norm(nei - own) * norm(g.area)) > 1e-15);
      fig.n_severe += non_orth > 70.0 && !error;
      fig.n_non_orth_errors += error;
      fig.n_pyramid_errors += !(-face_pyramid_volume(g, nei) > 0.0);
    }
    // checkMesh's threshold for the face tets is OpenFOAM's minTetQuality, 1e-30; it
    // counts the owner's face-centre fan, the neighbour's and the base point apart.
    constexpr double kTol = 1e-30;
    fig.n_face_tet_errors += !(face_centre_tet_quality(p, g, own) > kTol);
    if (internal) fig.n_face_tet_errors += !(face_centre_tet_quality(reversed(p), g, nei) > kTol);
    fig.n_face_tet_errors += !(face_tet_quality(p, own, internal ? &nei : nullptr) > kTol);
  }
  return fig;
}

double figure_after(const std::string& out, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(out, m, std::regex(pattern + "\\s*(-?[0-9.e+-]+)")) ? std::stod(m[1]) : -1.0;
}

long count_after(const std::string& out, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(out, m, std::regex(pattern + "\\s*([0-9]+)")) ? std::stol(m[1]) : 0;
}

Figures check_mesh_figures(const VolumeMesh& m, const testing::TempDir& dir) {
  const std::string case_dir = dir.file("case");
  std::filesystem::create_directories(case_dir + "/constant/polyMesh");
  std::filesystem::create_directories(case_dir + "/system");
  write_openfoam_polymesh(make_solver_mesh(m, {}, "rest"), case_dir + "/constant/polyMesh", case_dir);
  write_openfoam_system(case_dir + "/system", case_dir);
  const testing::ToolRun run = testing::run_tool(std::string(testing::kOpenFoamEnv) +
                                                 "checkMesh -allGeometry -case " + testing::shell_quote(case_dir));
  EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 1) << testing::describe_failure(run, "checkMesh", "openfoam");
  const std::string& out = run.output;
  Figures f;
  f.max_skewness = figure_after(out, "Max skewness =");
  f.max_non_orthogonality = figure_after(out, "non-orthogonality Max:");
  if (f.max_non_orthogonality < 0.0 && count_after(out, "internal faces:") == 0) f.max_non_orthogonality = 0.0;
  f.min_flatness = figure_after(out, "Face flatness \\(1 = flat, 0 = butterfly\\) : min =");
  if (f.min_flatness < 0.0 && out.find("All face flatness OK.") != std::string::npos) f.min_flatness = 1.0;
  f.n_skew = count_after(out, "Max skewness = [0-9.e+-]+,");
  f.n_severe = count_after(out, "Number of severely non-orthogonal \\(> 70 degrees\\) faces:");
  f.n_non_orth_errors = count_after(out, "Number of non-orthogonality errors:");
  f.n_pyramid_errors = count_after(out, "Error in face pyramids:");
  f.n_face_tet_errors = count_after(out, "Error in face tets:");
  EXPECT_GE(f.max_skewness, 0.0) << out;
  EXPECT_GE(f.max_non_orthogonality, 0.0) << out;
  EXPECT_GE(f.min_flatness, 0.0) << out;
  return f;
}

// checkMesh prints six significant digits.
void expect_same(const Figures& ours, const Figures& foam) {
  EXPECT_NEAR(ours.max_skewness, foam.max_skewness, 1e-5 * foam.max_skewness + 1e-6);
  EXPECT_NEAR(ours.max_non_orthogonality, foam.max_non_orthogonality, 1e-5 * foam.max_non_orthogonality + 1e-6);
  EXPECT_NEAR(ours.min_flatness, foam.min_flatness, 1e-5);
  EXPECT_EQ(ours.n_skew, foam.n_skew);
  EXPECT_EQ(ours.n_severe, foam.n_severe);
  EXPECT_EQ(ours.n_non_orth_errors, foam.n_non_orth_errors);
  EXPECT_EQ(ours.n_pyramid_errors, foam.n_pyramid_errors);
  EXPECT_EQ(ours.n_face_tet_errors, foam.n_face_tet_errors);
}

// The grid with every point moved by up to `dx` in x and y and `dz` in z, the layer of
// points z = k shifted sideways by shift x (0, 1, -1, 0, 1, ...)[k] (sheared layers
// leaning back and forth), then scaled by (1, 1, z_scale) (thin layers). Seeds are
// tried in turn until every cell passes the exact test.
VolumeMesh distorted(VolumeMesh m, double dx, double dz, double shift, double z_scale, std::uint64_t seed) {
  const std::vector<Vec3> original = m.points;
  for (int attempt = 0; attempt < 1000; ++attempt, ++seed) {
    testing::Lcg rng(seed);
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      const Vec3& p = original[i];
      static const double kLean[3] = {0.0, 1.0, -1.0};
      const double zig = shift * kLean[std::lround(p[2]) % 3];
      m.points[i] = {p[0] + zig + dx * (2 * rng.uniform() - 1), p[1] + dx * (2 * rng.uniform() - 1),
                     z_scale * (p[2] + dz * (2 * rng.uniform() - 1))};
    }
    bool valid = true;
    for (std::size_t c = 0; c < m.n_cells() && valid; ++c) {
      Vec3 corners[8];
      for (int k = 0; k < corner_count(m.cell_types[c]); ++k) corners[k] = m.points[m.connectivity[m.offsets[c] + k]];
      valid = cell_validity(m.cell_types[c], corners) == Validity::kValid;
    }
    if (valid) return m;
  }
  ADD_FAILURE() << "no valid distortion found";
  return m;
}

TEST(SolverAcceptanceAgainstCheckMesh, DistortedWedgeGridHasCheckMeshsFigures) {
  testing::TempDir dir;
  const VolumeMesh m = distorted(testing::grid_mesh(4, 4, 3, GridCell::kWedges), 0.2, 0.2, 0.0, 1.0, 1);
  expect_same(measure(m), check_mesh_figures(m, dir));
}

TEST(SolverAcceptanceAgainstCheckMesh, ThinSkewedWedgeLayersHaveCheckMeshsFiguresAndErrors) {
  // Layers 20 times thinner than wide, sheared by up to 6 cells back and forth, with
  // the points moved by up to 0.15: skewness far above 4, non-orthogonality above 70
  // degrees, warped quads.
  testing::TempDir dir;
  const VolumeMesh m = distorted(testing::grid_mesh(5, 5, 4, GridCell::kWedges), 0.02, 0.02, 4.0, 0.05, 7);
  const Figures ours = measure(m);
  EXPECT_GT(ours.n_skew, 0);
  EXPECT_GT(ours.n_severe, 0);
  expect_same(ours, check_mesh_figures(m, dir));
}

TEST(SolverAcceptanceAgainstCheckMesh, DistortedMixedGridHasCheckMeshsFigures) {
  // Wedges, hexes and pyramids (with their apex points inside the cubes).
  testing::TempDir dir;
  const VolumeMesh m = distorted(testing::mixed_grid_mesh(3, 3, 4), 0.15, 0.15, 0.3, 1.0, 3);
  expect_same(measure(m), check_mesh_figures(m, dir));
}

TEST(SolverAcceptanceAgainstCheckMesh, DistortedTetGridHasCheckMeshsFigures) {
  testing::TempDir dir;
  const VolumeMesh m = distorted(testing::grid_mesh(3, 3, 3, GridCell::kTets), 0.1, 0.1, 0.2, 0.2, 5);
  expect_same(measure(m), check_mesh_figures(m, dir));
}

TEST(SolverAcceptanceAgainstCheckMesh, TallShearedPrismAloneHasCheckMeshsBoundarySkewness) {
  // Height 10, top moved by 20: the caps' skewness is normalised by 0.4 x the centre's
  // distance h/2 to them (2, more than the caps' own extent 2/3): (s/2) / 2 = 5.
  testing::TempDir dir;
  VolumeMesh m;
  m.points = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {20, 0, 10}, {20, 1, 10}, {21, 0, 10}};
  const std::int64_t wedge[6] = {0, 1, 2, 3, 4, 5};
  m.add_cell(CellType::kWedge, wedge);
  const Figures ours = measure(m);
  EXPECT_NEAR(ours.max_skewness, 5.0, 1e-12);
  expect_same(ours, check_mesh_figures(m, dir));
}

}  // namespace
}  // namespace blayer
