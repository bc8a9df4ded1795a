#include "expected_figures.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace blayer::cases {
namespace {

namespace fs = std::filesystem;

std::string write_temp(const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("expected-figures-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(p) << text;
  return p.string();
}

ExpectedFigure figure(const std::string& op, double value, double tol) {
  ExpectedFigure f;
  f.name = "x";
  f.op = op;
  f.value = value;
  f.tolerance = tol;
  f.has_tolerance = tol > 0;
  return f;
}

TEST(ExpectedFigures, ReadsOperatorsValuesTolerancesAndExitStatus) {
  const std::string path = write_temp(
      "exit_status = 2\n"
      "\"check.cells.wedge\" = [\"==\", 6920]  # 1,384 x 5\n"
      "\"volume.layers\" = [\"~=\", 1.0025, 1e-6]\n"
      "\"min_visibility\" = [\">=\", 0.17, 0.05]\n");
  int status = 0;
  const auto f = read_expected_figures(path, &status);
  EXPECT_EQ(status, 2);
  ASSERT_EQ(f.size(), 3u);
  std::remove(path.c_str());
}

TEST(ExpectedFigures, RejectsMalformedEntriesNamingTheFigure) {
  for (const char* bad : {"\"a\" = [\"~=\", 1.0]\n", "\"a\" = [\"=<\", 1.0]\n", "\"a\" = [\"==\", 1, 0.1]\n",
                          "\"a\" = [\">=\", \"one\"]\n", "\"a\" = 3\n"}) {
    const std::string path = write_temp(bad);
    int status = 0;
    try {
      read_expected_figures(path, &status);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("figure a"), std::string::npos) << e.what();
    }
    std::remove(path.c_str());
  }
}

TEST(ExpectedFigures, BoundsAndNearnessUseTheRelativeToleranceOnOneOrBothSides) {
  std::string accepted;
  EXPECT_TRUE(figure_passes(figure("~=", 100.0, 0.01), 100.99, &accepted));
  EXPECT_FALSE(figure_passes(figure("~=", 100.0, 0.01), 101.01, &accepted));
  EXPECT_FALSE(figure_passes(figure("~=", 100.0, 0.01), 98.99, &accepted));
  EXPECT_TRUE(figure_passes(figure(">=", 100.0, 0.05), 95.5, &accepted));
  EXPECT_TRUE(figure_passes(figure(">=", 100.0, 0.05), 1e9, &accepted));
  EXPECT_FALSE(figure_passes(figure(">=", 100.0, 0.05), 94.9, &accepted));
  EXPECT_TRUE(figure_passes(figure("<=", 10.0, 0.0), 10.0, &accepted));
  EXPECT_FALSE(figure_passes(figure("<=", 10.0, 0.0), 10.000001, &accepted));
  EXPECT_TRUE(figure_passes(figure("==", 6920, 0.0), 6920, &accepted));
  EXPECT_FALSE(figure_passes(figure("==", 6920, 0.0), 6921, &accepted));
  EXPECT_FALSE(figure_passes(figure("~=", 1.0, 0.5), std::nan(""), &accepted));
}

TEST(ExpectedFigures, RewriteFillsInMeasuredValuesAndKeepsEverythingElse) {
  const std::string text =
      "# header comment\n"
      "\"check.cells.wedge\" = [\"==\", 6920]  # 1,384 x 5\n"
      "\"volume.layers\" = [\"~=\", 1.0025, 1e-6]  # measured; 1e-6: reason\n"
      "\"min_visibility\" = [\">=\", 0.17, 0.05]\n"
      "\"untouched\" = [\"<=\", 3]\n";
  const std::string out = rewrite_with_measured(
      text, {{"check.cells.wedge", 6921}, {"volume.layers", 1.00256789012345}, {"min_visibility", 0.25}});
  EXPECT_EQ(out,
            "# header comment\n"
            "\"check.cells.wedge\" = [\"==\", 6921]  # 1,384 x 5\n"
            "\"volume.layers\" = [\"~=\", 1.00256789, 1e-6]  # measured; 1e-6: reason\n"
            "\"min_visibility\" = [\">=\", 0.25, 0.05]\n"
            "\"untouched\" = [\"<=\", 3]\n");
}

TEST(ExpectedFigures, RewriteKeepsClosedFormAndDerivedValues) {
  const std::string text =
      "\"check.cells.wedge\" = [\"==\", 6920]  # derived: 1,384 x 5\n"
      "\"volume.layers\" = [\"~=\", 0.5811298613, 1e-12]  # closed form (1 + 2T)^3 - 1\n"
      "\"coverage\" = [\"~=\", 0.86, 1e-9]  # measured\n";
  const std::string out =
      rewrite_with_measured(text, {{"check.cells.wedge", 6921}, {"volume.layers", 0.6}, {"coverage", 0.87}});
  EXPECT_EQ(out,
            "\"check.cells.wedge\" = [\"==\", 6920]  # derived: 1,384 x 5\n"
            "\"volume.layers\" = [\"~=\", 0.5811298613, 1e-12]  # closed form (1 + 2T)^3 - 1\n"
            "\"coverage\" = [\"~=\", 0.87, 1e-9]  # measured\n");
}

TEST(ExpectedFigures, RewrittenValuesPassTheirOwnFigures) {
  // The printed digits must be enough for the tolerance: a figure refilled with its
  // measured value passes against that same measurement.
  const double measured = 3.3500000000000002e-4 * (1 + 3e-13);
  const std::string out = rewrite_with_measured("\"a\" = [\"~=\", 1, 1e-12]\n", {{"a", measured}});
  const std::string path = write_temp(out);
  int status = 0;
  const auto f = read_expected_figures(path, &status);
  std::string accepted;
  ASSERT_EQ(f.size(), 1u);
  EXPECT_TRUE(figure_passes(f[0], measured, &accepted)) << out;
  std::remove(path.c_str());
}

}  // namespace
}  // namespace blayer::cases
