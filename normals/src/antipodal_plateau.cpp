#include "antipodal_plateau.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>
#include <vector>

#include "candidate_families.h"

namespace blayer {
namespace detail {

namespace {

// Link vertices this close to antipodal (|u_a + u_b|) form a pair: exactly antipodal
// data carries ~1e-16 of rounding, and the bound then exceeds pi/2 by at most 5e-13 rad,
// three orders inside normality_tie.
constexpr double kAntipodal = 1e-12;

// A link vertex whose projection on C's plane is shorter than this lies on the axis: it
// is at pi/2 from every direction of C to that, so it leaves no half-circle condition
// (the candidates are evaluated exactly whatever is left out).
constexpr double kOnAxis = 1e-12;

// A widest gap short of pi by at most this still holds the single direction opposite it:
// the rounding of the projections' angles.
constexpr double kGapRounding = 1e-12;

}  // namespace

bool antipodal_plateau_settles(CandidatePool* pool) {
  const FanGeometry& g = pool->geometry();
  // The most nearly antipodal pair: by the first coordinate, sorted, each vertex meets
  // only the few whose coordinate is nearly its opposite (O(k log k) instead of all pairs).
  thread_local std::vector<std::pair<double, int>> by_x;
  by_x.clear();
  for (int i = 0; i < static_cast<int>(g.dirs.size()); ++i) by_x.push_back({g.dirs[i][0], i});
  std::sort(by_x.begin(), by_x.end());
  int a = -1, b = -1;
  double closest = kAntipodal * kAntipodal;
  for (const auto& [x, i] : by_x) {
    auto j = std::lower_bound(by_x.begin(), by_x.end(), std::pair<double, int>{-x - kAntipodal, -1});
    for (; j != by_x.end() && j->first <= -x + kAntipodal; ++j) {
      if (j->second <= i) continue;  // each pair once, and never a vertex with itself
      const double gap2 = norm2(g.dirs[i] + g.dirs[j->second]);
      if (gap2 <= closest) {
        closest = gap2;
        a = i;
        b = j->second;
      }
    }
  }
  if (a < 0) return false;
  // C and its parameter t, as the envelope sweep takes them: n(t) = cos t e1 + sin t e2.
  const PlateauCircle circle{normalized(g.dirs[a] - g.dirs[b]), 0.0};
  CircleFrame frame;
  if (!circle_frame(circle, &frame)) return false;
  const Vec3 &e1 = frame.e1, &e2 = frame.e2;
  // The link vertices projected on C's plane, as angles.
  thread_local std::vector<double> angles;
  angles.clear();
  for (const Vec3& u : g.dirs) {
    const double x = dot(u, e1), y = dot(u, e2);
    if (std::hypot(x, y) > kOnAxis) angles.push_back(std::atan2(y, x));
  }
  if (angles.empty()) return false;
  std::sort(angles.begin(), angles.end());
  // Directions opposite a gap of pi or more between the projections: those of
  // t in [from + pi/2, from + gap - pi/2] for the gap from angle `from`. Two gaps can reach
  // pi only when the projections lie on one line; each then holds a single direction.
  auto offer = [&](const Vec3& n) { pool->consider(n); };
  thread_local std::vector<int> faces;  // every face bounds V
  thread_local std::vector<double> ca, cb, cc;
  faces.resize(g.n_faces());
  std::iota(faces.begin(), faces.end(), 0);
  const int m = static_cast<int>(angles.size());
  for (int i = 0; i < m; ++i) {
    const double from = angles[(i + m - 1) % m];
    const double gap = i == 0 ? angles[0] + 2.0 * M_PI - angles[m - 1] : angles[i] - angles[i - 1];
    if (gap < M_PI - kGapRounding) continue;
    const double mid = from + 0.5 * gap, half = 0.5 * std::max(0.0, gap - M_PI);
    if (half > 0.0) {
      envelope_peaks_between(g, circle, faces.data(), g.n_faces(), mid - half, mid + half, &ca, &cb, &cc, offer);
    } else {
      offer(std::cos(mid) * e1 + std::sin(mid) * e2);
    }
  }
  const double bound = 0.5 * M_PI + std::asin(std::min(1.0, 0.5 * std::sqrt(closest)));
  const double reached = bound - pool->tolerances().normality_tie;
  if (pool->best_unconstrained() >= reached) pool->settle_unconstrained();
  return pool->best_constrained() >= reached && !pool->limited();
}

}  // namespace detail
}  // namespace blayer
