// Usage: extruder_bench surface.off[.gz] [layers=10] [first_height_over_diagonal=2e-4] [ratio=1.2]
// Extrudes the layers on an outward-oriented closed surface (fluid outside) and prints
// the run report, the envelope intersection check and the peak resident set size.
#include <sys/resource.h>
#include <zlib.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "blayer/core/surface.h"
#include "blayer/extruder/extrude_layers.h"

namespace {

std::string read_gz(const char* path) {
  gzFile f = gzopen(path, "rb");
  if (!f) {
    std::fprintf(stderr, "cannot open %s\n", path);
    std::exit(1);
  }
  std::string out;
  char buf[1 << 16];
  int n;
  while ((n = gzread(f, buf, sizeof buf)) > 0) out.append(buf, n);
  gzclose(f);
  return out;
}

blayer::TriSurface read_off(const char* path) {
  std::istringstream in(read_gz(path));
  std::string tag;
  in >> tag;
  if (tag != "OFF") {
    std::fprintf(stderr, "%s: not an OFF file\n", path);
    std::exit(1);
  }
  long nv, nf, ne;
  in >> nv >> nf >> ne;
  blayer::TriSurface s;
  s.points.resize(nv);
  for (auto& p : s.points) in >> p[0] >> p[1] >> p[2];
  s.triangles.resize(nf);
  for (auto& t : s.triangles) {
    int k;
    in >> k >> t[0] >> t[1] >> t[2];
    if (k != 3) {
      std::fprintf(stderr, "%s: only triangles are supported\n", path);
      std::exit(1);
    }
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s surface.off[.gz] [layers] [first_height/diagonal] [ratio]\n", argv[0]);
    return 2;
  }
  const blayer::TriSurface wall = read_off(argv[1]);
  const double diag = blayer::bounding_box_diagonal(wall.points);
  blayer::ExtrusionParams p;
  p.growth.layers = argc > 2 ? std::atoi(argv[2]) : 10;
  p.growth.first_height = (argc > 3 ? std::atof(argv[3]) : 2e-4) * diag;
  p.growth.growth_ratio = argc > 4 ? std::atof(argv[4]) : 1.2;
  std::printf("surface %s: %zu points, %zu triangles, bbox diagonal %.6g, signed volume %.6g\n", argv[1],
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
