#include "normal_hull.h"

#include <array>
#include <utility>
#include <vector>

#include "blayer/quality/filtered_orient3d.h"

namespace blayer {
namespace detail {

namespace {

using Facet = std::array<int, 3>;

// Whether p lies strictly above the plane of facet t (on the side its winding faces).
bool above(const Vec3* f, const Facet& t, int p) { return orient3d_filtered(f[t[0]], f[t[1]], f[t[2]], f[p]) > 0; }

// A facet of the hull being built, with its plane's minors (every test against it
// shares them, which halves a test's filter).
struct HullFacet {
  Facet t;
  PlaneSides plane;
  HullFacet(const Vec3* f, const Facet& facet) : t(facet), plane(f[facet[0]], f[facet[1]], f[facet[2]]) {}
  // Whether p sees the facet: above(f, t, p), the shared filter first.
  bool seen_by(const Vec3* f, int p) const {
    const int sign = plane.filter(f[p]);
    return (sign != 0 ? sign : orient3d_sign(f[t[0]], f[t[1]], f[t[2]], f[p])) > 0;
  }
};

// The first four points that span a volume, or false. Exact: point 0, the first point b
// apart from it, the first c not on their line, the first d after c off their plane (a c
// on the line has every d on a plane with it; a c off the line with no d off its plane
// leaves every point on one plane).
bool initial_simplex(const Vec3* f, int k, int* s) {
  int b = 1;
  while (b < k && f[b] == f[0]) ++b;
  for (int c = b + 1; c < k; ++c)
    for (int d = c + 1; d < k; ++d)
      if (orient3d_filtered(f[0], f[b], f[c], f[d]) != 0) {
        s[0] = 0;
        s[1] = b;
        s[2] = c;
        s[3] = d;
        return true;
      }
  return false;
}

// The simplex's four facets, each wound away from the fourth point.
void simplex_facets(const Vec3* f, const int* s, std::vector<Facet>* out) {
  out->clear();
  for (int t = 0; t < 4; ++t) {
    Facet face{s[t], s[(t + 1) % 4], s[(t + 2) % 4]};
    if (above(f, face, s[(t + 3) % 4])) std::swap(face[1], face[2]);
    out->push_back(face);
  }
}

bool is_simplex_point(const int* s, int p) { return p == s[0] || p == s[1] || p == s[2] || p == s[3]; }

// Whether the points have a hull with volume: at least four, finite (the exact predicate
// assumes finite coordinates), not all on one plane; *s receives the first simplex.
bool spans_volume(const Vec3* f, int k, int* s) {
  if (k < 4) return false;
  for (int i = 0; i < k; ++i)
    if (!is_finite(f[i])) return false;
  return initial_simplex(f, k, s);
}

}  // namespace

bool normal_hull_facets_by_sweep(const Vec3* f, int k, std::vector<std::array<int, 3>>* facets) {
  facets->clear();
  int s[4];
  if (!spans_volume(f, k, s)) return false;
  thread_local std::vector<Facet> start;
  thread_local std::vector<HullFacet> hull, kept;
  simplex_facets(f, s, &start);
  hull.clear();
  for (const Facet& t : start) hull.emplace_back(f, t);
  thread_local std::vector<std::array<int, 2>> rim;  // edges of the facets the point sees
  for (int p = 0; p < k; ++p) {
    if (is_simplex_point(s, p)) continue;
    kept.clear();
    rim.clear();
    for (const HullFacet& h : hull) {
      if (h.seen_by(f, p)) {
        const Facet& t = h.t;
        rim.push_back({t[0], t[1]});
        rim.push_back({t[1], t[2]});
        rim.push_back({t[2], t[0]});
      } else {
        kept.push_back(h);
      }
    }
    if (rim.empty()) continue;
    // The horizon: edges of seen facets whose twin belongs to a facet not seen.
    for (const auto& [u, v] : rim) {
      bool inner = false;
      for (const auto& [x, y] : rim) inner = inner || (x == v && y == u);
      if (!inner) kept.emplace_back(f, Facet{u, v, p});
    }
    hull.swap(kept);
  }
  for (const HullFacet& h : hull) facets->push_back(h.t);
  return true;
}

namespace {

// The hull of normal_hull_facets with conflicts: every point not added yet is filed
// under one facet it sees, or under none once it lies inside (the hull only grows, so
// it stays inside). Adding a point removes the facets it sees, found from its own facet
// across their edges (they form one patch: seen from inside, the facets a point sees are
// the vertices of the polar polytope beyond one plane, and those are joined by its
// edges, as the simplex method's walk shows), and files the points of the removed facets
// under the new ones. That is exact: a point above a removed facet that sees none of the
// new ones lies inside the grown hull (a point above the removed facet's plane and
// outside the hull leaves the hull through the part of its surface above that plane,
// which only new facets make up). The points are added in index order, each exactly when
// it sees a facet of the hull of those before it, as in the sweep: the same facets.
class ConflictHull {
 public:
  // The hull of f[0..k) from the simplex s; false where a patch's rim is not one cycle
  // (the sweep then answers). One per thread: its arrays are kept from fan to fan.
  bool build(const Vec3* f, int k, const int* s, std::vector<std::array<int, 3>>* out);

