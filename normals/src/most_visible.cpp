#include "blayer/normals/most_visible.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <vector>

#include "normal_hull.h"

namespace blayer {

namespace {

// Slack of the supporting-plane and multiplier tests. Entries are products of unit
// vectors rounded at ~1e-16; 1e-13 leaves a thousandfold margin, and a support accepted
// within it moves V* by at most ~1e-13 / V* (in Wolfe's certificate, x.x - f.x): below
// 1e-12 for V* above 0.1, 2e-12 on the face normals of a pole 3 degrees from flat.
constexpr double kSupportSlack = 1e-13;

// Relative pivot below which a Gram system is singular (affinely dependent points): the
// entries carry ~1e-16 rounding, so a relative determinant of 1e-14 has lost all but two
// digits.
constexpr double kSingularGram = 1e-14;

constexpr int kMaxWolfeSteps = 64;

// Min-norm point of the affine hull of m <= 4 points: weights alpha (sum 1) with
// x = sum alpha_i P_i. Returns false when the points are affinely dependent.
bool affine_min_norm(const Vec3* const* pts, int m, double* alpha) {
  if (m == 1) {
    alpha[0] = 1.0;
    return true;
  }
  const int n = m - 1;
  Vec3 d[3];
  for (int i = 0; i < n; ++i) d[i] = *pts[i + 1] - *pts[0];
  double a[3][4];
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) a[i][j] = dot(d[i], d[j]);
    a[i][n] = -dot(d[i], *pts[0]);
  }
  double diag = 1.0;
  for (int i = 0; i < n; ++i) diag *= a[i][i];
  if (!(diag > 0.0)) return false;
  // Gaussian elimination with partial pivoting on the n x n normal equations.
  double det = 1.0;
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[piv][c])) piv = r;
    if (piv != c)
      for (int j = 0; j <= n; ++j) std::swap(a[c][j], a[piv][j]);
    det *= a[c][c];
    if (a[c][c] == 0.0) return false;
    for (int r = c + 1; r < n; ++r) {
      const double fct = a[r][c] / a[c][c];
      for (int j = c; j <= n; ++j) a[r][j] -= fct * a[c][j];
    }
  }
  if (std::fabs(det) <= kSingularGram * diag) return false;
  double beta[3];
  for (int r = n - 1; r >= 0; --r) {
    double s = a[r][n];
    for (int j = r + 1; j < n; ++j) s -= a[r][j] * beta[j];
    beta[r] = s / a[r][r];
  }
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    alpha[i + 1] = beta[i];
    sum += beta[i];
  }
  alpha[0] = 1.0 - sum;
  return true;
}

// Wolfe's step when the support s[0..n-1] (n = 2 or 3) and the new point j are affinely
// dependent (the nearly coplanar normals of a pole, nearly collinear ones): the
// min-norm point of their hull, which does not contain the origin, lies on a face
// through j (the face s[0..n-1] holds the current point, which j improves on): the
// triangles {j, a, b}, the edges {j, a} or j itself, whichever has the smallest norm
// with positive weights. Writes the new support and weights; false when no face gives
// one (singular faces only).
// Cold and out of line: kept out of Wolfe's loop, which it slowed by 13 % when inlined.
[[gnu::cold, gnu::noinline]] bool min_norm_face_through(const Vec3* f, const int* s, int n, int j, int* s_out,
                                                         double* w_out, int* m_out) {
  double best = std::numeric_limits<double>::infinity();
  auto consider = [&](std::initializer_list<int> face) {
    const int m = static_cast<int>(face.size());
    const Vec3* pts[3];
    int ids[3];
    int i = 0;
    for (int id : face) {
      ids[i] = id;
      pts[i++] = &f[id];
    }
    double alpha[4];
    if (!affine_min_norm(pts, m, alpha)) return;
    Vec3 x{0.0, 0.0, 0.0};
    for (i = 0; i < m; ++i) {
      if (!(alpha[i] > 0.0)) return;
      x += alpha[i] * *pts[i];
    }
    if (!(norm2(x) < best)) return;
    best = norm2(x);
    *m_out = m;
    for (i = 0; i < m; ++i) {
      s_out[i] = ids[i];
      w_out[i] = alpha[i];
    }
  };
  consider({j});
  for (int a = 0; a < n; ++a) consider({j, s[a]});
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) consider({j, s[a], s[b]});
  return best < std::numeric_limits<double>::infinity();
}

