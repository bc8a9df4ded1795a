// The default first height of the growth law (growth_law.h), as the extrude command
// uses it.
#include <gtest/gtest.h>

#include "blayer/core/errors.h"
#include "blayer/extruder/growth_law.h"

namespace blayer {
namespace {

TEST(DefaultFirstHeight, NoHeightGivenTakesTwoTenThousandthsOfTheDiagonalAndSaysSo) {
  std::string note = "stale";
  const GrowthLaw law = with_default_first_height(GrowthLaw{}, 1.7320508075688772, &note);
  EXPECT_DOUBLE_EQ(law.first_height, 2e-4 * 1.7320508075688772);
  EXPECT_EQ(note, "no height given: first-height = 0.00034641 (2e-4 x bounding-box diagonal)");
  EXPECT_EQ(law.layers, GrowthLaw{}.layers);
  EXPECT_NEAR(resolve_growth_law(law).first_height, 3.4641016e-4, 1e-10);
}

TEST(DefaultFirstHeight, AnyGivenHeightLeavesTheLawAlone) {
  for (int which = 0; which < 3; ++which) {
    GrowthLaw given;
    (which == 0 ? given.first_height : which == 1 ? given.last_height : given.total_thickness) = 0.01;
    std::string note = "stale";
    const GrowthLaw law = with_default_first_height(given, 5.0, &note);
    EXPECT_TRUE(note.empty()) << which;
    EXPECT_EQ(law.first_height, given.first_height) << which;
    EXPECT_EQ(law.last_height, given.last_height) << which;
    EXPECT_EQ(law.total_thickness, given.total_thickness) << which;
  }
}

TEST(DefaultFirstHeight, RelativeHeightsNeedAGivenHeight) {
  GrowthLaw law;
  law.relative = true;
  std::string note;
  EXPECT_THROW(with_default_first_height(law, 1.0, &note), InputError);
  law.first_height = 0.1;
  EXPECT_NO_THROW(with_default_first_height(law, 1.0, &note));
}

}  // namespace
}  // namespace blayer
