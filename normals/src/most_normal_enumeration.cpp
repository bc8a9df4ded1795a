#include "most_normal_enumeration.h"

#include <cmath>
#include <numeric>
#include <vector>

#include "candidate_families.h"
#include "recycled_vector.h"
#include "sphere_solvers.h"

namespace blayer {
namespace detail {

namespace {

// Margin of the cheap cosine pre-test of CandidatePool::evaluate (a few ulps).
constexpr double kCheapTestMargin = 1e-15;

// Level above the rejection bound at which the great-circle screen
// (circle_screened_off) requires a link vertex, and the rounding allowance of its
// computed boundary points: the candidates it discards lie within ~1e-15 of the circle,
// so each is still beyond the bound by ~1e-12, and a boundary point it computes is
// within 1e-15 of the exact one, well inside 1e-14.
constexpr double kCircleLevel = 1e-12;
constexpr double kCircleRounding = 1e-14;

struct Subsets {
  RecycledVector<int> points, arcs;
  SiteSubset all;
  explicit Subsets(const FanSites& s) {
    points.resize(s.points.size());
    arcs.resize(s.arcs.size());
    std::iota(points.begin(), points.end(), 0);
    std::iota(arcs.begin(), arcs.end(), 0);
    all = {points.data(), static_cast<int>(points.size()), arcs.data(), static_cast<int>(arcs.size())};
  }
};

// Whether every candidate on the great circle {n.h = 0} (h unit) would be rejected by
// the pool at its current threshold thr, so that a whole family of candidates on that
// bisector need not be built. Proof: u_j is a link point, so D(n) <= angle(n, u_j), and
// n.u_j > cos(thr) + kCheapTestMargin makes the computed D(n) < thr (the arc ending at
// u_j is at most angle(n, u_j) away; the margin covers rounding; see
// CandidatePool::evaluate). The threshold only rises during the enumeration, so a
// candidate rejected now is rejected when its turn comes. The sets
// G_j = {n on the circle : n.u_j > lambda}, lambda = cos(thr) + kCheapTestMargin +
// kCircleLevel, are open arcs; if they do not cover the circle, some component of the
// uncovered part has a boundary point p on the boundary of one G_j with p.u_i <= lambda
// for all i, which is found below (its computed image is within rounding of p, so the
// test at lambda + kCircleRounding sees it uncovered). When no such point is found, every
// n on the circle has n.u_j > lambda for some j, and every candidate within 1e-13 of the
// circle has n.u_j > cos(thr) + kCheapTestMargin.
bool circle_screened_off(const CandidatePool& pool, const Vec3& h) {
  const double thr = pool.threshold();
  if (!(thr > 0.0)) return false;
  const double lambda = std::cos(thr) + kCheapTestMargin + kCircleLevel;
  Vec3 e1, e2;
  orthonormal_complement(h, &e1, &e2);
  const std::vector<Vec3>& dirs = pool.geometry().dirs;
  const int k = static_cast<int>(dirs.size());
  constexpr int kMaxVertices = 64;
  if (k > kMaxVertices) return false;
  double a[kMaxVertices], b[kMaxVertices];
  for (int j = 0; j < k; ++j) {
    a[j] = dot(dirs[j], e1);
    b[j] = dot(dirs[j], e2);
  }
  bool any_arc = false;
  for (int j = 0; j < k; ++j) {
    const double r2 = a[j] * a[j] + b[j] * b[j];
    // G_j empty (r <= lambda) or the whole circle (r < -lambda, lambda < 0).
    if (lambda >= 0.0 && r2 <= lambda * lambda) continue;
    if (lambda < 0.0 && r2 < lambda * lambda) return true;
    any_arc = true;
    // Boundary points: (x, y) with a x + b y = lambda on the unit circle.
    const double q = std::sqrt(std::max(0.0, r2 - lambda * lambda));
    for (double sign : {1.0, -1.0}) {
      const double x = (lambda * a[j] - sign * q * b[j]) / r2;
      const double y = (lambda * b[j] + sign * q * a[j]) / r2;
      bool covered = false;
      for (int i = 0; i < k && !covered; ++i) covered = a[i] * x + b[i] * y > lambda + kCircleRounding;
      if (!covered) return false;
    }
  }
  return any_arc;
}

// The great-circle screen of the enumeration (circle_screened_off).
struct CircleScreen : NoScreen {
  const CandidatePool* pool;
  bool on;
  bool circle(const Vec3& h) const { return on && circle_screened_off(*pool, h); }
};

// Both the great-circle and the generator screens.
struct FullScreen {
  const CandidatePool* pool;
  ArcReachScreen reach;
  bool circle(const Vec3& h) const { return circle_screened_off(*pool, h); }
  bool arc(const Vec3& h, const Vec3& g) const { return reach.arc(h, g); }
  bool arc_pair(const Vec3& a, const Vec3& b) const { return reach.arc_pair(a, b); }
  bool point_ok(const Vec3& x, const Vec3& w) const { return reach.point_ok(x, w); }
  bool arc_ok(const Vec3& x, const Vec3& g) const { return reach.arc_ok(x, g); }
};

}  // namespace

void enumerate_unconstrained(const FanSites& s, bool screen, CandidatePool* pool) {
  const Subsets sub(s);
  auto emit = [pool](const Vec3& n) { pool->consider(n); };
  CircleScreen circles;
  circles.pool = pool;
  circles.on = screen;
  single_and_pair_candidates(s, sub.all, NoScreen{}, emit);
  triple_candidates(s, sub.all, circles, emit);
}

void enumerate_screened(const FanSites& s, CandidatePool* pool) {
  const Subsets sub(s);
  auto emit = [pool](const Vec3& n) { pool->consider(n); };
  const FullScreen screen{pool, ArcReachScreen(*pool)};
  single_and_pair_candidates(s, sub.all, screen, emit);
  triple_candidates(s, sub.all, screen, emit);
}

void enumerate_constraint_circles(const FanSites& s, CandidatePool* pool) {
  pool->begin_constrained_pass();
  const Subsets sub(s);
  const FanGeometry& g = pool->geometry();
  std::vector<int> faces(g.n_faces());
  std::iota(faces.begin(), faces.end(), 0);
  constraint_candidates(g, s, sub.all, faces.data(), g.n_faces(), pool->v_min(),
                        [pool](const Vec3& n) { pool->consider(n); });
}

void enumerate_plateau_peaks(const FanSites& s, CandidatePool* pool) {
  std::vector<int> faces(pool->geometry().n_faces());
  std::iota(faces.begin(), faces.end(), 0);
  enumerate_plateau_peaks(s, pool, faces);
}

void enumerate_plateau_peaks(const FanSites& s, CandidatePool* pool, const std::vector<int>& faces) {
  const Subsets sub(s);
  std::vector<PlateauCircle> circles;
  plateau_circles(s, sub.all, pool->tolerances().normality_tie, pool->best_constrained(), &circles);
  const FanGeometry& g = pool->geometry();
  std::vector<double> ca, cb, cc;
  const int n = static_cast<int>(faces.size());
  for (const PlateauCircle& c : circles)
    plateau_peaks(g, c, faces.data(), n, &ca, &cb, &cc, [pool](const Vec3& n) { pool->consider(n); });
}

}  // namespace detail
}  // namespace blayer
