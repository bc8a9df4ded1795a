// A tiny deterministic random generator for tests (Knuth's 64-bit linear congruential
// step): the same sequence on every platform and standard library, unlike <random>'s
// distributions.
#pragma once

#include <cstdint>

namespace blayer::testing {

class Lcg {
 public:
  explicit Lcg(std::uint64_t seed) : state_(seed) {}
  // Uniform in [0, 1), 53 bits.
  double uniform() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state_ >> 11) / 9007199254740992.0;
  }

 private:
  std::uint64_t state_;
};

}  // namespace blayer::testing
