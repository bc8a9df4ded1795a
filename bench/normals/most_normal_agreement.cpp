// most_normal_agreement [--fronts N] [--oracle full|pruned] [--free] [--max-valence K] [--show M]
//                       [--cad N] surface ...
// The default most-normal solver against an enumeration on every closed vertex of each
// surface and of N simulated offset fronts (front_march.h), and with --cad on N
// generated CAD-like fans per shape, valence 20-60 (tests/normals/cad_fans.h),
// constrained (the default) and, with --free, also without the visibility constraint.
// Agreement is the rule of tests/normals/agreement.h: the same status, D within
// normality_tie, the same direction (1e-7) or V not lower, except where the oracle's
// answer, or the maximiser that makes its status non-unique, is a point of the tie band
// that is not a genuine maximiser (counted apart as "through the tie band"). Prints the
// counts, the worst differences and the first M disagreements.
//   --oracle full    the unpruned enumeration (default; slow on fans of valence > 100)
//   --oracle pruned  the enumeration with its shortcut and screen (the previous default)
//   --max-valence K  skip fans of more than K triangles (the full enumeration is O(k^3))
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include "agreement.h"
#include "blayer/io/prepare_surface.h"
#include "blayer/normals/most_normal.h"
#include "cad_fans.h"
#include "front_march.h"
#include "test_fans.h"

namespace {

using namespace blayer;

struct Options {
  int fronts = 0;
  bool pruned_oracle = false;
  bool free_too = false;
  int max_valence = 1 << 30;
  int show = 10;
};

struct Tally {
  long compared = 0, agree = 0, skipped = 0;
  long status = 0, tie_band = 0, near_degenerate = 0, above = 0, below = 0;
  double worst_d = 0.0, worst_dir = 0.0, worst_v = 0.0;
  std::vector<std::string> examples;
};

int reflex_count(const FanGeometry& g) {
  const int k = g.n_faces();
  int n = 0;
  for (int j = 0; j < k; ++j) n += dot(g.face_normals[(j + k - 1) % k], g.dirs[(j + 1) % k]) < -1e-12 ? 1 : 0;
  return n;
}

// Compares the solvers on fans 0 .. n-1 of `fan(v, &g)` (false: no closed fan there).
template <class FanOf>
void compare(std::size_t n, FanOf&& fan, const Options& opt, bool constrained, Tally* tally) {
  std::mutex lock;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      FanGeometry g;
                      Tally local;
                      for (std::size_t v = range.begin(); v != range.end(); ++v) {
                        if (!fan(v, &g)) continue;
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
                        const testing_fans::Agreement verdict = testing_fans::compare_optimum(g, constrained, a, b);
                        const bool ok = verdict.ok;
                        if (a.status != b.status) ++local.status;
                        if (a.normality > b.normality + default_tolerances().normality_tie) ++local.above;
                        if (a.normality < b.normality - default_tolerances().normality_tie) ++local.below;
                        if (verdict.through_tie_band) ++local.tie_band;
                        if (verdict.near_degenerate) ++local.near_degenerate;
                        if (a.status == NormalStatus::kOk && b.status == NormalStatus::kOk) {
                          local.worst_dir = std::max(local.worst_dir, dir);
                        } else {
                          local.worst_v = std::max(local.worst_v, dv);
                        }
                        local.worst_d = std::max(local.worst_d, dd);
                        if (ok) {
                          ++local.agree;
                        } else if (static_cast<int>(local.examples.size()) < opt.show) {
                          char line[600];
                          std::snprintf(line, sizeof line, "    vertex %zu k %d reflex %d: %s", v, g.n_faces(),
                                        reflex_count(g), verdict.why.c_str());
                          local.examples.push_back(line);
                        }
                      }
                      std::lock_guard<std::mutex> guard(lock);
                      tally->compared += local.compared;
                      tally->agree += local.agree;
                      tally->skipped += local.skipped;
                      tally->status += local.status;
                      tally->tie_band += local.tie_band;
                      tally->near_degenerate += local.near_degenerate;
                      tally->above += local.above;
                      tally->below += local.below;
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
      compare(
          march.surface.points.size(), [&](std::size_t v, FanGeometry* g) { return march.closed_fan(v, g); }, opt,
          constrained, &t);
      std::printf("%s front %d %s: %ld vertices, %ld agree (%ld through the tie band, %ld near-degenerate, %ld"
                  " statuses differ), %ld disagree (D beyond the tie: %ld above the oracle, %ld below), %ld skipped;"
                  " worst |dD| %.2e, worst angle (both ok) %.2e, worst V below oracle %.2e\n",
                  path.c_str(), f, constrained ? "constrained" : "free", t.compared, t.agree, t.tie_band,
                  t.near_degenerate, t.status, t.compared - t.agree, t.above, t.below, t.skipped, t.worst_d,
                  t.worst_dir, t.worst_v);
      for (const std::string& e : t.examples) std::printf("%s\n", e.c_str());
      std::fflush(stdout);
      *total_compared += t.compared;
      *total_disagree += t.compared - t.agree;
    }
    if (f < opt.fronts) march.advance();
  }
}

// CAD-like fans of valence 20-60, n per shape and valence, exact planes and offsets of
// 1e-5 and 1e-3 of the edge length.
void run_cad(int n, const Options& opt, long* total_compared, long* total_disagree) {
  std::vector<FanGeometry> fans;
  std::mt19937 rng(60606);
  testing_fans::for_each_cad_fan(rng, {20, 30, 40, 50, 60}, n,
                                 [&](FanGeometry g, const std::string&) { fans.push_back(std::move(g)); });
  for (bool constrained : {true, false}) {
    if (!constrained && !opt.free_too) continue;
    Tally t;
    compare(
        fans.size(),
        [&](std::size_t v, FanGeometry* g) {
          *g = fans[v];
          return true;
        },
        opt, constrained, &t);
    std::printf("CAD-like fans %s: %ld fans, %ld agree (%ld through the tie band, %ld near-degenerate, %ld statuses"
                " differ), %ld disagree (D beyond the tie: %ld above the oracle, %ld below), %ld skipped; worst |dD|"
                " %.2e, worst angle (both ok) %.2e, worst V below oracle %.2e\n",
                constrained ? "constrained" : "free", t.compared, t.agree, t.tie_band, t.near_degenerate, t.status,
                t.compared - t.agree, t.above, t.below, t.skipped, t.worst_d, t.worst_dir, t.worst_v);
    for (const std::string& e : t.examples) std::printf("%s\n", e.c_str());
    std::fflush(stdout);
    *total_compared += t.compared;
    *total_disagree += t.compared - t.agree;
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options opt;
  int cad = 0;
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
    } else if (a == "--cad" && i + 1 < argc) {
      cad = std::atoi(argv[++i]);
    } else if (a == "-h" || a == "--help") {
      std::printf("usage: most_normal_agreement [--fronts N] [--oracle full|pruned] [--free] [--max-valence K]"
                  " [--show M] [--cad N] surface...\n");
      return 0;
    } else {
      files.push_back(a);
    }
  }
  long compared = 0, disagree = 0;
  try {
    if (cad > 0) run_cad(cad, opt, &compared, &disagree);
    for (const std::string& f : files) run(f, opt, &compared, &disagree);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  std::printf("total: %ld vertex solves compared, %ld disagree\n", compared, disagree);
  return 0;
}
