// The solver-acceptance limits end to end: the cone-tip case, whose layers checkMesh
// rejects without them (side quads at the base rim skewed above 4), written as an
// OpenFOAM polyMesh by `blayer extrude` with the default options and judged by checkMesh.
#include <gtest/gtest.h>

#include <string>

#include "../io/solver_tools.h"
#include "../io/temp_dir.h"
#include "run_cli.h"

namespace blayer {
namespace {

using testing::ToolRun;

// Extrudes the cone-tip case into DIR/case with the extra options, runs checkMesh on it.
ToolRun extrude_cone_and_check(const std::string& extra, const testing::TempDir& dir) {
  const std::string config = std::string(BLAYER_CASES_DIR) + "/007_cone_tip/case.toml";
  const std::string case_dir = dir.file("case");
  const testing::CliRun r = testing::run_blayer("extrude --config " + testing::shell_quote(config) + " " + extra +
                                                    " -o " + testing::shell_quote(case_dir + "/constant/polyMesh"),
                                                dir.file(""));
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  return testing::run_check_mesh(case_dir);
}

void expect_mesh_ok(const ToolRun& run) {
  ASSERT_EQ(run.exit_code, 0) << testing::describe_failure(run, "checkMesh", "openfoam");
  EXPECT_NE(run.output.find("Mesh OK."), std::string::npos) << run.output;
  EXPECT_LE(testing::check_mesh_max(run.output, "skewness"), 4.0);
  EXPECT_LT(testing::check_mesh_max(run.output, "non-orthogonality"), 90.0);
}

TEST(SolverAcceptanceExport, ConeTipLayersAreMeshOkWithTheDefaultLimits) {
  testing::TempDir dir;
  expect_mesh_ok(extrude_cone_and_check("", dir));
}

TEST(SolverAcceptanceExport, ConeTipHybridIsMeshOkWithTheDefaultLimits) {
  testing::TempDir dir;
  expect_mesh_ok(extrude_cone_and_check("--fill", dir));
}

TEST(SolverAcceptanceExport, ConeTipLayersFailCheckMeshWithoutTheLimits) {
  // The control: the same case on single columns with every limit off is the mesh
  // checkMesh rejects (the limits apply to single columns only).
  testing::TempDir dir;
  const ToolRun run = extrude_cone_and_check(
      "--fan-angle 0 --max-non-orthogonality 0 --max-skewness 0 --max-boundary-skewness 0 --face-pyramids-check=false", dir);
  ASSERT_NE(run.output.find("Checking geometry"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("Mesh OK."), std::string::npos) << run.output;
  EXPECT_GT(testing::check_mesh_max(run.output, "skewness"), 4.0);
}

}  // namespace
}  // namespace blayer
