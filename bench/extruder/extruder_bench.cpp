// Usage: extruder_bench surface.off[.gz] [layers=10] [first_height_over_diagonal=2e-4] [ratio=1.2]
//                       [--cap-length shortest|mean|face] [--cap-ratio x]
// Extrudes the layers on an outward-oriented closed surface (fluid outside) and prints
// the run report, the envelope intersection check and the peak resident set size. The
// options set ExtrusionParams::height_cap_length and max_height_to_edge_ratio, to
// compare thickness policies.
#include <sys/resource.h>
#include <zlib.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

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
  const blayer::TriSurface wall = read_off(pos[0]);
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