double min_dot(const Vec3* f, int k, const Vec3& x) {
  double v = std::numeric_limits<double>::infinity();
  for (int j = 0; j < k; ++j) v = std::min(v, dot(f[j], x));
  return v;
}

bool certified(const Vec3* f, int k, const Vec3& q) {
  const double qq = norm2(q);
  for (int j = 0; j < k; ++j)
    if (dot(f[j], q) < qq - kSupportSlack) return false;
  return true;
}

MostVisibleResult finish_feasible(const Vec3* f, int k, const Vec3& q, int support, const Tolerances& tol) {
  const double len = norm(q);
  if (!(len >= tol.min_visibility)) return best_margin_direction(f, k);
  MostVisibleResult r;
  r.normal = q / len;
  // V* = |q*| in exact arithmetic; the directly evaluated minimum is what callers see.
  r.visibility = min_dot(f, k, r.normal);
  r.feasible = r.visibility >= tol.min_visibility;
  r.support_size = support;
  return r;
}

}  // namespace

namespace {

// The largest margin min_j n.f_j among the candidate directions offered, each in both
// signs. Each candidate names its place in the enumeration's order (its rank, then +
// before - within it), so that it may be offered in any order: of equal margins the
// earliest place wins. A margin is a minimum of the same products whatever their
// order, so the faces named as hints (those that likely hold the candidate's minimum:
// a facet's own corners for its inward normal) are tried first, then the face that
// stopped the previous candidate, then all: the candidate is abandoned as soon as it
// can no longer win, with the same answer.
class MarginSearch {
 public:
  MarginSearch(const Vec3* f, int k) : f_(f), k_(k) {}
  void consider(const Vec3& c, std::uint64_t rank, std::initializer_list<int> hints) {
    const double len = norm(c);
    if (!(len > 0.0)) return;
    const Vec3 n[2] = {c / len, -c / len};
    for (int sign = 0; sign < 2; ++sign) {
      const std::uint64_t place = 2 * rank + static_cast<std::uint64_t>(sign);
      // Still able to win with margin v: above the best, or equal to it and earlier.
      auto can_win = [&](double v) { return v > best_v_ || (v == best_v_ && place < best_place_); };
      double v = std::numeric_limits<double>::infinity();
      for (int j : hints) v = std::min(v, dot(f_[j], n[sign]));
      v = std::min(v, dot(f_[last_stop_], n[sign]));
      for (int j = 0; j < k_ && can_win(v); ++j) {
        v = std::min(v, dot(f_[j], n[sign]));
        if (!can_win(v)) last_stop_ = j;
      }
      if (can_win(v)) {
        best_v_ = v;
        best_place_ = place;
        best_n_ = n[sign];
      }
    }
  }
  MostVisibleResult result() const {
    MostVisibleResult r;
    r.normal = best_n_;
    r.visibility = k_ == 1 ? 1.0 : best_v_;
    r.feasible = false;
    return r;
  }

 private:
  const Vec3* f_;
  int k_;
  int last_stop_ = 0;
  double best_v_ = -std::numeric_limits<double>::infinity();
  std::uint64_t best_place_ = std::numeric_limits<std::uint64_t>::max();
  Vec3 best_n_{0.0, 0.0, 0.0};
};

}  // namespace

