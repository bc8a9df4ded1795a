// Regression cases: every folder cases/NNN_name/ with a case.toml and an expected.toml
// becomes the test Regression.NNN_name. The case runs through the blayer executable
// exactly as a user would run it (`blayer extrude --config case.toml`), with a JSON
// report, and every figure of expected.toml is compared with the report.
//
// expected.toml: one key per figure, the key a dotted path into the report JSON
// (e.g. "check.inverted", "achieved.total_thickness.min"), the value
// [op, number] or ["~=", number, relative_tolerance], op one of == <= >= ~=.
// An optional `exit_status` (default 0) is the expected exit status of blayer.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <toml++/toml.h>

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const nlohmann::json* find_path(const nlohmann::json& j, const std::string& path) {
  const nlohmann::json* cur = &j;
  std::stringstream ss(path);
  std::string part;
  while (std::getline(ss, part, '.')) {
    if (!cur->is_object() || !cur->contains(part)) return nullptr;
    cur = &(*cur)[part];
  }
  return cur;
}

class CaseTest : public ::testing::Test {
 public:
  explicit CaseTest(fs::path dir) : dir_(std::move(dir)) {}

  void TestBody() override {
    const toml::table expected = toml::parse_file((dir_ / "expected.toml").string());
    const fs::path work = fs::temp_directory_path() / ("blayer-case-" + dir_.filename().string() + "-" +
                                                       std::to_string(::getpid()));
    fs::remove_all(work);
    fs::create_directories(work);
    const std::string cmd = std::string(BLAYER_EXE) + " extrude --config " + (dir_ / "case.toml").string() +
                            " -o " + (work / "mesh.vtu").string() + " --report " + (work / "report.json").string() +
                            " > " + (work / "stdout.txt").string() + " 2> " + (work / "stderr.txt").string();
    const int raw = std::system(cmd.c_str());
    const int status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    const int expected_status = expected["exit_status"].value_or(0);
    ASSERT_EQ(status, expected_status) << "blayer exit status\nstdout:\n"
                                       << slurp(work / "stdout.txt") << "\nstderr:\n"
                                       << slurp(work / "stderr.txt");
    if (status != 0) {
      fs::remove_all(work);
      return;
    }
    const nlohmann::json report = nlohmann::json::parse(slurp(work / "report.json"));
    int n_figures = 0;
    for (const auto& [key, node] : expected) {
      const std::string name(key.str());
      if (name == "exit_status") continue;
      const toml::array* spec = node.as_array();
      ASSERT_TRUE(spec && spec->size() >= 2) << name << ": expected [op, value(, tolerance)]";
      const std::string op = spec->get(0)->value_or(std::string());
      const double want = spec->get(1)->value_or(std::nan(""));
      const nlohmann::json* got_node = find_path(report, name);
      ASSERT_TRUE(got_node && got_node->is_number()) << name << ": not a number in the report";
      const double got = got_node->get<double>();
      ++n_figures;
      if (op == "==") {
        EXPECT_EQ(got, want) << name << ": expected == " << want << ", actual " << got;
      } else if (op == "<=") {
        EXPECT_LE(got, want) << name << ": expected <= " << want << ", actual " << got;
      } else if (op == ">=") {
        EXPECT_GE(got, want) << name << ": expected >= " << want << ", actual " << got;
      } else if (op == "~=") {
        ASSERT_EQ(spec->size(), 3u) << name << ": ~= needs a relative tolerance";
        const double rel = spec->get(2)->value_or(0.0);
        EXPECT_NEAR(got, want, rel * std::abs(want)) << name << ": expected " << want << " within " << rel * 100
                                                      << " %, actual " << got;
      } else {
        ADD_FAILURE() << name << ": unknown operator '" << op << "'";
      }
    }
    EXPECT_GT(n_figures, 0) << "expected.toml lists no figures";
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
