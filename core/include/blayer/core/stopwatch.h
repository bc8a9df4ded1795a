// Wall-clock time since a starting point, for the timings printed in summaries and
// stored in reports. steady_clock: never goes backwards when the system clock is set.
#pragma once

#include <chrono>

namespace blayer {

class Stopwatch {
 public:
  // Seconds since construction or the last restart().
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  void restart() { start_ = Clock::now(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_ = Clock::now();
};

}  // namespace blayer
