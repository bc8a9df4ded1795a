// Regression cases: every folder cases/NNN_name/ with a case.toml and an expected.toml
// becomes the test Regression.NNN_name. A case runs as a user runs it:
//   1. `blayer extrude --config case.toml -o mesh.vtu --report report.json`, whose exit
//      status must be expected.toml's `exit_status` (default 0; blayer exits 0 only when
//      its own final exact check passed, so that check's zero counts are not figures);
//   2. `blayer check mesh.vtu --json check.json` re-reads the written file and checks it
//      again; it must exit 0 (this catches what writing and reading lose: node order,
//      precision, arrays), and its report is exposed under `check_cli.`;
//   3. the layer fidelity (quality/layer_fidelity.h) is measured here, independently of
//      blayer's report: mesh.vtu read back, the case's surface loaded by blayer_io as the
//      case's `side` orients it, the targets h1, T, N from case.toml's own numbers; its
//      figures are exposed under `fidelity.`;
//   4. every figure of expected.toml (format in expected_figures.h) is looked up by its
//      dotted path among report.json's keys, `check_cli.*` and `fidelity.*`, and judged;
//      a failure prints the figure, the accepted range and the actual value.
//
// Re-deriving the figures: scripts/update-golden.sh [case...] runs the cases with
// BLAYER_UPDATE_GOLDEN=1, under which each case writes expected.toml.new next to its
// expected.toml (never over it) with every value replaced by the measured one, keeping
// operators, tolerances and comments, and does not fail on figure differences; with
// BLAYER_MEASURED_DIR set it also writes every measured number there as NNN_name.json.
// A human diffs, checks each change against its reason, and renames. cases/README.md
// has more.
// An empty or unreadable cases/ folder fails loudly.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "case_measurements.h"
#include "expected_figures.h"

namespace {

namespace fs = std::filesystem;
using namespace blayer::cases;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool update_mode() {
  const char* v = std::getenv("BLAYER_UPDATE_GOLDEN");
  return v && std::string(v) == "1";
}

class CaseTest : public ::testing::Test {
 public:
  explicit CaseTest(fs::path dir) : dir_(std::move(dir)) {}

  void TestBody() override {
    int expected_status = 0;
    const std::vector<ExpectedFigure> figures =
        read_expected_figures((dir_ / "expected.toml").string(), &expected_status);
    ASSERT_FALSE(figures.empty()) << dir_ / "expected.toml" << " lists no figures";
    const fs::path work = fs::temp_directory_path() / ("blayer-case-" + dir_.filename().string() + "-" +
                                                       std::to_string(::getpid()));
    fs::remove_all(work);
    fs::create_directories(work);
    const std::string mesh = (work / "mesh.vtu").string();
    const int status = run_command(std::string(BLAYER_EXE) + " extrude --config '" + (dir_ / "case.toml").string() +
                                       "' -o '" + mesh + "' --report '" + (work / "report.json").string() + "'",
                                   (work / "stdout.txt").string(), (work / "stderr.txt").string());
    ASSERT_EQ(status, expected_status) << "blayer extrude exit status\nstdout:\n"
                                       << slurp(work / "stdout.txt") << "\nstderr:\n"
                                       << slurp(work / "stderr.txt");
    if (status != 0) {
      fs::remove_all(work);
      return;
    }
    nlohmann::json measured = nlohmann::json::parse(slurp(work / "report.json"));
    const int check_status = run_command(std::string(BLAYER_EXE) + " check '" + mesh + "' --json '" +
                                             (work / "check.json").string() + "'",
                                         (work / "check_stdout.txt").string(), (work / "check_stderr.txt").string());
    ASSERT_EQ(check_status, 0) << "blayer check of the written mesh\n"
                               << slurp(work / "check_stdout.txt") << slurp(work / "check_stderr.txt");
    measured["check_cli"] = nlohmann::json::parse(slurp(work / "check.json"));
    const CaseSettings settings = read_case_settings(dir_.string(), measured);
    measured["fidelity"] = measure_case_fidelity(mesh, settings);

    std::map<std::string, double> actual;
    flatten_numbers(measured, "", &actual);
    std::map<std::string, double> used;
    std::ostringstream table;
    for (const ExpectedFigure& f : figures) {
      const auto it = actual.find(f.name);
      if (it == actual.end()) {
        ADD_FAILURE() << f.name << ": no such number among the report, check_cli. and fidelity. keys";
        continue;
      }
      used[f.name] = it->second;
      std::string accepted;
      const bool ok = figure_passes(f, it->second, &accepted);
      table << (ok ? "  ok   " : "  FAIL ") << f.name << ": expected " << accepted << ", actual "
            << nlohmann::json(it->second).dump() << "\n";
      if (!update_mode()) {
        EXPECT_TRUE(ok) << f.name << ": expected " << accepted << ", actual " << it->second;
      }
    }
    std::printf("%s", table.str().c_str());
    if (update_mode()) {
      const fs::path out = dir_ / "expected.toml.new";
      std::ofstream(out) << rewrite_with_measured(slurp(dir_ / "expected.toml"), used);
      std::printf("wrote %s\n", out.c_str());
      if (const char* keep = std::getenv("BLAYER_MEASURED_DIR")) {
        const fs::path all = fs::path(keep) / (dir_.filename().string() + ".json");
        std::ofstream(all) << measured.dump(2) << "\n";
        std::printf("wrote %s (every measured number, to choose figures from)\n", all.c_str());
      }
    }
    if (!HasFailure()) fs::remove_all(work);
  }

 private:
  fs::path dir_;
};

// Registers one test per case folder; an empty or unreadable cases/ fails loudly.
void register_cases() {
  const fs::path root(BLAYER_CASES_DIR);
  std::vector<fs::path> dirs;
  std::error_code ec;
  for (auto it = fs::directory_iterator(root, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
    if (it->is_directory() && fs::exists(it->path() / "case.toml")) dirs.push_back(it->path());
  std::sort(dirs.begin(), dirs.end());
  if (dirs.empty()) {
    ::testing::RegisterTest("Regression", "CasesFolderHasCases", nullptr, nullptr, __FILE__, __LINE__,
                            [root]() -> ::testing::Test* {
                              struct Fail : ::testing::Test {
                                fs::path r;
                                void TestBody() override { FAIL() << "no cases found in " << r; }
                              };
                              auto* f = new Fail;
                              f->r = root;
                              return f;
                            });
    return;
  }
  for (const fs::path& d : dirs) {
    ::testing::RegisterTest("Regression", d.filename().string().c_str(), nullptr, nullptr, __FILE__, __LINE__,
                            [d]() -> ::testing::Test* { return new CaseTest(d); });
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  register_cases();
  return RUN_ALL_TESTS();
}
