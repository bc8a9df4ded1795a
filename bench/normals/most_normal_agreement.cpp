// most_normal_agreement [--fronts N] [--oracle full|pruned] [--free] [--max-valence K] [--show M]
//                       surface ...
// The default most-normal solver against an enumeration on every closed vertex of each
// surface and of N simulated offset fronts (front_march.h), constrained (the default)
// and, with --free, also without the visibility constraint. A vertex agrees when the
// statuses are equal, D is within normality_tie, and the directions are within 1e-7 rad
// (unique optima) or V is not lower by more than 1e-7 (plateaus and constrained optima,
// where the tie-break decides). Prints the counts, the worst differences and the first M
// disagreements with their fans' valence, reflex count and statuses.
//   --oracle full    the unpruned enumeration (default; slow on fans of valence > 100)
//   --oracle pruned  the enumeration with its shortcut and screen (the previous default)
//   --max-valence K  skip fans of more than K triangles (the full enumeration is O(k^3))
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>
#include <vector>

#include "blayer/io/prepare_surface.h"
#include "blayer/normals/most_normal.h"
#include "front_march.h"

namespace {

using namespace blayer;

constexpr double kSameDirection = 1e-7;

struct Options {
  int fronts = 0;
  bool pruned_oracle = false;
  bool free_too = false;
  int max_valence = 1 << 30;
  int show = 10;
};

struct Tally {
  long compared = 0, agree = 0, skipped = 0;
  long status = 0, normality = 0, direction = 0, visibility = 0;
  double worst_d = 0.0, worst_dir = 0.0, worst_v = 0.0;
  std::vector<std::string> examples;
};

int reflex_count(const FanGeometry& g) {
  const int k = g.n_faces();
  int n = 0;
  for (int j = 0; j < k; ++j) n += dot(g.face_normals[(j + k - 1) % k], g.dirs[(j + 1) % k]) < -1e-12 ? 1 : 0;
  return n;
}

void compare(const bench::FrontMarch& m, const Options& opt, bool constrained, Tally* tally) {
  std::mutex lock;
  const double tie = default_tolerances().normality_tie;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m.surface.points.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      FanGeometry g;
                      Tally local;
                      for (std::size_t v = range.begin(); v != range.end(); ++v) {
                        if (!m.closed_fan(v, &g)) continue;
                        if (g.n_faces() > opt.max_valence) {
                          ++local.skipped;
                          continue;
                        }
                        const MostNormalResult a = most_normal_normal(g, default_tolerances(), constrained);
                        const MostNormalResult b =
                            opt.pruned_oracle ? most_normal_by_pruned_enumeration(g, default_tolerances(), constrained)
                                              : most_normal_by_enumeration(g, default_tolerances(), constrained);
                        ++local.compared;
                        const double dd = std::fabs(a.normality - b.normality);
                        const double dir = angle_between(a.normal, b.normal);
                        const double dv = b.visibility - a.visibility;
                        bool ok = true;
                        if (a.status != b.status) {
                          ++local.status;
                          ok = false;
                        }
                        if (dd > tie) {
                          ++local.normality;
                          ok = false;
                        }
                        if (a.status == NormalStatus::kOk && b.status == NormalStatus::kOk) {
                          local.worst_dir = std::max(local.worst_dir, dir);
                          if (dir > kSameDirection) {
                            ++local.direction;
                            ok = false;
                          }
                        } else {
                          local.worst_v = std::max(local.worst_v, dv);
                          if (dv > kSameDirection) {
                            ++local.visibility;
                            ok = false;
                          }
                        }
                        local.worst_d = std::max(local.worst_d, dd);
                        if (ok) {
                          ++local.agree;
                        } else if (static_cast<int>(local.examples.size()) < opt.show) {
                          char line[400];
                          std::snprintf(line, sizeof line,
                                        "    vertex %zu k %d reflex %d: %s D %.12f V %.9f | oracle %s D %.12f V %.9f"
                                        " | angle %.3g",
                                        v, g.n_faces(), reflex_count(g), normal_status_name(a.status), a.normality,
                                        a.visibility, normal_status_name(b.status), b.normality, b.visibility, dir);
                          local.examples.push_back(line);
                        }
                      }
                      std::lock_guard<std::mutex> guard(lock);
                      tally->compared += local.compared;
                      tally->agree += local.agree;
                      tally->skipped += local.skipped;
                      tally->status += local.status;
                      tally->normality += local.normality;
                      tally->direction += local.direction;
                      tally->visibility += local.visibility;
                      tally->worst_d = std::max(tally->worst_d, local.worst_d);
                      tally->worst_dir = std::max(tally->worst_dir, local.worst_dir);
                      tally->worst_v = std::max(tally->worst_v, local.worst_v);
                      for (const std::string& e : local.examples)
                        if (static_cast<int>(tally->examples.size()) < opt.show) tally->examples.push_back(e);
                    });
}

void run(const std::string& path, const Options& opt, long* total_compared, long* total_disagree) {
  TriSurface s = load_surface(path, {}).surface;
  bench::FrontMarch march(s);
  for (int f = 0; f <= opt.fronts; ++f) {
    for (bool constrained : {true, false}) {
      if (!constrained && !opt.free_too) continue;
      Tally t;
      compare(march, opt, constrained, &t);
      std::printf("%s front %d %s: %ld vertices, %ld agree, %ld disagree (status %ld, D %ld, direction %ld, V %ld)"
                  ", %ld skipped; worst |dD| %.2e, worst angle (unique) %.2e, worst V loss %.2e\n",
                  path.c_str(), f, constrained ? "constrained" : "free", t.compared, t.agree, t.compared - t.agree,
                  t.status, t.normality, t.direction, t.visibility, t.skipped, t.worst_d, t.worst_dir, t.worst_v);
      for (const std::string& e : t.examples) std::printf("%s\n", e.c_str());
      std::fflush(stdout);
      *total_compared += t.compared;
      *total_disagree += t.compared - t.agree;
    }
    if (f < opt.fronts) march.advance();
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--fronts" && i + 1 < argc) {
      opt.fronts = std::atoi(argv[++i]);
    } else if (a == "--oracle" && i + 1 < argc) {
      opt.pruned_oracle = std::string(argv[++i]) == "pruned";
    } else if (a == "--free") {
      opt.free_too = true;
    } else if (a == "--max-valence" && i + 1 < argc) {
      opt.max_valence = std::atoi(argv[++i]);
    } else if (a == "--show" && i + 1 < argc) {
      opt.show = std::atoi(argv[++i]);
    } else if (a == "-h" || a == "--help") {
      std::printf("usage: most_normal_agreement [--fronts N] [--oracle full|pruned] [--free] [--max-valence K]"
                  " [--show M] surface...\n");
      return 0;
    } else {
      files.push_back(a);
    }
  }
  long compared = 0, disagree = 0;
  try {
    for (const std::string& f : files) run(f, opt, &compared, &disagree);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("total: %ld vertex solves compared, %ld disagree\n", compared, disagree);
  return 0;
}
