// normals_bench [surface.off[.gz] ...]
// For each surface (default: a generated sphere) and each normal method prints
// vertices/s on one thread and on all threads, then the status counts, min V and min D
// of the method. Surfaces whose triangles face inward (negative signed volume) are
// flipped so that normals point into the external fluid.
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <zlib.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

#include "blayer/core/surface.h"
#include "blayer/core/vertex_fans.h"
#include "blayer/normals/point_normals.h"

namespace {

using blayer::TriSurface;

std::string read_gz(const std::string& path) {
  gzFile f = gzopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error("cannot open " + path);
  std::string out;
  char buf[1 << 16];
  int n;
  while ((n = gzread(f, buf, sizeof buf)) > 0) out.append(buf, n);
  gzclose(f);
  return out;
}

TriSurface read_off(const std::string& path) {
  std::istringstream in(read_gz(path));
  std::string magic;
  in >> magic;
  if (magic != "OFF") throw std::runtime_error(path + ": not an OFF file");
  long nv, nf, ne;
  in >> nv >> nf >> ne;
  TriSurface s;
  s.points.resize(nv);
  for (auto& p : s.points) in >> p[0] >> p[1] >> p[2];
  for (long i = 0; i < nf; ++i) {
    int c;
    in >> c;
    std::vector<int> v(c);
    for (int& x : v) in >> x;
    for (int j = 1; j + 1 < c; ++j) s.triangles.push_back({v[0], v[j], v[j + 1]});
  }
  if (!in) throw std::runtime_error(path + ": truncated OFF file");
  return s;
}

TriSurface sphere(int n_lat, int n_lon) {
  TriSurface s;
  s.points.push_back({0, 0, 1});
  for (int i = 1; i < n_lat; ++i)
    for (int j = 0; j < n_lon; ++j) {
      const double th = M_PI * i / n_lat, ph = 2 * M_PI * (j + 0.5 * (i % 2)) / n_lon;
      s.points.push_back({std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
    }
  s.points.push_back({0, 0, -1});
  const int south = static_cast<int>(s.points.size()) - 1;
  auto id = [&](int i, int j) { return 1 + (i - 1) * n_lon + (j % n_lon); };
  for (int j = 0; j < n_lon; ++j) s.triangles.push_back({0, id(1, j), id(1, j + 1)});
  for (int i = 1; i < n_lat - 1; ++i)
    for (int j = 0; j < n_lon; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (int j = 0; j < n_lon; ++j) s.triangles.push_back({south, id(n_lat - 1, j + 1), id(n_lat - 1, j)});
  return s;
}

double seconds_per_run(const TriSurface& s, const blayer::VertexFans& fans, blayer::NormalMethod m, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  double best = 1e300;
  for (int rep = 0; rep < (s.points.size() > 100000 ? 1 : 3); ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    const blayer::PointNormals pn = blayer::compute_point_normals(s, fans, m);
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(t1 - t0).count());
    if (pn.normal.empty() && !s.points.empty()) std::printf("empty result\n");
  }
  return best;
}

void run(const std::string& name, TriSurface s) {
  if (blayer::signed_volume(s) < 0.0)
    for (auto& t : s.triangles) std::swap(t[1], t[2]);
  const blayer::VertexFans fans = blayer::build_vertex_fans(s);
  const int all = tbb::info::default_concurrency();
  std::printf("== %s: %zu vertices, %zu triangles, %zu non-manifold, %d threads\n", name.c_str(), s.points.size(),
              s.triangles.size(), fans.non_manifold.size(), all);
  for (const std::string& mname : blayer::normal_method_names()) {
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
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) run("generated sphere 200x400", sphere(200, 400));
    for (int i = 1; i < argc; ++i) run(argv[i], read_off(argv[i]));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
