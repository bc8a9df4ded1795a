// most_normal_tail_scan [first_seed [seeds [fans_per_valence [exact]]]]
// The slowest single vertex solves of the default most-normal solver over many more
// generated CAD-like fans than the benchmark holds (most_normal_bench's Tail keeps 400 per
// valence in memory): fans are drawn one at a time, seeds first_seed .. first_seed +
// seeds - 1 (default 101, 40 seeds, 2,000 fans per valence and seed), valences 20 to 60,
// with the shapes and offsets of the benchmark's fans (tests/normals/cad_fans.h); with
// a fourth argument `exact`, the same shapes with planar faces (offset 0).
// Each fan is solved once, and again up to twice more when it took over 300 us, keeping
// the fastest (a single reading is often a preemption of the shared machine). Prints,
// per valence, the solves per second, the slowest vertex and how many took over a
// millisecond, then every fan over a millisecond (seed, valence, index: enough to draw
// it again) with its status and cells. One thread.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "blayer/normals/most_normal.h"
#include "cad_fans.h"

namespace {

using namespace blayer;

struct SlowFan {
  unsigned seed;
  int valence, index;
  double us;
  MostNormalResult result;
};

struct ValenceTally {
  long fans = 0, over_1ms = 0;
  double seconds = 0.0, slowest_us = 0.0;
};

// Fastest of up to three solves, the repeats only where the first was slow.
double solve_us(const FanGeometry& g, MostNormalResult* r) {
  double best = 1e300;
  for (int rep = 0; rep < 3 && best > 300.0; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    *r = most_normal_normal(g);
    best = std::min(best, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const unsigned first_seed = argc > 1 ? static_cast<unsigned>(std::atoi(argv[1])) : 101u;
  const int seeds = argc > 2 ? std::atoi(argv[2]) : 40;
  const int per_valence = argc > 3 ? std::atoi(argv[3]) : 2000;
  const bool exact = argc > 4 && std::string(argv[4]) == "exact";
  const int valences[] = {20, 30, 40, 50, 60};
  ValenceTally tally[5];
  std::vector<SlowFan> slow;
  for (int s = 0; s < seeds; ++s)
    for (int v = 0; v < 5; ++v) {
      const int k = valences[v];
      const unsigned seed = first_seed + static_cast<unsigned>(s);
      std::mt19937 rng(seed + static_cast<unsigned>(k));
      for (int t = 0; t < per_valence; ++t) {
        const double offset = exact ? 0.0 : (t % 3 == 0 ? 1e-5 : 1e-3);
        const FanGeometry g =
            testing_fans::geometry(testing_fans::cad_like_fan(rng, testing_fans::kCadShapes[t % 4], k, offset));
        if (g.any_degenerate) continue;
        MostNormalResult r;
        const double us = solve_us(g, &r);
        ValenceTally& y = tally[v];
        ++y.fans;
        y.seconds += 1e-6 * us;
        y.slowest_us = std::max(y.slowest_us, us);
        if (us > 1000.0) {
          ++y.over_1ms;
          slow.push_back({seed, k, t, us, r});
        }
      }
    }
  std::printf("seeds %u..%u, %d fans per valence and seed%s\n", first_seed, first_seed + seeds - 1, per_valence,
              exact ? ", planar faces" : "");
  long fans = 0, over = 0;
  double slowest = 0.0;
  for (int v = 0; v < 5; ++v) {
    const ValenceTally& y = tally[v];
    std::printf("valence %d: %ld fans, %.0f solves/s, slowest %.0f us, over 1 ms %ld\n", valences[v], y.fans,
                y.seconds > 0.0 ? y.fans / y.seconds : 0.0, y.slowest_us, y.over_1ms);
    fans += y.fans;
    over += y.over_1ms;
    slowest = std::max(slowest, y.slowest_us);
  }
  std::printf("all: %ld fans, slowest %.0f us, over 1 ms %ld\n", fans, slowest, over);
  std::sort(slow.begin(), slow.end(), [](const SlowFan& a, const SlowFan& b) { return a.us > b.us; });
  for (const SlowFan& f : slow)
    std::printf("  seed %u valence %d fan %d: %.0f us, %s, %d cells, D %.9f deg, V %.6f\n", f.seed, f.valence, f.index,
                f.us, normal_status_name(f.result.status), f.result.n_cells, f.result.normality * 180.0 / M_PI,
                f.result.visibility);
}
