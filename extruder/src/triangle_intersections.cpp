#include "blayer/extruder/triangle_intersections.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "blayer/extruder/triangle_bvh.h"
#include "blayer/quality/filtered_orient3d.h"

namespace blayer {

namespace {

using Vec2 = std::array<double, 2>;

// The corners after corner k of a triangle, in order: a table, where (k + 1) % 3 costs
// a division in the hottest paths of the pair test.
constexpr int kNext[3] = {1, 2, 0};
constexpr int kAfterNext[3] = {2, 0, 1};

// 2D orientations from the 3D predicates: lifting the points to z = 0 and taking the
// apex (0,0,1) makes det[b-a, c-a, d-a] equal to the 2D determinant, with no rounding in
// the lifted coordinates.
Vec3 lifted(const Vec2& a) { return {a[0], a[1], 0.0}; }
const Vec3 kApex{0.0, 0.0, 1.0};

// Exact.
int orient2d(const Vec2& a, const Vec2& b, const Vec2& c) {
  return detail::orient3d_filtered(lifted(a), lifted(b), lifted(c), kApex);
}

// Where the floating-point filter certifies the sign, else 0 ("cannot decide").
int orient2d_filter(const Vec2& a, const Vec2& b, const Vec2& c) {
  return detail::orient3d_filter(lifted(a), lifted(b), lifted(c), kApex);
}

// c lies on the closed segment ab, given that a, b, c are collinear.
bool on_segment_collinear(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= c[1] &&
         c[1] <= std::max(a[1], b[1]);
}

bool segments_intersect_2d(const Vec2& p, const Vec2& q, const Vec2& a, const Vec2& b) {
  const int o1 = orient2d(p, q, a), o2 = orient2d(p, q, b), o3 = orient2d(a, b, p), o4 = orient2d(a, b, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  if (o1 == 0 && on_segment_collinear(p, q, a)) return true;
  if (o2 == 0 && on_segment_collinear(p, q, b)) return true;
  if (o3 == 0 && on_segment_collinear(a, b, p)) return true;
  if (o4 == 0 && on_segment_collinear(a, b, q)) return true;
  return false;
}

bool point_in_triangle_2d(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  const int o1 = orient2d(a, b, p), o2 = orient2d(b, c, p), o3 = orient2d(c, a, p);
  return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

// Projection indices (i, j) that drop the dominant axis of triangle abc's normal.
void projection_axes(const Vec3& a, const Vec3& b, const Vec3& c, int* i, int* j) {
  const Vec3 n = cross(b - a, c - a);
  int drop = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(n[k]) > std::fabs(n[drop])) drop = k;
  *i = kNext[drop];
  *j = kAfterNext[drop];
}

bool coplanar_segment_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  // Drop the dominant axis of the normal: any axis with a non-zero normal component
  // keeps the projection one-to-one, so a rounded normal is good enough to choose it.
  int i, j;
  projection_axes(a, b, c, &i, &j);
  const Vec2 P{p[i], p[j]}, Q{q[i], q[j]}, A{a[i], a[j]}, B{b[i], b[j]}, C{c[i], c[j]};
  if (point_in_triangle_2d(P, A, B, C) || point_in_triangle_2d(Q, A, B, C)) return true;
  return segments_intersect_2d(P, Q, A, B) || segments_intersect_2d(P, Q, B, C) || segments_intersect_2d(P, Q, C, A);
}

// Are c and d strictly on the same side of line ab, in the projection that drops the
// dominant axis of triangle abc's normal? For d coplanar with abc, the same side in the
// plane.
bool coplanar_same_side(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  int i, j;
  projection_axes(a, b, c, &i, &j);
  const Vec2 A{a[i], a[j]}, B{b[i], b[j]}, C{c[i], c[j]}, D{d[i], d[j]};
  return orient2d(A, B, C) * orient2d(A, B, D) > 0;
}

// Triangles (v, sa, sb) and (v, ta, tb) sharing only v, in the projection that drops
// the dominant axis of the first's normal, with orientation predicate `orient`. When
// the two are coplanar, near v each fills its angle at v and lies inside it, so they
// share a point other than v iff the two closed angles share a ray, i.e. iff a side ray
// of one lies in the other. A ray v x lies in the closed angle (v; a, b) of orientation o
// iff o * orient(v, a, x) >= 0 and o * orient(v, x, b) >= 0: the ray opposite a side
// fails the other test. Returns false in *decided when either projection is flat (a
// triangle of zero area: its sides were zero without the two being coplanar), for the
// edge tests to decide. With orient2d_filter, whose 0 means "cannot decide", an
// undecided sign counts as flat or as inside: "decided and not meeting" stays certain.
template <class Orient>
bool corner_angles_meet(Orient&& orient, const Vec3& v, const Vec3& sa, const Vec3& sb, const Vec3& ta,
                        const Vec3& tb, bool* decided) {
  int i, j;
  projection_axes(v, sa, sb, &i, &j);
  const Vec2 V{v[i], v[j]}, SA{sa[i], sa[j]}, SB{sb[i], sb[j]}, TA{ta[i], ta[j]}, TB{tb[i], tb[j]};
  const int os = orient(V, SA, SB), ot = orient(V, TA, TB);
  *decided = os != 0 && ot != 0;
  if (!*decided) return false;
  auto in_angle = [&](const Vec2& a, const Vec2& b, int o, const Vec2& x) {
    return o * orient(V, a, x) >= 0 && o * orient(V, x, b) >= 0;
  };
  return in_angle(SA, SB, os, TA) || in_angle(SA, SB, os, TB) || in_angle(TA, TB, ot, SA) || in_angle(TA, TB, ot, SB);
}

bool coplanar_corner_angles_meet(const Vec3& v, const Vec3& sa, const Vec3& sb, const Vec3& ta, const Vec3& tb,
                                 bool* decided) {
  return corner_angles_meet(orient2d, v, sa, sb, ta, tb, decided);
}

// Certificates of disjointness for the pairs whose plane tests the filter cannot decide:
// the nearly coplanar neighbours of a flat stretch of front, which would otherwise go to
// the exact predicate several times per pair. Both project the two triangles along the
// dominant axis of the first's normal and certify, with the filter alone, that the
// projections share no point (no point beyond the shared corner v). A common point of
// the triangles would project to a common point of the projections, so the triangles are
// then disjoint (beyond v), whether or not they are coplanar. False means "not
// certified", never "they meet": the exact tests decide then.

// No shared corner: the line of an edge of one projection has the other projection
// strictly on its far side (two disjoint convex polygons always have such an edge).
bool edge_line_separates(const Vec2* p, const Vec2* q) {
  for (int k = 0; k < 3; ++k) {
    const Vec2& a = p[k];
    const Vec2& b = p[kNext[k]];
    const int own = orient2d_filter(a, b, p[kAfterNext[k]]);
    if (own != 0 && orient2d_filter(a, b, q[0]) == -own && orient2d_filter(a, b, q[1]) == -own &&
        orient2d_filter(a, b, q[2]) == -own)
      return true;
  }
  return false;
}

bool projections_apart(const Vec3* const* s, const Vec3* const* t) {
  int i, j;
  projection_axes(*s[0], *s[1], *s[2], &i, &j);
  const Vec2 S[3] = {{(*s[0])[i], (*s[0])[j]}, {(*s[1])[i], (*s[1])[j]}, {(*s[2])[i], (*s[2])[j]}};
  const Vec2 T[3] = {{(*t[0])[i], (*t[0])[j]}, {(*t[1])[i], (*t[1])[j]}, {(*t[2])[i], (*t[2])[j]}};
  return edge_line_separates(S, T) || edge_line_separates(T, S);
}

// Triangles (v, sa, sb) and (v, ta, tb) sharing corner v: both projections have non-zero
// area and each side ray of one lies strictly outside the other's angle at v, so the
// angles (and the projections in them) share only v's projection. A common point x of
// the triangles other than v would then project onto v's, i.e. x - v would be parallel
// to the dropped axis; the first triangle holds no such segment, its normal having a
// non-zero component along that axis (its projection has area).
bool corner_angles_apart(const Vec3& v, const Vec3& sa, const Vec3& sb, const Vec3& ta, const Vec3& tb) {
  bool decided;
  const bool meet = corner_angles_meet(orient2d_filter, v, sa, sb, ta, tb, &decided);
  return decided && !meet;
}

// The sides of *p[0..n) against the plane abc, as orient3d_sides gives them, except
// where the filter cannot decide one: a disjointness certificate is asked first, once
// per pair (*tried records it). True when the certificate holds: the pair is disjoint
// and `side` is left unsettled.
template <class Certificate>
bool sides_or_certified_apart(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3* const* p, int n, int* side,
                              bool* tried, Certificate&& certified_apart) {
  if (detail::orient3d_sides_filter(a, b, c, p, n, side)) return false;
  if (!*tried) {
    *tried = true;
    if (certified_apart()) return true;
  }
  detail::orient3d_sides_settle(a, b, c, p, n, side);
  return false;
}

// segment_intersects_triangle given the orientations of p and q against the plane abc.
bool segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c,
                            const int* side);

// All three signs equal and non-zero: the triangle lies strictly on one side of the plane.
bool strictly_one_side(int a, int b, int c) { return a != 0 && a == b && a == c; }

// The corner whose side differs from the other two, given three non-zero sides that are
// not all equal.
int lone_corner(const int* side) { return side[1] == side[2] ? 0 : side[0] == side[2] ? 1 : 2; }

// Two triangles each of which crosses the other's plane with no corner on it (all six
// sides non-zero, mixed on both triangles). Each then meets the line L where the planes
// cross in a closed segment, and the triangles meet iff those segments overlap; two
// orientations order their ends along L (the test of Devillers and Guigue, 2002).
// Name the corners so that p1 is alone on the positive side of the plane (p2, q2, r2)
// and p2 alone on the positive side of (p1, q1, r1): a circular shift keeps a triangle's
// orientation, and swapping its last two corners flips the side of the other's lone
// corner. Let i1, i2 be where p1q1 and p1r1 cross L, j1, j2 where p2q2 and p2r2 do, and
// l = n_s x n_t the direction of L. Then
//   det[q1 - p1, p2 - p1, q2 - p1] = (positive) * l.(j1 - i1),
// since q1 - p1 and q2 - p2 point from the positive sides into the other plane; and
// l.(i2 - i1) < 0 < l.(j2 - j1) for non-degenerate triangles (expand i1, i2 as points of
// the edges: l.(i2 - i1) is minus a square that vanishes only when q1 - p1 and r1 - p1
// are parallel). So s covers [i2, i1] and t covers [j1, j2] along L, and they overlap
// iff l.(j1 - i1) <= 0 and l.(j2 - i2) >= 0: two exact orientations instead of up to 18
// in the edge tests.
bool crossing_triangles_meet(const Vec3* const* s, const Vec3* const* t, const int* s_side, const int* t_side) {
  const int i = lone_corner(s_side), j = lone_corner(t_side);
  const Vec3& p1 = *s[i];
  const Vec3& p2 = *t[j];
  const Vec3* q1 = s[kNext[i]];
  const Vec3* r1 = s[kAfterNext[i]];
  const Vec3* q2 = t[kNext[j]];
  const Vec3* r2 = t[kAfterNext[j]];
  if (s_side[i] < 0) std::swap(q2, r2);
  if (t_side[j] < 0) std::swap(q1, r1);
  return detail::orient3d_filtered(p1, *q1, p2, *q2) <= 0 && detail::orient3d_filtered(p1, *r1, p2, *r2) >= 0;
}

bool no_zero(const int* side) { return side[0] != 0 && side[1] != 0 && side[2] != 0; }

// Triangles (v, sa, sb) and (v, ta, tb) sharing only v, where sa and sb lie strictly on
// opposite sides of the plane of the second and ta and tb of the first. Each then meets
// the line L where the planes cross in a segment from v: [v, i] with i strictly inside
// sa sb, [v, j] with j strictly inside ta tb; they meet beyond v iff i and j lie on the
// same side of v. In the second's plane, the ray from v through j is on tb's side of the
// line v ta (j lies strictly between ta and tb), and the opposite ray on the other side
// (L is not that line: ta is off the first plane). The plane through v, ta, sa crosses
// the second's plane in that line (sa is off it), so sides of that line there are sides
// of this plane; and i = sa + m (sb - sa) with m > 0 is on the side of sb. Two
// orientations instead of up to six in the edge tests.
bool crossing_at_shared_corner(const Vec3& v, const Vec3& sa, const Vec3& sb, const Vec3& ta, const Vec3& tb) {
  return detail::orient3d_filtered(v, ta, sa, sb) == detail::orient3d_filtered(v, ta, sa, tb);
}

bool triangles_intersect(const Vec3* const* s, const Vec3* const* t) {
  // A triangle strictly on one side of the other's plane cannot meet it. This settles
  // almost every pair of nearby front triangles with 3 or 6 orientations instead of up
  // to 30 in the edge tests below, which decide the remaining pairs.
  // The edge tests reuse these sides of the edges' ends.
  // Where the filter cannot decide a side, the projections are tried before the exact
  // predicate (projections_apart), once.
  int s_side[3], t_side[3];
  bool tried = false;
  auto apart = [&] { return projections_apart(s, t); };
  if (sides_or_certified_apart(*t[0], *t[1], *t[2], s, 3, s_side, &tried, apart)) return false;
  if (strictly_one_side(s_side[0], s_side[1], s_side[2])) return false;
  if (sides_or_certified_apart(*s[0], *s[1], *s[2], t, 3, t_side, &tried, apart)) return false;
  if (strictly_one_side(t_side[0], t_side[1], t_side[2])) return false;
  if (no_zero(s_side) && no_zero(t_side)) return crossing_triangles_meet(s, t, s_side, t_side);
  for (int k = 0; k < 3; ++k) {
    const int l = kNext[k];
    const int s_ends[2] = {s_side[k], s_side[l]}, t_ends[2] = {t_side[k], t_side[l]};
    if (segment_meets_triangle(*s[k], *s[l], *t[0], *t[1], *t[2], s_ends)) return true;
    if (segment_meets_triangle(*t[k], *t[l], *s[0], *s[1], *s[2], t_ends)) return true;
  }
  return false;
}

}  // namespace

