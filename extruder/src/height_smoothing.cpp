#include "blayer/extruder/height_smoothing.h"

#include "parallel.h"

namespace blayer {

void smooth_downward(const Csr& nbr, const std::vector<char>& mask, int rings, std::vector<double>* f,
                     std::vector<StopReason>* reason) {
  if (rings <= 0) return;
  const double slope = 1.0 / (rings + 1);
  const int n = static_cast<int>(f->size());
  std::vector<double> g(*f);
  std::vector<StopReason> rg(*reason);
  for (int r = 0; r < rings; ++r) {
    parallel_vertices(n, [&](int v) {
      if (!mask[v]) return;
      double m = (*f)[v];
      StopReason why = (*reason)[v];
      bool lowered = false;  // by a neighbour: a tie with the point's own value keeps its reason
      for (const int* u = nbr.begin(v); u != nbr.end(v); ++u) {
        if (!mask[*u]) continue;
        const double bound = (*f)[*u] + slope;
        if (bound < m) {
          m = bound;
          why = (*reason)[*u];
          lowered = true;
        } else if (lowered && bound == m && (*reason)[*u] < why) {
          why = (*reason)[*u];  // a tie between neighbours: their order must not decide it
        }
      }
      g[v] = m;
      rg[v] = why;
    });
    f->swap(g);
    reason->swap(rg);
    g = *f;
    rg = *reason;
  }
}

}  // namespace blayer
