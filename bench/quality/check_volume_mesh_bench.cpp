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

#include "../common/stacked_prisms.h"
#include "blayer/core/stopwatch.h"
#include "blayer/quality/mesh_check.h"

namespace {

blayer::VolumeMesh make_prism_mesh(int n, int layers) {
  blayer::VolumeMesh m;
  blayer::bench::add_stacked_points(m, n, layers);
  blayer::bench::add_stacked_wedges(m, n, layers);
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
