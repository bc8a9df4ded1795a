// Times check_volume_mesh on a generated boundary-layer mesh: an n x n wavy wall grid,
// each quad split into two triangles, extruded by `layers` prisms with growth 1.2.
// Usage: quality_bench [n=500] [layers=10]  (default 5,000,000 prisms)
// Prints cells/s with one thread and with all threads.
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>

#include "blayer/core/stopwatch.h"
#include "blayer/quality/mesh_check.h"

namespace {

blayer::VolumeMesh make_prism_mesh(int n, int layers) {
  blayer::VolumeMesh m;
  const int np = n + 1;
  const double h0 = 1e-3;
  for (int k = 0; k <= layers; ++k) {
    const double z = h0 * (std::pow(1.2, k) - 1.0) / 0.2;
    for (int j = 0; j < np; ++j)
      for (int i = 0; i < np; ++i) {
        const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
        m.points.push_back({x, y, 0.05 * std::sin(6.0 * x) * std::cos(4.0 * y) + z});
      }
  }
  m.cell_types.reserve(static_cast<std::size_t>(2) * n * n * layers);
  m.connectivity.reserve(static_cast<std::size_t>(12) * n * n * layers);
  blayer::DataArray layer{"layer", 1, true, {}};
  auto id = [&](int k, int i, int j) { return static_cast<std::int64_t>(k) * np * np + static_cast<std::int64_t>(j) * np + i; };
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        // Wall triangles (a,b,c) with +z normals, written (a, c, b, a', c', b').
        const int tri[2][3][2] = {{{i, j}, {i + 1, j}, {i + 1, j + 1}}, {{i, j}, {i + 1, j + 1}, {i, j + 1}}};
        for (const auto& t : tri) {
          const std::int64_t nodes[6] = {id(k, t[0][0], t[0][1]),     id(k, t[2][0], t[2][1]),
                                         id(k, t[1][0], t[1][1]),     id(k + 1, t[0][0], t[0][1]),
                                         id(k + 1, t[2][0], t[2][1]), id(k + 1, t[1][0], t[1][1])};
          m.add_cell(blayer::CellType::kWedge, nodes);
          layer.values.push_back(k);
        }
      }
  m.cell_data.push_back(std::move(layer));
  return m;
}

struct Timing {
  double wall = 0.0;
  double cpu = 0.0;  // process CPU time, all threads: meaningful on a shared machine
};

Timing time_check(const blayer::VolumeMesh& m, blayer::MeshCheckReport* out) {
  const blayer::Stopwatch clock;
  const std::clock_t c0 = std::clock();
  *out = blayer::check_volume_mesh(m);
  return {clock.seconds(),
          static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC};
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 500;
  const int layers = argc > 2 ? std::atoi(argv[2]) : 10;
  const blayer::Stopwatch clock;
  const blayer::VolumeMesh m = make_prism_mesh(n, layers);
  const double t_gen = clock.seconds();
  std::printf("mesh: %zu prisms, %zu points (generated in %.2f s)\n", m.n_cells(), m.points.size(), t_gen);

  blayer::MeshCheckReport r;
  Timing t1;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    t1 = time_check(m, &r);
  }
  const int threads = tbb::info::default_concurrency();
  const Timing tn = time_check(m, &r);
  std::printf("check_volume_mesh 1 thread : wall %.2f s (%.3g cells/s), cpu %.2f s\n", t1.wall,
              m.n_cells() / t1.wall, t1.cpu);
  std::printf("check_volume_mesh %d threads: wall %.2f s (%.3g cells/s), cpu %.2f s\n", threads, tn.wall,
              m.n_cells() / tn.wall, tn.cpu);
  std::printf("result: ok=%d inverted=%zu flat=%zu non_conforming=%zu boundary_faces=%zu min_scaled_jacobian=%.4f\n",
              r.ok() ? 1 : 0, r.totals.inverted, r.totals.flat, r.totals.non_conforming, r.boundary_faces,
              r.min_scaled_jacobian());
  return r.ok() ? 0 : 1;
}