 private:
  struct Node {
    HullFacet facet;
    std::array<int, 3> across{-1, -1, -1};  // the facet beyond edge (t[e], t[e + 1])
    int points = -1;            // the first point filed under it
    bool alive = true;
    Node(const Vec3* f, const Facet& t) : facet(f, t) {}
  };

  bool sees(int facet, int p) const { return nodes_[facet].facet.seen_by(f_, p); }
  void file(int p, int facet) {
    next_point_[p] = nodes_[facet].points;
    nodes_[facet].points = p;
    facet_of_[p] = facet;
  }
  // Files p under the first of facets [first, last) it sees, or as inside.
  void file_among(int p, int first, int last) {
    for (int t = first; t < last; ++t)
      if (sees(t, p)) return file(p, t);
    facet_of_[p] = -1;
  }
  int edge_towards(int facet, int u, int v) const {
    const Facet& t = nodes_[facet].facet.t;
    for (int e = 0; e < 3; ++e)
      if (t[e] == u && t[(e + 1) % 3] == v) return e;
    return -1;
  }
  bool add(int p);

  const Vec3* f_ = nullptr;
  int k_ = 0;
  std::vector<Node> nodes_;
  std::vector<int> facet_of_, next_point_;
  std::vector<int> patch_, mark_;
  std::vector<std::array<int, 3>> rim_;  // u, v, the facet beyond: the patch's rim edges
  std::vector<int> from_, to_;           // per point: the new facet whose rim edge starts / ends there
  int stamp_ = 0;
};

bool ConflictHull::build(const Vec3* f, int k, const int* s, std::vector<std::array<int, 3>>* out) {
  f_ = f;
  k_ = k;
  nodes_.clear();
  mark_.clear();
  stamp_ = 0;
  thread_local std::vector<Facet> start;
  simplex_facets(f_, s, &start);
  for (const Facet& t : start) nodes_.emplace_back(f_, t);
  for (int a = 0; a < 4; ++a)
    for (int e = 0; e < 3; ++e) {
      const Facet& t = nodes_[a].facet.t;
      const int u = t[e], v = t[(e + 1) % 3];
      for (int b = 0; b < 4; ++b)
        if (b != a && edge_towards(b, v, u) >= 0) nodes_[a].across[e] = b;
    }
  facet_of_.assign(k_, -1);
  next_point_.assign(k_, -1);
  from_.assign(k_, -1);
  to_.assign(k_, -1);
  for (int p = 0; p < k_; ++p)
    if (!is_simplex_point(s, p)) file_among(p, 0, 4);
  for (int p = 0; p < k_; ++p)
    if (facet_of_[p] >= 0 && !add(p)) return false;
  out->clear();
  for (const Node& n : nodes_)
    if (n.alive) out->push_back(n.facet.t);
  return true;
}

bool ConflictHull::add(int p) {
  // The patch of facets p sees, from its own across the edges.
  ++stamp_;
  mark_.resize(nodes_.size(), 0);
  patch_.assign(1, facet_of_[p]);
  mark_[facet_of_[p]] = stamp_;
  rim_.clear();
  for (std::size_t i = 0; i < patch_.size(); ++i) {
    const int a = patch_[i];
    for (int e = 0; e < 3; ++e) {
      const int b = nodes_[a].across[e];
      if (mark_[b] == stamp_) continue;
      if (mark_[b] != -stamp_ && sees(b, p)) {
        mark_[b] = stamp_;
        patch_.push_back(b);
      } else {
        mark_[b] = -stamp_;
        rim_.push_back({nodes_[a].facet.t[e], nodes_[a].facet.t[(e + 1) % 3], b});
      }
    }
  }
  // A cone over the rim, from p: the rim must be one cycle.
  const int first_new = static_cast<int>(nodes_.size());
  for (const auto& [u, v, beyond] : rim_) {
    if (from_[u] >= first_new || to_[v] >= first_new) return false;
    const int id = static_cast<int>(nodes_.size());
    from_[u] = id;
    to_[v] = id;
    nodes_.emplace_back(f_, Facet{u, v, p});
    const int e = edge_towards(beyond, v, u);
    if (e < 0) return false;
    nodes_[beyond].across[e] = id;
    nodes_[id].across[0] = beyond;
  }
  for (int id = first_new; id < static_cast<int>(nodes_.size()); ++id) {
    const int u = nodes_[id].facet.t[0], v = nodes_[id].facet.t[1];
    if (from_[v] < first_new || to_[u] < first_new) return false;
    nodes_[id].across[1] = from_[v];  // edge (v, p): the new facet leaving v
    nodes_[id].across[2] = to_[u];    // edge (p, u): the new facet arriving at u
  }
  // The points of the removed facets, filed anew.
  const int last_new = static_cast<int>(nodes_.size());
  for (const int a : patch_) {
    nodes_[a].alive = false;
    for (int q = nodes_[a].points; q >= 0;) {
      const int next = next_point_[q];
      if (q != p) file_among(q, first_new, last_new);
      q = next;
    }
  }
  facet_of_[p] = -1;
  return true;
}

}  // namespace

bool normal_hull_facets(const Vec3* f, int k, std::vector<std::array<int, 3>>* facets) {
  facets->clear();
  int s[4];
  if (!spans_volume(f, k, s)) return false;
  thread_local ConflictHull hull;
  if (hull.build(f, k, s, facets)) return true;
  return normal_hull_facets_by_sweep(f, k, facets);
}

}  // namespace detail
}  // namespace blayer
