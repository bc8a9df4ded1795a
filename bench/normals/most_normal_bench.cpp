// most_normal_bench [google benchmark flags] [surface ...]
// Google Benchmark figures of the most-normal solvers, all in one run (the machine is
// shared: compare ratios within a run):
//   ByValence/<solver>/<k>   generated fans of valence k (6: convex, saddle and near-flat
//                            wing-skin vertices with mesh jitter; 12-60: CAD-like fans,
//                            tests/normals/cad_fans.h, with offsets of 1e-5 and 1e-3 of
//                            the edge length)
//   ByShape/default/<shape>/<k>  the same CAD-like fans one shape at a time (ridge,
//                            corner, rim, sliver; 32 fans, valence 20, 40, 60): where
//                            the averages above come from
//   Exact/default/<shape>/<k>  the same shapes with planar faces (offset 0), as a CAD
//                            tessellation gives the wall: merged arcs, exact plateaus,
//                            dozens of faces on one constraint circle
//   Poles/<solver>/<k>       poles of bodies of revolution of valence k (every ring
//                            point at one elevation), exact and with the ring moved by
//                            1e-12, 1e-7 and 1e-5 of its radius
//   Plateaus/default/<k>     the CAD-like sliver fans of valence k exactly as drawn
//                            (offset 0): exactly antipodal link vertices and slivers
//                            nearly tied along a plateau of maximisers
//   SlackPoles/default/<k>   poles whose ring is moved by 1e-9 of its radius: the
//                            supports then miss the 1e-10 slack of the many-support
//                            shortcut, and the lens leaf keeps every nearly tied site
//                            The last two are the known slow families, timed apart so
//                            that they do not hide in the averages of the others.
//   Tail/default/<k>         ByValence's CAD-like fans drawn on to 400 (100 per shape):
//                            the slowest single vertices, which 64 fans can miss
//                            (max_vertex_us, and over_1ms: how many take longer)
//   TailExact/default/<k>    the same scan over 400 fans with planar faces (offset 0)
//   Mesh/<solver>/<surface>/<wall|front>
//                            every closed vertex of the surface, and of its first offset
//                            front (bench/normals/front_march.h)
// for solver = default (most_normal_normal), pruned (the previous default,
// most_normal_by_pruned_enumeration) and, up to valence 20, enumeration (the oracle).
// One thread; fan geometries are built before timing, so items/s counts vertex solves
// per second per core. Mesh benchmarks of the default solver also report max_vertex_us:
// the longest single vertex solve, each vertex timed three times and its fastest kept (a
// single reading is often a preemption of the shared machine); so do the ByValence
// benchmarks of the default solver, over their 64 fans.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bench_fans.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/normals/most_normal.h"
#include "cad_fans.h"
#include "front_march.h"
#include "random_fans.h"
#include "test_fans.h"

namespace {

using namespace blayer;
using bench::fans_of_shape;
using bench::fans_of_valence;

enum class Solver { kDefault, kPruned, kEnumeration };

MostNormalResult solve(Solver s, const FanGeometry& g) {
  switch (s) {
    case Solver::kDefault: return most_normal_normal(g);
    case Solver::kPruned: return most_normal_by_pruned_enumeration(g);
    case Solver::kEnumeration: return most_normal_by_enumeration(g);
  }
  return {};
}

const char* solver_name(Solver s) {
  switch (s) {
    case Solver::kDefault: return "default";
    case Solver::kPruned: return "pruned";
    case Solver::kEnumeration: return "enumeration";
  }
  return "";
}

std::vector<FanGeometry> plateau_fans_of_valence(int k) {
  std::vector<FanGeometry> fans;
  std::mt19937 rng(777u + static_cast<unsigned>(k));
  for (int t = 0; fans.size() < 16 && t < 1000; ++t) {
    FanGeometry g = testing_fans::geometry(testing_fans::cad_like_fan(rng, testing_fans::CadShape::kSliver, k, 0.0));
    if (!g.any_degenerate) fans.push_back(std::move(g));
  }
  return fans;
}

std::vector<FanGeometry> poles_of_valence(int k, std::initializer_list<double> offsets) {
  std::vector<FanGeometry> fans;
  std::mt19937 rng(96u + static_cast<unsigned>(k));
  std::normal_distribution<double> nd;
  for (double offset : offsets)
    for (int t = 0; t < 4; ++t) {
      std::vector<Vec3> ring;
      for (int j = 0; j < k; ++j)
        ring.push_back(Vec3{std::cos(2.0 * M_PI * j / k), std::sin(2.0 * M_PI * j / k), -0.05} +
                       offset * Vec3{nd(rng), nd(rng), nd(rng)});
      fans.push_back(testing_fans::geometry(ring));
    }
  return fans;
}

// The longest single vertex solve over fans (each timed three times, its fastest kept);
// *over_1ms (optional) counts the fans above a millisecond.
double longest_vertex_us(Solver solver, const std::vector<FanGeometry>& fans, int* over_1ms = nullptr) {
  double worst = 0.0;
  if (over_1ms) *over_1ms = 0;
  for (const FanGeometry& g : fans) {
    double best = 1e300;
    for (int rep = 0; rep < 3; ++rep) {
      const auto t0 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(solve(solver, g));
      best = std::min(best, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
    }
    worst = std::max(worst, best);
    if (over_1ms && best > 1000.0) ++*over_1ms;
  }
  return worst;
}

enum class Family { kMixed, kPoles, kPlateaus, kSlackPoles };

std::vector<FanGeometry> fans_of(Family family, int k) {
  switch (family) {
    case Family::kMixed: return fans_of_valence(k);
    case Family::kPoles: return poles_of_valence(k, {0.0, 1e-12, 1e-7, 1e-5});
    case Family::kPlateaus: return plateau_fans_of_valence(k);
    case Family::kSlackPoles: return poles_of_valence(k, {1e-9});
  }
  return {};
}

// Solves of the fans in turn, one per iteration; the default solver's slowest vertex too.
void time_fans(benchmark::State& state, Solver solver, const std::vector<FanGeometry>& fans) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(solve(solver, fans[i]));
    if (++i == fans.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  if (solver == Solver::kDefault) state.counters["max_vertex_us"] = longest_vertex_us(solver, fans);
}

void by_valence(benchmark::State& state, Solver solver, int k, Family family) {
  time_fans(state, solver, fans_of(family, k));
}

void by_shape(benchmark::State& state, testing_fans::CadShape shape, int k, bool exact) {
  time_fans(state, Solver::kDefault, fans_of_shape(shape, k, exact));
}

void tail(benchmark::State& state, int k, bool exact) {
  const std::vector<FanGeometry> fans = fans_of_valence(k, 400, exact);
  for (auto _ : state)
    for (const FanGeometry& g : fans) benchmark::DoNotOptimize(solve(Solver::kDefault, g));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(fans.size()));
  int over = 0;
  state.counters["max_vertex_us"] = longest_vertex_us(Solver::kDefault, fans, &over);
  state.counters["over_1ms"] = over;
}

void whole_mesh(benchmark::State& state, Solver solver, const std::vector<FanGeometry>* fans) {
  for (auto _ : state)
    for (const FanGeometry& g : *fans) benchmark::DoNotOptimize(solve(solver, g));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(fans->size()));
  // Three more passes: affordable for the default solver only (the baseline needs 76 s
  // per pass on the sliver wing's front).
  if (solver == Solver::kDefault) state.counters["max_vertex_us"] = longest_vertex_us(solver, *fans);
}