MostVisibleResult best_margin_direction_by_enumeration(const Vec3* f, int k) {
  MarginSearch search(f, k);
  std::uint64_t rank = 0;  // the candidates come in the enumeration's order
  for (int a = 0; a < k; ++a) {
    search.consider(f[a], rank++, {a});
    for (int b = a + 1; b < k; ++b) {
      search.consider(f[a] + f[b], rank++, {a, b});
      // A great circle through both normals: the margin directions of a flat hull.
      search.consider(cross(f[a], f[b]), rank++, {a, b});
      for (int c = b + 1; c < k; ++c) search.consider(cross(f[b] - f[a], f[c] - f[a]), rank++, {a, b, c});
    }
  }
  return search.result();
}

namespace {

// A hull feature's place in the order in which the enumeration over every vertex, pair
// and triple meets it: a vertex (a, -1, -1), an edge (a, b, -1), a facet (a, b, c),
// a < b < c, ordered as triples (-1 first). As an integer, (a + 1, b + 1, c + 1) packed
// into 21 bits each: the same order (ids are below 2^21 - 1), at a fraction of the
// comparisons' cost.
std::uint64_t feature_rank(int a, int b, int c) {
  return (std::uint64_t(a + 1) << 42) | (std::uint64_t(b + 1) << 21) | std::uint64_t(c + 1);
}

// The features of a triangulated hull, as (a, b, c) keys in the enumeration's order,
// distinct.
void hull_feature_keys(const std::vector<std::array<int, 3>>& facets, std::vector<std::array<int, 3>>* keys) {
  thread_local std::vector<std::uint64_t> packed;
  packed.clear();
  for (std::array<int, 3> t : facets) {
    std::sort(t.begin(), t.end());
    if (t[0] == t[1] || t[1] == t[2]) continue;
    for (const std::uint64_t key :
         {feature_rank(t[0], t[1], t[2]), feature_rank(t[0], t[1], -1), feature_rank(t[0], t[2], -1),
          feature_rank(t[1], t[2], -1), feature_rank(t[0], -1, -1), feature_rank(t[1], -1, -1),
          feature_rank(t[2], -1, -1)})
      packed.push_back(key);
  }
  std::sort(packed.begin(), packed.end());
  packed.erase(std::unique(packed.begin(), packed.end()), packed.end());
  constexpr std::uint64_t kField = (std::uint64_t(1) << 21) - 1;
  keys->clear();
  for (const std::uint64_t key : packed)
    keys->push_back({static_cast<int>(key >> 42) - 1, static_cast<int>((key >> 21) & kField) - 1,
                     static_cast<int>(key & kField) - 1});
}

}  // namespace

// The optimum is -(the unit outward normal of the hull facet nearest to the origin) when
// the origin lies inside conv{f_i} or on its boundary (the support function's least
// value on the sphere is the distance to the nearest facet plane), and the direction of
// the hull's point nearest to the origin otherwise: a facet normal, or an edge's
// midpoint f_a + f_b (the normals are unit; a vertex f_a is nearest only when every
// normal equals it, which spans no volume). So the enumeration's candidates built from
// the hull's edges and facets suffice; the vertices are offered too, each ranked by its
// place in the enumeration's order, so that of equal margins the enumeration's first
// wins unless its winner was a candidate off the hull (equal to rounding).
MostVisibleResult best_margin_direction(const Vec3* f, int k) {
  thread_local std::vector<std::array<int, 3>> facets;
  if (!detail::normal_hull_facets(f, k, &facets)) return best_margin_direction_by_enumeration(f, k);
  // The candidates in any order, each with its feature_rank: every vertex, each edge
  // once (from the facet that runs it upwards), each facet by its sorted corners.
  MarginSearch search(f, k);
  for (int a = 0; a < k; ++a) search.consider(f[a], feature_rank(a, -1, -1), {a});
  for (std::array<int, 3> t : facets) {
    for (int e = 0; e < 3; ++e) {
      const int u = t[e], v = t[(e + 1) % 3];
      if (u < v) search.consider(f[u] + f[v], feature_rank(u, v, -1), {u, v});
    }
    std::sort(t.begin(), t.end());
    if (t[0] == t[1] || t[1] == t[2]) continue;
    search.consider(cross(f[t[1]] - f[t[0]], f[t[2]] - f[t[0]]), feature_rank(t[0], t[1], t[2]), {t[0], t[1], t[2]});
  }
  return search.result();
}

