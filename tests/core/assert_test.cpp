#include "blayer/core/assert.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace blayer {
namespace {

int assert_line = 0;

std::string message_of_cheap_failure() {
  try {
    const int n_points = -1;
    assert_line = __LINE__ + 1;
    BLAYER_ASSERT(n_points >= 0);
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "no exception";
}

TEST(Assert, CheapAssertionThrowsLogicErrorNamingFileLineAndCondition) {
  const std::string msg = message_of_cheap_failure();
  EXPECT_NE(msg.find("assert_test.cpp:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("assertion failed: n_points >= 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find(":" + std::to_string(assert_line) + ":"), std::string::npos) << msg;
}

TEST(Assert, MessageVariantAppendsItsText) {
  try {
    BLAYER_ASSERT_MSG(1 + 1 == 3, "arithmetic is broken");
    FAIL() << "no exception";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("1 + 1 == 3: arithmetic is broken"), std::string::npos) << e.what();
  }
}

TEST(Assert, PassingAssertionsDoNothing) {
  EXPECT_NO_THROW(BLAYER_ASSERT(2 > 1));
  EXPECT_NO_THROW(BLAYER_ASSERT_MSG(true, "unused"));
  EXPECT_NO_THROW(BLAYER_EXPENSIVE_ASSERT(2 > 1));
}

TEST(Assert, ExpensiveAssertionIsEvaluatedOnlyInCheckedBuilds) {
  int evaluations = 0;
  auto failing = [&] {
    ++evaluations;
    return false;
  };
  static_cast<void>(failing);  // the unchecked build's assertion expands to nothing
  if (kExpensiveChecks) {
    EXPECT_THROW(BLAYER_EXPENSIVE_ASSERT(failing()), std::logic_error);
    EXPECT_EQ(evaluations, 1);
  } else {
    EXPECT_NO_THROW(BLAYER_EXPENSIVE_ASSERT(failing()));
    EXPECT_EQ(evaluations, 0);
  }
}

}  // namespace
}  // namespace blayer