std::vector<FanGeometry> closed_fans(const bench::FrontMarch& m) {
  std::vector<FanGeometry> fans;
  FanGeometry g;
  for (std::size_t v = 0; v < m.surface.points.size(); ++v)
    if (m.closed_fan(v, &g)) fans.push_back(g);
  return fans;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  for (int k : {6, 12, 20, 40, 60})
    for (Solver s : {Solver::kDefault, Solver::kPruned, Solver::kEnumeration}) {
      if (s == Solver::kEnumeration && k > 20) continue;
      benchmark::RegisterBenchmark(("ByValence/" + std::string(solver_name(s)) + "/" + std::to_string(k)).c_str(),
                                   by_valence, s, k, Family::kMixed);
    }
  for (testing_fans::CadShape shape : testing_fans::kCadShapes)
    for (int k : {20, 40, 60}) {
      const std::string label = std::string(testing_fans::cad_shape_name(shape)) + "/" + std::to_string(k);
      benchmark::RegisterBenchmark(("ByShape/default/" + label).c_str(), by_shape, shape, k, false);
      benchmark::RegisterBenchmark(("Exact/default/" + label).c_str(), by_shape, shape, k, true);
    }
  for (int k : {16, 32, 64, 96})
    for (Solver s : {Solver::kDefault, Solver::kPruned})
      benchmark::RegisterBenchmark(("Poles/" + std::string(solver_name(s)) + "/" + std::to_string(k)).c_str(),
                                   by_valence, s, k, Family::kPoles);
  for (int k : {12, 20, 40})
    benchmark::RegisterBenchmark(("Plateaus/default/" + std::to_string(k)).c_str(), by_valence, Solver::kDefault, k,
                                 Family::kPlateaus);
  for (int k : {32, 64, 96})
    benchmark::RegisterBenchmark(("SlackPoles/default/" + std::to_string(k)).c_str(), by_valence, Solver::kDefault,
                                 k, Family::kSlackPoles);
  for (int k : {20, 40, 60})
    for (bool exact : {false, true})
      benchmark::RegisterBenchmark(((exact ? "TailExact/default/" : "Tail/default/") + std::to_string(k)).c_str(), tail,
                                   k, exact)
          ->Unit(benchmark::kMillisecond);
  // Surfaces given after the benchmark flags; their fans live until the run ends.
  std::vector<std::vector<FanGeometry>*> keep;
  for (int i = 1; i < argc; ++i) {
    const std::string path = argv[i];
    const std::string name = path.substr(path.find_last_of('/') + 1);
    bench::FrontMarch march(load_surface(path, {}).surface);
    auto* wall = new std::vector<FanGeometry>(closed_fans(march));
    march.advance();
    auto* front = new std::vector<FanGeometry>(closed_fans(march));
    keep.push_back(wall);
    keep.push_back(front);
    for (Solver s : {Solver::kDefault, Solver::kPruned})
      for (auto [label, fans] : {std::pair<const char*, std::vector<FanGeometry>*>{"wall", wall}, {"front", front}})
        benchmark::RegisterBenchmark(("Mesh/" + std::string(solver_name(s)) + "/" + name + "/" + label).c_str(),
                                     whole_mesh, s, fans)
            ->Unit(benchmark::kMillisecond)
            ->Iterations(1);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  for (auto* f : keep) delete f;
  return 0;
}
