// Usage: extruder_bench SURFACE [layers=10] [first_height_over_diagonal=2e-4] [ratio=1.2]
//                       [--limit compress|terminate] [--directions kept|recomputed] [--worst k]
// Extrudes the layers on a closed surface, read and oriented for external flow by
// blayer_io as the command line does (any input format, .gz too), and prints
// the run report, the envelope intersection check and the peak resident set size. The
// options set ExtrusionParams::limit_policy and column_directions, to compare
// policies. --worst k lists the k columns whose top lies lowest
// against the plane of one of their incident wall faces (the report's thickness
// measure), with their stop reason, layers, direction and incident face normals, to
// tell a fold-back from a column that turns at a sharp edge.
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "blayer/core/stopwatch.h"
#include "blayer/core/surface.h"
#include "blayer/extruder/extrude_layers.h"
#include "blayer/io/prepare_surface.h"

namespace {

// Columns ranked by min over incident wall faces of the top's height above the face
// plane; for each: position, layers, stop reason, the last segment's direction and,
// per incident face, its normal, the height above its plane and n.f.
void print_worst_columns(const blayer::TriSurface& wall, const blayer::ExtrusionResult& r, int count) {
  using namespace blayer;
  const int nv = static_cast<int>(wall.points.size());
  std::vector<std::vector<int>> vtri(nv);
  for (int f = 0; f < static_cast<int>(wall.triangles.size()); ++f)
    for (int v : wall.triangles[f]) vtri[v].push_back(f);
  auto face_normal = [&](int f) { return blayer::normalized(blayer::triangle_area_vector(wall, wall.triangles[f])); };
  std::vector<std::pair<double, int>> h;
  for (int v = 0; v < nv; ++v) {
    if (r.column_layers[v] == 0 || vtri[v].empty()) continue;
    double m = HUGE_VAL;
    for (int f : vtri[v]) m = std::min(m, blayer::dot(r.envelope.points[v] - wall.points[v], face_normal(f)));
    h.push_back({m, v});
  }
  std::sort(h.begin(), h.end());
  for (int i = 0; i < count && i < static_cast<int>(h.size()); ++i) {
    const int v = h[i].second;
    const Vec3& p = wall.points[v];
    const Vec3 d = r.envelope.points[v] - p;
    std::printf("column %d at (%.6g %.6g %.6g): min height %.4g, layers %d, stop %s, top - wall (%.4g %.4g %.4g)\n", v,
                p[0], p[1], p[2], h[i].first, r.column_layers[v], blayer::stop_reason_name(r.stop_reason[v]), d[0],
                d[1], d[2]);
    const Vec3 dn = blayer::normalized(d);
    for (int f : vtri[v]) {
      const Vec3 n = face_normal(f);
      std::printf("    face %d n (%.4f %.4f %.4f) height %.4g  dir.n %.4f\n", f, n[0], n[1], n[2], blayer::dot(d, n),
                  blayer::dot(dn, n));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  auto usage = [&] {
    std::fprintf(stderr,
                 "usage: %s surface.off[.gz] [layers] [first_height/diagonal] [ratio] "
                 "[--limit compress|terminate] [--directions kept|recomputed] [--worst k]\n",
                 argv[0]);
    return 2;
  };
  blayer::ExtrusionParams p;
  std::vector<const char*> pos;
  int worst = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--limit" && i + 1 < argc) {
      const std::string v = argv[++i];
      if (v == "compress") p.limit_policy = blayer::LimitPolicy::kCompress;
      else if (v == "terminate") p.limit_policy = blayer::LimitPolicy::kTerminate;
      else return usage();
    } else if (a == "--directions" && i + 1 < argc) {
      const std::string v = argv[++i];
      if (v == "kept") p.column_directions = blayer::ColumnDirections::kKept;
      else if (v == "recomputed") p.column_directions = blayer::ColumnDirections::kRecomputed;
      else return usage();
    } else if (a == "--worst" && i + 1 < argc) {
      worst = std::atoi(argv[++i]);
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

  const blayer::Stopwatch clock;
  const auto pairs = blayer::find_envelope_intersections(wall, r, 100);
  const double t_check = clock.seconds();
  std::printf("envelope check      %zu intersecting pairs (wall + envelope, exact) in %.3f s\n", pairs.size(),
              t_check);
  if (worst > 0) print_worst_columns(wall, r, worst);
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  std::printf("peak RSS            %.1f MB\n", ru.ru_maxrss / 1024.0);
  return 0;
}