bool segment_intersects_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3* const ends[2] = {&p, &q};
  int side[2];
  detail::orient3d_sides(a, b, c, ends, 2, side);
  return segment_meets_triangle(p, q, a, b, c, side);
}

namespace {

bool segment_meets_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c,
                            const int* side) {
  const int sp = side[0], sq = side[1];
  if (sp == 0 && sq == 0) return coplanar_segment_triangle(p, q, a, b, c);
  if (sp * sq > 0) return false;
  // The line pq crosses the plane within the segment; it meets the closed triangle iff
  // it passes on the same side of (or touches) all three edges.
  const int o1 = detail::orient3d_filtered(p, q, a, b), o2 = detail::orient3d_filtered(p, q, b, c);
  if (o1 * o2 < 0) return false;  // already on opposite sides of two edges
  const int o3 = detail::orient3d_filtered(p, q, c, a);
  return (o1 >= 0 && o2 >= 0 && o3 >= 0) || (o1 <= 0 && o2 <= 0 && o3 <= 0);
}

}  // namespace

namespace {

template <class Triangle3>
bool soup_pair_intersects(const std::vector<Vec3>& pts, const Triangle3& s, const Triangle3& t) {
  if (names_a_point_twice(s) || names_a_point_twice(t)) return false;  // else more than 3 shared pairs could be counted
  int shared_s[3], shared_t[3], n_shared = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (s[i] == t[j]) {
        shared_s[n_shared] = i;
        shared_t[n_shared] = j;
        ++n_shared;
      }
  if (n_shared >= 3) return false;
  if (n_shared == 2) {
    const int os = 3 - shared_s[0] - shared_s[1], ot = 3 - shared_t[0] - shared_t[1];
    const Vec3& a = pts[s[shared_s[0]]];
    const Vec3& b = pts[s[shared_s[1]]];
    const Vec3& c = pts[s[os]];
    const Vec3& d = pts[t[ot]];
    // A fold iff the four points are coplanar and c and d lie on the same side of the
    // line ab in that plane. The filter settles almost every pair as not coplanar; where
    // it cannot (a flat stretch of front), the side test in the projection comes before
    // the exact predicate: c and d apart there means no fold, coplanar or not.
    if (detail::orient3d_filter(a, b, c, d) != 0) return false;
    return coplanar_same_side(a, b, c, d) && orient3d_sign(a, b, c, d) == 0;
  }
  if (n_shared == 1) {
    const int is = shared_s[0], it = shared_t[0];
    const Vec3& sa = pts[s[kNext[is]]];
    const Vec3& sb = pts[s[kAfterNext[is]]];
    const Vec3& ta = pts[t[kNext[it]]];
    const Vec3& tb = pts[t[kAfterNext[it]]];
    const Vec3& v = pts[s[is]];
    // A triangle whose far edge lies strictly on one side of the other's plane meets it
    // at v alone: the first plane test settles most neighbours of a front.
    const Vec3* const s_far[2] = {&sa, &sb};
    const Vec3* const t_far[2] = {&ta, &tb};
    // Where the filter cannot decide a side, the angles at v in the projection are tried
    // before the exact predicate (corner_angles_apart), once.
    int s_side[2], t_side[2];
    bool tried = false;
    auto apart = [&] { return corner_angles_apart(v, sa, sb, ta, tb); };
    if (sides_or_certified_apart(v, ta, tb, s_far, 2, s_side, &tried, apart)) return false;
    if (s_side[0] * s_side[1] > 0) return false;
    if (sides_or_certified_apart(v, sa, sb, t_far, 2, t_side, &tried, apart)) return false;
    if (t_side[0] * t_side[1] > 0) return false;
    if (s_side[0] * s_side[1] < 0 && t_side[0] * t_side[1] < 0) return crossing_at_shared_corner(v, sa, sb, ta, tb);
    if (s_side[0] == 0 && s_side[1] == 0 && t_side[0] == 0 && t_side[1] == 0) {
      bool decided;
      const bool meet = coplanar_corner_angles_meet(v, sa, sb, ta, tb, &decided);
      if (decided) return meet;
    }
    return segment_meets_triangle(sa, sb, v, ta, tb, s_side) || segment_meets_triangle(ta, tb, v, sa, sb, t_side);
  }
  const Vec3* const S[3] = {&pts[s[0]], &pts[s[1]], &pts[s[2]]};
  const Vec3* const T[3] = {&pts[t[0]], &pts[t[1]], &pts[t[2]]};
  return triangles_intersect(S, T);
}

}  // namespace