namespace {

// The distinct normals (closer than tol.duplicate_normal merged), in input order.
std::vector<Vec3> distinct_normals(const Vec3* f, int k, const Tolerances& tol) {
  std::vector<Vec3> u;
  u.reserve(k);
  for (int i = 0; i < k; ++i) {
    bool dup = false;
    for (const Vec3& w : u) dup |= norm(f[i] - w) < tol.duplicate_normal;
    if (!dup) u.push_back(f[i]);
  }
  return u;
}

// The certified min-norm point among the supports offered (|S| <= 3): the smallest
// |q|^2, the first of equal ones.
class SupportSearch {
 public:
  explicit SupportSearch(const std::vector<Vec3>& u) : u_(u) {}
  void offer(std::initializer_list<int> s) {
    const Vec3* pts[3] = {nullptr, nullptr, nullptr};  // s holds 1 to 3 indices
    int n = 0;
    for (int i : s) pts[n++] = &u_[i];
    double lambda[3];
    if (!affine_min_norm(pts, n, lambda)) return;
    Vec3 q{0.0, 0.0, 0.0};
    for (int i = 0; i < n; ++i) {
      if (lambda[i] < -kSupportSlack) return;
      q += lambda[i] * *pts[i];
    }
    const double qq = norm2(q);
    if (qq >= best_) return;
    if (!certified(u_.data(), static_cast<int>(u_.size()), q)) return;
    best_ = qq;
    best_q_ = q;
    support_ = n;
  }
  // The answer of the supports offered, or best_margin_direction without a certified one.
  MostVisibleResult finish(const Vec3* f, int k, const Tolerances& tol) const {
    if (support_ == 0) return best_margin_direction(f, k);
    return finish_feasible(f, k, best_q_, support_, tol);
  }

 private:
  const std::vector<Vec3>& u_;
  double best_ = std::numeric_limits<double>::infinity();
  Vec3 best_q_{0.0, 0.0, 0.0};
  int support_ = 0;
};

}  // namespace

MostVisibleResult most_visible_by_enumeration(const Vec3* f, int k, const Tolerances& tol) {
  const std::vector<Vec3> u = distinct_normals(f, k, tol);
  const int m = static_cast<int>(u.size());
  SupportSearch search(u);
  for (int a = 0; a < m; ++a) {
    search.offer({a});
    for (int b = a + 1; b < m; ++b) {
      search.offer({a, b});
      for (int c = b + 1; c < m; ++c) search.offer({a, b, c});
    }
  }
  return search.finish(f, k, tol);
}

MostVisibleResult most_visible_on_hull(const Vec3* f, int k, const Tolerances& tol) {
  const std::vector<Vec3> u = distinct_normals(f, k, tol);
  thread_local std::vector<std::array<int, 3>> facets;
  if (!detail::normal_hull_facets(u.data(), static_cast<int>(u.size()), &facets))
    return most_visible_by_enumeration(f, k, tol);
  // In the enumeration's order, so that the first of equal |q| is the enumeration's
  // unless its winner was a support off the hull (equal to rounding).
  thread_local std::vector<std::array<int, 3>> keys;
  hull_feature_keys(facets, &keys);
  SupportSearch search(u);
  for (const auto& [a, b, c] : keys) {
    if (b < 0) {
      search.offer({a});
    } else if (c < 0) {
      search.offer({a, b});
    } else {
      search.offer({a, b, c});
    }
  }
  return search.finish(f, k, tol);
}

