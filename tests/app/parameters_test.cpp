#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "parameters.h"

namespace blayer {
namespace {

TEST(Parameters, NamesAreUniqueAndDocumented) {
  std::set<std::string> seen;
  for (const ParamSpec& p : parameter_table()) {
    EXPECT_TRUE(seen.insert(p.name).second) << p.name;
    EXPECT_FALSE(p.help.empty()) << p.name;
    EXPECT_NE(p.commands, 0u) << p.name;
  }
}

TEST(Parameters, ReadmeListsTheTableAsGenerated) {
  std::ifstream in(std::string(BLAYER_SOURCE_DIR) + "/README.md");
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_NE(ss.str().find(parameter_table_markdown()), std::string::npos)
      << "README.md's parameter list is out of date; paste the output of `blayer params`";
}

}  // namespace
}  // namespace blayer

#include "blayer/extruder/extrude_layers.h"

namespace blayer {
namespace {

TEST(Parameters, ChoiceDefaultsAreTheEngines) {
  int seen = 0;
  for (const ParamSpec& p : parameter_table()) {
    if (p.name == "column-directions") {
      ++seen;
      EXPECT_EQ(p.default_value, "kept");
      EXPECT_EQ(ExtrusionParams{}.column_directions, ColumnDirections::kKept);
    }
    if (p.name == "limit") {
      ++seen;
      EXPECT_EQ(p.default_value, "compress");
      EXPECT_EQ(ExtrusionParams{}.limit_policy, LimitPolicy::kCompress);
    }
  }
  EXPECT_EQ(seen, 2);
}

}  // namespace
}  // namespace blayer
