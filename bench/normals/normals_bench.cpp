// normals_bench [--methods m1,m2,...] [--dump DIR] [--stats] [surface ...]  (any input format, .gz too)
// For each surface (default: a generated sphere) and each normal method prints
// vertices/s on one thread and on all threads, then the status counts, min V and min D
// of the method. Surfaces whose triangles face inward (negative signed volume) are
// flipped so that normals point into the external fluid.
//   --methods  only these methods (names as on the command line; default all)
//   --dump     write each result to DIR/<surface>.<method>.txt, one vertex a line
//              (status, V, D, normal at 17 digits), to compare two builds exactly
//   --stats    most-normal only: per-vertex path counts (reflex link vertices, arcs,
//              candidates evaluated), to see where the solver spends its time
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "blayer/core/stopwatch.h"
#include "blayer/core/surface.h"
#include "blayer/core/vertex_fans.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/normals/fan_geometry.h"
#include "blayer/normals/most_normal.h"
#include "blayer/normals/point_normals.h"
#include "analytic_surfaces.h"

namespace {

using blayer::TriSurface;

struct Options {
  std::vector<std::string> methods;  // empty: all
  std::string dump_dir;
  bool stats = false;
};


double seconds_per_run(const TriSurface& s, const blayer::VertexFans& fans, blayer::NormalMethod m, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  double best = 1e300;
  for (int rep = 0; rep < (s.points.size() > 100000 ? 1 : 3); ++rep) {
    const blayer::Stopwatch clock;
    const blayer::PointNormals pn = blayer::compute_point_normals(s, fans, m);
    best = std::min(best, clock.seconds());
    if (pn.normal.empty() && !s.points.empty()) std::printf("empty result\n");
  }
  return best;
}

void dump(const std::string& dir, const std::string& name, const std::string& method, const blayer::PointNormals& pn) {
  const std::string base = name.substr(name.find_last_of('/') + 1);
  const std::string path = dir + "/" + base + "." + method + ".txt";
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + path);
  for (std::size_t v = 0; v < pn.normal.size(); ++v)
    std::fprintf(f, "%d %.17g %.17g %.17g %.17g %.17g\n", static_cast<int>(pn.status[v]), pn.visibility[v],
                 pn.normality[v], pn.normal[v][0], pn.normal[v][1], pn.normal[v][2]);
  std::fclose(f);
}

// Histogram of candidates evaluated per vertex by the most-normal solver, by number of
// reflex link vertices (the sites that make the enumeration non-trivial), and timing per
// class, so a change can be aimed at the vertices that cost the most.
void stats(const TriSurface& s, const blayer::VertexFans& fans) {
  struct Row {
    long vertices = 0;
    long candidates = 0;
    double seconds = 0.0;
  };
  std::map<int, Row> by_reflex;
  std::map<int, long> by_status;
  std::vector<blayer::Vec3> ring;
  for (std::size_t v = 0; v < s.points.size(); ++v) {
    const blayer::VertexFan& fan = fans.fans[v];
    if (fan.triangles.empty() || !fan.closed) continue;
    ring.clear();
    for (int r : fan.ring) ring.push_back(s.points[r]);
    const blayer::FanGeometry g = blayer::build_fan_geometry(s.points[v], ring, true);
    if (g.any_degenerate) continue;
    const int k = g.n_faces();
    int n_reflex = 0;
    for (int j = 0; j < k; ++j)
      n_reflex += blayer::dot(g.face_normals[(j + k - 1) % k], g.dirs[(j + 1) % k]) < -1e-12 ? 1 : 0;
    const blayer::Stopwatch clock;
    const blayer::MostNormalResult r = blayer::most_normal_normal(g);
    const double seconds = clock.seconds();
    Row& row = by_reflex[n_reflex];
    ++row.vertices;
    row.candidates += r.n_candidates;
    row.seconds += seconds;
    ++by_status[static_cast<int>(r.status)];
  }
  std::printf("most-normal per reflex-vertex count: reflex vertices  candidates/vertex  us/vertex  share of time\n");
  double total = 0.0;
  for (const auto& e : by_reflex) total += e.second.seconds;
  for (const auto& e : by_reflex)
    std::printf("  reflex %2d: %8ld vertices  %10.1f cand  %9.2f us  %5.1f%%\n", e.first, e.second.vertices,
                static_cast<double>(e.second.candidates) / e.second.vertices, 1e6 * e.second.seconds / e.second.vertices,
                100.0 * e.second.seconds / total);
  for (const auto& e : by_status)
    std::printf("  status %s: %ld\n", blayer::normal_status_name(static_cast<blayer::NormalStatus>(e.first)),
                e.second);
}

