// most_normal_fronts [--fronts N] [--first-height F] surface ...
// A simulated layer march (front_march.h: each point moved by h_k along its normal,
// h_0 = F times the bounding-box diagonal, default 2e-4, h_{k+1} = 1.2 h_k) over N fronts
// (default 10). On every front the most-normal normals are computed cold and
// warm-started from the previous front (compute_point_normals with a
// MostNormalWarmStart per point), both on one thread in the same run, and compared:
// the warm answers must equal the cold ones (same status, D within normality_tie,
// direction within 1e-12 rad, or V not lower on ties). Prints per front the vertex solves
// per second of each, their ratio, the hit rate of the warm certificates and the
// differences found, each described under its front (statuses, and how far apart the
// two answers' D, directions and V are).
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "blayer/io/prepare_surface.h"
#include "blayer/normals/most_normal.h"
#include "front_march.h"

namespace {

using namespace blayer;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void run(const std::string& path, int fronts, double first_height) {
  TriSurface s = load_surface(path, {}).surface;
  bench::FrontMarch march(s, first_height);
  std::vector<MostNormalWarmStart> warm;
  std::printf("== %s: %zu points, %zu triangles\n", path.c_str(), s.points.size(), s.triangles.size());
  std::printf("  front   height       cold v/s    warm v/s  warm/cold   hit rate (hits/warm)   differences\n");
  long total_warm = 0, total_hits = 0;
  for (int f = 0; f <= fronts; ++f) {
    const double height = march.height;
    auto t0 = std::chrono::steady_clock::now();
    const PointNormals cold = compute_point_normals(march.surface, march.fans, NormalMethod::kMostNormal);
    const double t_cold = seconds_since(t0);
    WarmStartCounts counts;
    t0 = std::chrono::steady_clock::now();
    const PointNormals hot =
        compute_point_normals(march.surface, march.fans, NormalMethod::kMostNormal, default_tolerances(), &warm, &counts);
    const double t_warm = seconds_since(t0);
    long differences = 0;
    std::vector<std::string> difference_lines;
    for (std::size_t v = 0; v < cold.normal.size(); ++v) {
      const bool tie = cold.status[v] == NormalStatus::kNonUnique || cold.status[v] == NormalStatus::kVisibilityConstrained;
      const bool same = cold.status[v] == hot.status[v] &&
                        std::fabs(cold.normality[v] - hot.normality[v]) <= default_tolerances().normality_tie &&
                        (angle_between(cold.normal[v], hot.normal[v]) <= 1e-12 ||
                         (tie && hot.visibility[v] >= cold.visibility[v] - 1e-12));
      if (same) continue;
      ++differences;
      char line[256];
      std::snprintf(line, sizeof line,
                    "         point %zu: cold %s, warm %s, cold D %.12f, warm D - cold D %.3g (tie %.3g), "
                    "directions %.3g rad apart, warm V - cold V %.3g\n",
                    v, normal_status_name(cold.status[v]), normal_status_name(hot.status[v]), cold.normality[v],
                    hot.normality[v] - cold.normality[v], default_tolerances().normality_tie,
                    angle_between(cold.normal[v], hot.normal[v]), hot.visibility[v] - cold.visibility[v]);
      difference_lines.push_back(line);
    }
    const double n = static_cast<double>(cold.normal.size());
    std::printf("  %5d  %9.3g  %10.0f  %10.0f  %8.2f   %6.3f (%ld/%ld)   %ld\n", f, height, n / t_cold, n / t_warm,
                t_cold / t_warm, counts.hit_rate(), counts.hits, counts.warm, differences);
    for (const std::string& line : difference_lines) std::fputs(line.c_str(), stdout);
    std::fflush(stdout);
    if (f > 0) {
      total_warm += counts.warm;
      total_hits += counts.hits;
    }
    if (f < fronts) march.advance(cold.normal);
  }
  std::printf("  fronts 1-%d: hit rate %.3f (%ld of %ld warm-started vertices)\n", fronts,
              total_warm > 0 ? static_cast<double>(total_hits) / total_warm : 0.0, total_hits, total_warm);
}

}  // namespace

int main(int argc, char** argv) {
  int fronts = 10;
  double first_height = 2e-4;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--fronts" && i + 1 < argc) {
      fronts = std::atoi(argv[++i]);
    } else if (a == "--first-height" && i + 1 < argc) {
      first_height = std::atof(argv[++i]);
    } else if (a == "-h" || a == "--help") {
      std::printf("usage: most_normal_fronts [--fronts N] [--first-height F] surface...\n");
      return 0;
    } else {
      files.push_back(a);
    }
  }
  // One thread: vertex solves per second per core.
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  try {
    for (const std::string& f : files) run(f, fronts, first_height);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