WolfeOutcome wolfe_min_norm_point(const Vec3* f, int k, const Tolerances& tol, MostVisibleResult* out) {
  int s[4] = {0, 0, 0, 0};
  double w[4] = {1.0, 0.0, 0.0, 0.0};
  int m = 1;
  Vec3 x = f[0];
  for (int step = 0; step < kMaxWolfeSteps; ++step) {
    int j = 0;
    double fx = dot(f[0], x);
    for (int l = 1; l < k; ++l) {
      const double d = dot(f[l], x);
      if (d < fx) {
        fx = d;
        j = l;
      }
    }
    const double xx = norm2(x);
    if (fx >= xx - kSupportSlack) {
      const double len = norm(x);
      if (!(len >= tol.min_visibility)) return WolfeOutcome::kNoVisibleDirection;
      out->normal = x / len;
      // V* = |q*| in exact arithmetic; the directly evaluated minimum is what callers see.
      out->visibility = min_dot(f, k, out->normal);
      out->feasible = out->visibility >= tol.min_visibility;
      out->support_size = m;
      return WolfeOutcome::kCertified;
    }
    if (xx < tol.min_visibility * tol.min_visibility) return WolfeOutcome::kNoVisibleDirection;
    bool in_s = false;
    for (int i = 0; i < m; ++i) in_s |= s[i] == j;
    if (in_s || m == 4) break;
    s[m] = j;
    w[m] = 0.0;
    ++m;
    for (bool just_added = true;; just_added = false) {
      const Vec3* pts[4];
      for (int i = 0; i < m; ++i) pts[i] = &f[s[i]];
      double alpha[4];
      if (!affine_min_norm(pts, m, alpha)) {
        // Right after adding the new point s[m - 1] to a support of two or three: the
        // face through it. Anything else stays uncertified (for the hull).
        if (!just_added || m < 3) return WolfeOutcome::kUncertified;
        int face[3];
        double weights[3];
        int n = 0;
        if (!min_norm_face_through(f, s, m - 1, s[m - 1], face, weights, &n)) return WolfeOutcome::kUncertified;
        for (int i = 0; i < 4; ++i) {
          s[i] = i < n ? face[i] : 0;
          w[i] = i < n ? weights[i] : 0.0;
        }
        m = n;
        break;
      }
      bool positive = true;
      for (int i = 0; i < m; ++i) positive &= alpha[i] > 0.0;
      if (positive) {
        for (int i = 0; i < m; ++i) w[i] = alpha[i];
        break;
      }
      // Move from w towards alpha until the first weight reaches zero, then drop it.
      double theta = 1.0;
      int drop = -1;
      for (int i = 0; i < m; ++i)
        if (alpha[i] <= 0.0) {
          const double t = w[i] / (w[i] - alpha[i]);
          if (t < theta || drop < 0) {
            theta = t;
            drop = i;
          }
        }
      for (int i = 0; i < m; ++i) w[i] = (1.0 - theta) * w[i] + theta * alpha[i];
      w[drop] = 0.0;
      int n = 0;
      for (int i = 0; i < m; ++i)
        if (w[i] > 0.0) {
          s[n] = s[i];
          w[n] = w[i];
          ++n;
        }
      m = n;
      if (m == 0) return WolfeOutcome::kUncertified;
    }
    x = Vec3{0.0, 0.0, 0.0};
    for (int i = 0; i < m; ++i) x += w[i] * f[s[i]];
    // A full-dimensional simplex with positive weights contains the origin.
    if (m == 4) return WolfeOutcome::kNoVisibleDirection;
  }
  return WolfeOutcome::kUncertified;
}

MostVisibleResult most_visible_normal(const Vec3* f, int k, const Tolerances& tol) {
  MostVisibleResult r;
  switch (wolfe_min_norm_point(f, k, tol, &r)) {
    case WolfeOutcome::kCertified: return r;
    case WolfeOutcome::kNoVisibleDirection: return best_margin_direction(f, k);
    case WolfeOutcome::kUncertified: break;
  }
  // Where Wolfe's iteration stays uncertified (its step limit), the enumeration would try
  // C(k, 3) supports; the hull's supports give its answer in O(k^2) after the hull.
  return most_visible_on_hull(f, k, tol);
}

}  // namespace blayer