bool soup_triangles_intersect(const std::vector<Vec3>& pts, const IndexedTriangle& s, const IndexedTriangle& t) {
  return soup_pair_intersects(pts, s, t);
}

bool compact_soup_triangles_intersect(const std::vector<Vec3>& pts, const SoupTriangle& s, const SoupTriangle& t) {
  return soup_pair_intersects(pts, s, t);
}

bool order_star_ring(std::int32_t v, const std::array<std::int32_t, 2>* triangles, int n,
                     std::vector<std::int32_t>* ring, bool* closed) {
  ring->clear();
  if (n == 0) return false;
  thread_local std::vector<std::array<std::int32_t, 2>> e;
  thread_local std::vector<std::int32_t> ends;
  e.assign(triangles, triangles + n);
  ends.clear();
  for (const auto& [a, b] : e)
    if (a == v || b == v || a == b) return false;
  std::sort(e.begin(), e.end());
  for (int i = 0; i < n; ++i) {
    if (i > 0 && e[i][0] == e[i - 1][0]) return false;  // two triangles after one point
    ends.push_back(e[i][1]);
  }
  std::sort(ends.begin(), ends.end());
  if (std::adjacent_find(ends.begin(), ends.end()) != ends.end()) return false;  // two before one point
  // A path starts at the one point no triangle ends at; a cycle anywhere.
  std::int32_t first = e[0][0];
  for (const auto& ab : e)
    if (!std::binary_search(ends.begin(), ends.end(), ab[0])) {
      first = ab[0];
      break;
    }
  auto next = [&](std::int32_t a) {
    const auto it = std::lower_bound(e.begin(), e.end(), std::array<std::int32_t, 2>{a, INT32_MIN});
    return it != e.end() && (*it)[0] == a ? (*it)[1] : -1;
  };
  ring->push_back(first);
  for (int steps = 0; steps < n; ++steps) {
    const std::int32_t p = next(ring->back());
    if (p < 0) return false;  // the path ended before taking every triangle
    if (p == first) {
      *closed = true;
      return steps == n - 1;  // a cycle through every triangle
    }
    ring->push_back(p);
  }
  *closed = false;
  return true;  // n triangles from the path's first point: all of them
}

