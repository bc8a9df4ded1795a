// The agreement rule of agreement.h as a GoogleTest assertion.
#pragma once

#include <gtest/gtest.h>

#include "agreement.h"

namespace blayer {
namespace testing_fans {

inline ::testing::AssertionResult same_optimum(const FanGeometry& g, bool constrained, const MostNormalResult& a,
                                               const MostNormalResult& oracle) {
  const Agreement r = compare_optimum(g, constrained, a, oracle);
  if (r.ok) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << r.why;
}

}  // namespace testing_fans
}  // namespace blayer
