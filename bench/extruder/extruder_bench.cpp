// Usage: extruder_bench SURFACE [layers=10] [first_height_over_diagonal=2e-4] [ratio=1.2]
//                       [--cap-length shortest|mean|face] [--cap-ratio x]
// Extrudes the layers on a closed surface, read and oriented for external flow by
// blayer_io as the command line does (any input format, .gz too), and prints
// the run report, the envelope intersection check and the peak resident set size. The
// options set ExtrusionParams::height_cap_length and max_height_to_edge_ratio, to
// compare thickness policies.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "blayer/core/surface.h"
#include "blayer/extruder/extrude_layers.h"
#include "blayer/io/prepare_surface.h"

int main(int argc, char** argv) {
  auto usage = [&] {
    std::fprintf(stderr,
                 "usage: %s surface.off[.gz] [layers] [first_height/diagonal] [ratio] "
                 "[--cap-length shortest|mean|face] [--cap-ratio x]\n",
                 argv[0]);
    return 2;
  };
  blayer::ExtrusionParams p;
  std::vector<const char*> pos;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--cap-length" && i + 1 < argc) {
      const std::string v = argv[++i];
      if (v == "shortest") p.height_cap_length = blayer::HeightCapLength::kShortestEdge;
      else if (v == "mean") p.height_cap_length = blayer::HeightCapLength::kMeanEdge;
      else if (v == "face") p.height_cap_length = blayer::HeightCapLength::kFaceSize;
      else return usage();
    } else if (a == "--cap-ratio" && i + 1 < argc) {
      p.max_height_to_edge_ratio = std::atof(argv[++i]);
    } else if (a.rfind("--", 0) == 0) {
      return usage();
    } else {
      pos.push_back(argv[i]);
    }
  }
  if (pos.empty()) return usage();
  const blayer::TriSurface wall = blayer::load_surface(pos[0], {}).surface;
  const double diag = blayer::bounding_box_diagonal(wall.points);
  p.growth.layers = pos.size() > 1 ? std::atoi(pos[1]) : 10;
  p.growth.first_height = (pos.size() > 2 ? std::atof(pos[2]) : 2e-4) * diag;
  p.growth.growth_ratio = pos.size() > 3 ? std::atof(pos[3]) : 1.2;
  std::printf("surface %s: %zu points, %zu triangles, bbox diagonal %.6g, signed volume %.6g\n", pos[0],
              wall.points.size(), wall.triangles.size(), diag, blayer::signed_volume(wall));

  const blayer::ExtrusionResult r = blayer::extrude_layers(wall, p, [](int k, int n) {
    std::fprintf(stderr, "\rlayer %d/%d", k, n);
    if (k == n) std::fprintf(stderr, "\n");
  });
  std::printf("%s", blayer::format_extrusion_report(r.report).c_str());

  const auto t0 = std::chrono::steady_clock::now();
  const auto pairs = blayer::find_envelope_intersections(wall, r, 100);
  const double t_check = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("envelope check      %zu intersecting pairs (wall + envelope, exact) in %.3f s\n", pairs.size(),
              t_check);
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("peak RSS            %.1f MB\n", ru.ru_maxrss / 1024.0);
  return 0;
}
