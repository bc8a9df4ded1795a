#include "blayer/extruder/height_smoothing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "parallel.h"

namespace blayer {

namespace {

struct Bound {
  double value;
  StopReason reason;
  bool lowered;  // below the point's own value, by a neighbour
};

// One Jacobi pass at masked point v, from the values and reasons of the pass before.
Bound bound_at(int v, const Csr& nbr, const std::vector<char>& mask, double slope, const std::vector<double>& f,
               const std::vector<StopReason>& reason) {
  Bound b{f[v], reason[v], false};  // a tie with the point's own value keeps its reason
  for (const int* u = nbr.begin(v); u != nbr.end(v); ++u) {
    if (!mask[*u]) continue;
    const double bound = f[*u] + slope;
    if (bound < b.value) {
      b = {bound, reason[*u], true};
    } else if (b.lowered && bound == b.value && reason[*u] < b.reason) {
      b.reason = reason[*u];  // a tie between neighbours: their order must not decide it
    }
  }
  return b;
}

// Every point in every pass.
void all_point_passes(const Csr& nbr, const std::vector<char>& mask, int rings, double slope, std::vector<double>* f,
                      std::vector<StopReason>* reason) {
  const int n = static_cast<int>(f->size());
  std::vector<double> g(*f);
  std::vector<StopReason> rg(*reason);
  for (int r = 0; r < rings; ++r) {
    parallel_vertices(n, [&](int v) {
      if (!mask[v]) return;
      const Bound b = bound_at(v, nbr, mask, slope, *f, *reason);
      g[v] = b.value;
      rg[v] = b.reason;
    });
    f->swap(g);
    reason->swap(rg);
    g = *f;
    rg = *reason;
  }
}

// Below this share of low points (1 in kFewLow), the passes visit only the points
// around them.
constexpr int kFewLow = 8;

}  // namespace

void smooth_downward(const Csr& nbr, const std::vector<char>& mask, int rings, std::vector<double>* f,
                     std::vector<StopReason>* reason) {
  if (rings <= 0) return;
  const double slope = 1.0 / (rings + 1);
  const int n = static_cast<int>(f->size());
  // The first pass lowers a point only under a neighbour more than the slope below it,
  // so more than the slope below the largest value: a low point. A later pass changes
  // only the neighbours of points the pass before lowered: a point whose neighbours kept
  // their values and reasons is already at most each of their bounds, and a tie leaves
  // its reason. The repair attempts lower a few columns of the front: their passes then
  // visit those columns' rings, not every column (NaN values neither lower nor are
  // lowered, in either form).
  double top = -HUGE_VAL;
  for (int v = 0; v < n; ++v)
    if (mask[v]) top = std::max(top, (*f)[v]);
  std::vector<int> sources;
  for (int v = 0; v < n; ++v)
    if (mask[v] && (*f)[v] + slope < top) sources.push_back(v);
  if (static_cast<std::int64_t>(sources.size()) * kFewLow >= n) {
    all_point_passes(nbr, mask, rings, slope, f, reason);
    return;
  }
  std::vector<int> seen(n, -1), candidates;
  std::vector<std::pair<int, Bound>> lowered;
  for (int r = 0; r < rings && !sources.empty(); ++r) {
    candidates.clear();
    for (const int u : sources)
      for (const int* w = nbr.begin(u); w != nbr.end(u); ++w)
        if (mask[*w] && seen[*w] != r) {
          seen[*w] = r;
          candidates.push_back(*w);
        }
    lowered.clear();
    for (const int v : candidates) {
      const Bound b = bound_at(v, nbr, mask, slope, *f, *reason);
      if (b.lowered) lowered.emplace_back(v, b);
    }
    sources.clear();
    for (const auto& [v, b] : lowered) {
      (*f)[v] = b.value;
      (*reason)[v] = b.reason;
      sources.push_back(v);
    }
  }
}

}  // namespace blayer
