#include "blayer/core/stopwatch.h"

#include <gtest/gtest.h>

#include <thread>

namespace blayer {
namespace {

// Only ordering is pinned down (sleep_for waits at least the given time); how fast
// anything runs is for the benchmarks.
TEST(Stopwatch, CountsUpFromConstructionAndFromRestart) {
  Stopwatch w;
  const double t0 = w.seconds();
  EXPECT_GE(t0, 0.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const double t1 = w.seconds();
  EXPECT_GE(t1, 0.02);
  EXPECT_GE(t1, t0);
  w.restart();
  EXPECT_LT(w.seconds(), t1);
}

}  // namespace
}  // namespace blayer
