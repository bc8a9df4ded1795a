// Wall-clock seconds since construction, for the timings printed in summaries.
#pragma once

#include <chrono>

namespace blayer {

class RunTimer {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace blayer