void run(const std::string& name, TriSurface s, const Options& opt) {
  if (blayer::signed_volume(s) < 0.0)
    for (auto& t : s.triangles) std::swap(t[1], t[2]);
  const blayer::VertexFans fans = blayer::build_vertex_fans(s);
  const int all = tbb::info::default_concurrency();
  std::printf("== %s: %zu vertices, %zu triangles, %zu non-manifold, %d threads\n", name.c_str(), s.points.size(),
              s.triangles.size(), fans.non_manifold.size(), all);
  if (opt.stats) stats(s, fans);
  for (const std::string& mname : blayer::normal_method_names()) {
    if (!opt.methods.empty() && std::find(opt.methods.begin(), opt.methods.end(), mname) == opt.methods.end())
      continue;
    blayer::NormalMethod m;
    blayer::parse_normal_method(mname, &m);
    const double t1 = seconds_per_run(s, fans, m, 1);
    const double ta = seconds_per_run(s, fans, m, all);
    const blayer::PointNormals pn = blayer::compute_point_normals(s, fans, m);
    int counts[6] = {0, 0, 0, 0, 0, 0};
    double min_v = 1e300, min_d = 1e300;
    for (std::size_t v = 0; v < s.points.size(); ++v) {
      if (fans.fans[v].triangles.empty()) continue;
      ++counts[static_cast<int>(pn.status[v])];
      min_v = std::min(min_v, pn.visibility[v]);
      min_d = std::min(min_d, pn.normality[v]);
    }
    std::printf("%-13s 1 thread %10.0f v/s  %d threads %10.0f v/s  min V %+.6f  min D %8.4f deg  |", mname.c_str(),
                s.points.size() / t1, all, s.points.size() / ta, min_v, min_d * 180.0 / M_PI);
    for (int st = 0; st < 6; ++st)
      std::printf(" %s %d", blayer::normal_status_name(static_cast<blayer::NormalStatus>(st)), counts[st]);
    std::printf("\n");
    if (!opt.dump_dir.empty()) dump(opt.dump_dir, name, mname, pn);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    Options opt;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--help" || a == "-h") {
        std::printf("usage: normals_bench [--methods m1,m2,...] [--dump DIR] [--stats] [surface.off[.gz] ...]\n");
        return 0;
      } else if (a == "--methods" && i + 1 < argc) {
        std::stringstream list(argv[++i]);
        std::string m;
        blayer::NormalMethod parsed;
        while (std::getline(list, m, ','))
          if (blayer::parse_normal_method(m, &parsed)) {
            opt.methods.push_back(m);
          } else {
            throw std::runtime_error("unknown method " + m);
          }
      } else if (a == "--dump" && i + 1 < argc) {
        opt.dump_dir = argv[++i];
      } else if (a == "--stats") {
        opt.stats = true;
      } else {
        files.push_back(a);
      }
    }
    if (files.empty()) run("generated sphere 200x400", blayer::test_surfaces::uv_sphere(200, 400, 1.0, M_PI / 400), opt);
    for (const std::string& f : files) run(f, blayer::load_surface(f, {}).surface, opt);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