bool star_pairs_meet_only_at_centre(const std::vector<Vec3>& points, std::int32_t v, const std::int32_t* ring,
                                    int m, bool closed) {
  const int n = closed ? m : m - 1;  // the triangles: (ring[i], ring[i + 1]), wrapping when closed
  if (n < 2) return true;
  // A point named twice, or v in the ring, needs no test of its own: the second time
  // the ring reaches a direction it has turned a full turn, and v gives a zero area.
  const Vec3& c = points[v];
  Vec3 area{0.0, 0.0, 0.0};
  for (int t = 0; t < n; ++t) area += cross(points[ring[t]] - c, points[ring[(t + 1) % m]] - c);
  // The projection runs along e = q - c, exact whatever q is: the orientation of the
  // projected (c, a, b) is the sign of det[a - c, b - c, e], i.e. orient3d(c, a, b, q).
  // The rounded vector area, scaled to the ring's size, only chooses a direction that
  // likely leaves every triangle an area (an axis would not: a CAD edge's two faces at 90
  // degrees, one of them parallel to the axis nearest their mean).
  const double area_norm = norm(area), reach = norm(points[ring[0]] - c);
  if (!(area_norm > 0.0) || !(reach > 0.0) || !std::isfinite(area_norm + reach)) return false;
  const Vec3 q = c + (reach / area_norm) * area;
  auto orientation = [&](const Vec3& a, const Vec3& b) { return detail::orient3d_filter(c, a, b, q); };
  const Vec3& x = points[ring[0]];
  const int sign = orientation(x, points[ring[1]]);
  if (sign == 0) return false;
  // side: the orientation of (c, ring[t], x). Triangle t holds x's direction in its
  // closed angle iff sign * side(t) >= 0 and sign * side(t + 1) <= 0.
  const Vec3* a = &x;
  int side_a = 0;
  for (int t = 0; t < n; ++t) {
    const int r = (t + 1) % m;
    const Vec3& b = points[ring[r]];
    if (orientation(*a, b) != sign) return false;
    const int side_b = r == 0 ? 0 : orientation(b, x);
    const bool at_first = t == 0 || r == 0;
    if (!at_first && side_a != -sign && side_b != sign) return false;
    a = &b;
    side_a = side_b;
  }
  return true;
}

