// cell_metrics_bench [google benchmark flags]
// Google Benchmark figures of compute_cell_metrics, one cell type at a time: the
// reference cells (tests/quality/test_cells.h) flattened like boundary-layer cells (a
// tenth of their height) with every coordinate moved by up to 5 % of the cap edge, 4096
// cells per type built before timing, one thread. items/s counts cells per second per
// core; the final check of `blayer extrude` and `blayer check` compute these for every
// cell (fan hexes are most of a CAD surface's layers).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "blayer/quality/cell_metrics.h"
#include "test_cells.h"

namespace {

using namespace blayer;

std::vector<Vec3> perturbed_cells(const std::vector<Vec3>& ref, std::size_t count) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  std::vector<Vec3> out;
  out.reserve(ref.size() * count);
  for (std::size_t c = 0; c < count; ++c)
    for (const Vec3& x : ref) out.push_back({x[0] + u(rng), x[1] + u(rng), 0.1 * x[2] + 0.1 * u(rng)});
  return out;
}

void metrics_of(benchmark::State& state, CellType type, const std::vector<Vec3>& ref) {
  constexpr std::size_t kCells = 4096;
  const std::vector<Vec3> p = perturbed_cells(ref, kCells);
  const std::size_t n = ref.size();
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t c = 0; c < kCells; ++c) sum += compute_cell_metrics(type, &p[c * n]).skewness;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kCells));
}

}  // namespace

BENCHMARK_CAPTURE(metrics_of, tet, CellType::kTet, test::unit_tet());
BENCHMARK_CAPTURE(metrics_of, pyramid, CellType::kPyramid, test::unit_pyramid());
BENCHMARK_CAPTURE(metrics_of, wedge, CellType::kWedge, test::right_prism());
BENCHMARK_CAPTURE(metrics_of, hex, CellType::kHex, test::unit_hex());

BENCHMARK_MAIN();
