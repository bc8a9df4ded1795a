// `blayer check` on meshes with twisted and inverted cells: both fail (exit status 2),
// and the report counts them apart, as VTK, Gmsh and ParaView count inversion.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "../io/temp_dir.h"
#include "blayer/io/vtk_io.h"
#include "run_cli.h"
#include "separate_wedges.h"

namespace blayer {
namespace {

using testing::run_blayer;
using testing::slurp;
using testing::TempDir;

// Three wedges over the unit equilateral triangle: a right one, one with its top cap
// turned half round the column (every corner positive, the quads folded) and a mirrored
// one (negative corner Jacobians).
VolumeMesh three_wedges() {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0.5, std::sqrt(3.0) / 2, 0};
  const Vec3 centre = (a + b + c) / 3.0, up{0, 0, 1};
  auto half_turn = [&](const Vec3& p) { return 2.0 * centre - p + up; };
  const std::vector<std::vector<Vec3>> cells = {
      {a, c, b, a + up, c + up, b + up},
      {a, c, b, half_turn(a), half_turn(c), half_turn(b)},
      {a, c, b, a - up, c - up, b - up}};
  return test::separate_wedges(cells);
}

TEST(CheckCommand, CountsTwistedAndInvertedCellsApartAndFailsOnBoth) {
  TempDir dir;
  write_vtu(three_wedges(), dir.file("m.vtu"));
  const auto r = run_blayer("check " + dir.file("m.vtu") + " --json " + dir.file("r.json"), dir.file(""));
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.out.find("inverted: 1  twisted: 1  flat: 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("INVALID: 1 inverted, 1 twisted, 0 flat, 0 non-conforming cells"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(slurp(dir.file("r.json")));
  EXPECT_EQ(j["inverted"], 1);
  EXPECT_EQ(j["twisted"], 1);
  EXPECT_EQ(j["ok"], false);
}

}  // namespace
}  // namespace blayer
