// The run says plainly when the layer is thinner than asked: a warning line with the
// shares per reason, the report's verdict, and --require-thickness as an exit status.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "../io/temp_dir.h"
#include "run_cli.h"

namespace blayer {
namespace {

using testing::run_blayer;
using testing::slurp;
using testing::TempDir;

// The thin-slot case: its slot is narrower than twice the requested thickness, so a
// quarter of the columns cannot reach 0.9 T (cases/006_thin_slot/README.md).
const std::string kSlotCase = std::string(BLAYER_CASES_DIR) + "/006_thin_slot/case.toml";
const std::string kSphereCase = std::string(BLAYER_CASES_DIR) + "/002_sphere/case.toml";

TEST(ThicknessVerdict, ALimitedLayerIsNamedWithItsReasons) {
  TempDir dir;
  const std::string mesh = dir.file("slot.vtu"), report = dir.file("slot.json");
  const auto r = run_blayer("extrude --config " + kSlotCase + " -o " + mesh + " --report " + report, dir.file(""));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("warning: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("got less than 90 % of the thickness"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wall_gap"), std::string::npos) << r.out;
  const nlohmann::json j = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(j["verdict"]["outcome"], "limited");
  const double thin = j["verdict"]["thin_columns"].get<double>();
  EXPECT_GT(thin, 0.1);
  EXPECT_LT(thin, 0.5);
  EXPECT_GT(j["verdict"]["thin_columns_by_reason"]["wall_gap"].get<double>(), 0.0);
  // The check's full summaries, which a run without --report leaves out: the metrics'
  // percentiles and one entry per layer (the case asks for 10).
  EXPECT_TRUE(j["check"]["metrics"]["min_corner_jacobian"]["p50"].is_number()) << j["check"].dump();
  EXPECT_EQ(j["check"]["layers"].size(), 10u);
}

TEST(ThicknessVerdict, RequireThicknessExitsThreeAndStillWritesTheMesh) {
  TempDir dir;
  const std::string mesh = dir.file("slot.vtu");
  const auto r = run_blayer("extrude --config " + kSlotCase + " -o " + mesh + " --require-thickness 0.95", dir.file(""));
  EXPECT_EQ(r.status, 3) << r.out << r.err;
  EXPECT_NE(r.out.find("--require-thickness"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(mesh));
  // A share the slot reaches passes.
  const auto ok = run_blayer("extrude --config " + kSlotCase + " -o " + mesh + " --require-thickness 0.5", dir.file(""));
  EXPECT_EQ(ok.status, 0) << ok.out << ok.err;
}

TEST(ThicknessVerdict, ACompleteLayerHasNoWarning) {
  TempDir dir;
  const std::string mesh = dir.file("sphere.vtu"), report = dir.file("sphere.json");
  const auto r = run_blayer("extrude --config " + kSphereCase + " -o " + mesh + " --report " + report +
                                " --require-thickness 1",
                            dir.file(""));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("warning: "), std::string::npos) << r.out;
  EXPECT_EQ(nlohmann::json::parse(slurp(report))["verdict"]["outcome"], "complete");
}

}  // namespace
}  // namespace blayer