std::vector<std::pair<int, int>> find_triangle_intersections(const std::vector<Vec3>& points,
                                                             const std::vector<IndexedTriangle>& triangles,
                                                             const std::vector<char>* check, std::size_t max_pairs) {
  const int n = static_cast<int>(triangles.size());
  // With the slabs that rule out most pairs of long thin triangles (diagonal_slabs.h).
  TriangleBvh bvh;
  bvh.build_triangles(n, [&](int i, Vec3* c) {
    for (int k = 0; k < 3; ++k) c[k] = points[triangles[i][k]];
  });
  // Each unordered pair with a flagged triangle is tested once, found by descending the
  // tree against itself (TriangleBvh); pairs of unflagged triangles are not tested.
  const std::vector<char> flagged = check ? *check : std::vector<char>(n, 1);
  std::vector<char> flagged_nodes;
  bvh.mark_nodes(flagged, &flagged_nodes);
  tbb::enumerable_thread_specific<std::vector<std::pair<int, int>>> found;
  bvh.for_each_overlapping_pair(flagged, flagged_nodes, [&](int i, int j) {
    if (soup_triangles_intersect(points, triangles[i], triangles[j])) found.local().emplace_back(std::min(i, j), std::max(i, j));
  });
  std::vector<std::pair<int, int>> pairs;
  for (const auto& l : found) pairs.insert(pairs.end(), l.begin(), l.end());
  std::sort(pairs.begin(), pairs.end());
  if (pairs.size() > max_pairs) pairs.resize(max_pairs);
  return pairs;
}

}  // namespace blayer
