#include "blayer/quality/cell_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "cell_faces.h"

namespace blayer {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadToDeg = 180.0 / kPi;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Corner tets (node, then its three edge-neighbours in positive order). These are the
// corner entries of cell_validity.cpp's validity tets.
constexpr std::array<int, 4> kTetCorners[] = {{0, 1, 2, 3}, {1, 2, 0, 3}, {2, 0, 1, 3}, {3, 0, 2, 1}};
constexpr std::array<int, 4> kPyramidCorners[] = {{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}};
constexpr std::array<int, 4> kWedgeCorners[] = {{0, 2, 1, 3}, {1, 0, 2, 4}, {2, 1, 0, 5},
                                                {3, 4, 5, 0}, {4, 5, 3, 1}, {5, 3, 4, 2}};
constexpr std::array<int, 4> kHexCorners[] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                              {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};

double triple(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

// A squared length in [1e-150, 1e150]: products of two such vectors' components neither
// overflow nor lose digits to underflow.
bool moderate_square(double n2) { return n2 >= 1e-150 && n2 <= 1e150; }

// Squared length and length of every edge of a cell, by node pair (both orders). Every
// edge serves two corner Jacobians, two faces and the aspect ratio, so its length is
// computed once. The square is the same number whichever way the edge is subtracted.
struct EdgeLengths {
  double n2[8][8];
  double len[8][8];
  // Every squared length is moderate_square (see SkewFloors).
  bool moderate = true;
};

constexpr std::array<int, 2> kTetEdges[] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr std::array<int, 2> kPyramidEdges[] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
constexpr std::array<int, 2> kWedgeEdges[] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5},
                                              {5, 3}, {0, 3}, {1, 4}, {2, 5}};
constexpr std::array<int, 2> kHexEdges[] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                            {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

template <std::size_t N>
void fill_edge_lengths(const std::array<int, 2> (&edges)[N], const Vec3* p, EdgeLengths* e) {
  for (const std::array<int, 2>& ab : edges) {
    const int a = ab[0], b = ab[1];
    const double n2 = norm2(p[b] - p[a]);
    const double len = std::sqrt(n2);
    e->n2[a][b] = e->n2[b][a] = n2;
    e->len[a][b] = e->len[b][a] = len;
    e->moderate &= moderate_square(n2);
  }
}

void fill_edge_lengths(CellType t, const Vec3* p, EdgeLengths* e) {
  switch (t) {
    case CellType::kTet: fill_edge_lengths(kTetEdges, p, e); break;
    case CellType::kPyramid: fill_edge_lengths(kPyramidEdges, p, e); break;
    case CellType::kWedge: fill_edge_lengths(kWedgeEdges, p, e); break;
    case CellType::kHex: fill_edge_lengths(kHexEdges, p, e); break;
  }
}

// det[e1,e2,e3] / (|e1||e2||e3|), 0 when an edge has zero length.
double normalized_jacobian(const Vec3& e1, const Vec3& e2, const Vec3& e3, double lengths) {
  return lengths > 0.0 ? triple(e1, e2, e3) / lengths : 0.0;
}

double normalized_jacobian(const Vec3& e1, const Vec3& e2, const Vec3& e3) {
  return normalized_jacobian(e1, e2, e3, norm(e1) * norm(e2) * norm(e3));
}

// The edge vectors are still subtracted at each corner, from the corner: the sign of a
// zero component (and so of a zero determinant) depends on the direction.
template <std::size_t N>
double min_corner_jacobian(const std::array<int, 4> (&corners)[N], const Vec3* p, const EdgeLengths& e) {
  double m = std::numeric_limits<double>::infinity();
  for (const std::array<int, 4>& c : corners) {
    const Vec3& o = p[c[0]];
    const double lengths = e.len[c[0]][c[1]] * e.len[c[0]][c[2]] * e.len[c[0]][c[3]];
    m = std::min(m, normalized_jacobian(p[c[1]] - o, p[c[2]] - o, p[c[3]] - o, lengths));
  }
  return m;
}

// A tet's corner determinants are all 6V; verdict divides by the largest product of
// corner edge lengths, which for a negative volume gives the value closest to zero.
double tet_jacobian(const Vec3* p, const EdgeLengths& e) {
  double largest = 0.0;
  for (const std::array<int, 4>& c : kTetCorners)
    largest = std::max(largest, e.len[c[0]][c[1]] * e.len[c[0]][c[2]] * e.len[c[0]][c[3]]);
  return largest > 0.0 ? triple(p[1] - p[0], p[2] - p[0], p[3] - p[0]) / largest : 0.0;
}

double hex_centre_jacobian(const Vec3* p) {
  const Vec3 x1 = (p[1] - p[0]) + (p[2] - p[3]) + (p[5] - p[4]) + (p[6] - p[7]);
  const Vec3 x2 = (p[3] - p[0]) + (p[2] - p[1]) + (p[7] - p[4]) + (p[6] - p[5]);
  const Vec3 x3 = (p[4] - p[0]) + (p[5] - p[1]) + (p[6] - p[2]) + (p[7] - p[3]);
  return normalized_jacobian(x1, x2, x3);
}

double scaled_jacobian(CellType t, const Vec3* p, const EdgeLengths& e) {
  double j = 0.0;
  switch (t) {
    case CellType::kTet: j = std::sqrt(2.0) * tet_jacobian(p, e); break;
    case CellType::kPyramid: j = std::sqrt(2.0) * min_corner_jacobian(kPyramidCorners, p, e); break;
    case CellType::kWedge: j = 2.0 / std::sqrt(3.0) * min_corner_jacobian(kWedgeCorners, p, e); break;
    case CellType::kHex: j = std::min(min_corner_jacobian(kHexCorners, p, e), hex_centre_jacobian(p)); break;
  }
  return std::min(j, 1.0);
}

// Cosine of the angle between a and b from their squared lengths; both must be non-zero.
double cosine(const Vec3& a, double a_n2, const Vec3& b, double b_n2) {
  return dot(a, b) / std::sqrt(a_n2 * b_n2);
}

// cos |cos| of the angle between a and b (squared lengths a_n2, b_n2, both non-zero):
// an increasing function of the cosine, so it picks the same extreme pairs without a
// square root per pair (the cosines' square roots were most of a hex's metrics; only
// the picked pairs' cosines or angles are then computed). dot |dot| / (a_n2 b_n2)
// neither overflows nor underflows to a zero denominator for squared lengths in
// [1e-150, 1e150]; others square the cosine. The rounded key and the rounded cosine
// can order two pairs differently only where their cosines agree to a few units in the
// last place: angles near 0 closer than about 1e-8 radians, which neither resolves.
double cosine_key(const Vec3& a, double a_n2, const Vec3& b, double b_n2) {
  if (!moderate_square(a_n2) || !moderate_square(b_n2)) {
    const double c = cosine(a, a_n2, b, b_n2);
    return c * std::fabs(c);
  }
  const double d = dot(a, b);
  return d * std::fabs(d) / (a_n2 * b_n2);
}

// The two edge vectors at each corner of a face (n = 3 or 4 nodes): u[i] to the
// previous node, w[i] to the next, both subtracted from the corner; n2[i] is the squared
// length of edge i -> i + 1, so that of u[i] is n2[i - 1] and that of w[i] is n2[i].
struct FaceCorners {
  int n;
  Vec3 u[4], w[4];
  double n2[4];
};

// Tables instead of the modulo: the node before and after each corner.
constexpr int kPrev[2][4] = {{2, 0, 1, -1}, {3, 0, 1, 2}};
constexpr int kNext[2][4] = {{1, 2, 0, -1}, {1, 2, 3, 0}};

void fill_face_corners(const Vec3* p, const detail::FaceDef& f, const EdgeLengths& e, FaceCorners* fc) {
  fc->n = f.n;
  const int* prev = kPrev[f.n - 3];
  const int* next = kNext[f.n - 3];
  for (int i = 0; i < f.n; ++i) {
    const Vec3& b = p[f.v[i]];
    fc->u[i] = p[f.v[prev[i]]] - b;
    fc->w[i] = p[f.v[next[i]]] - b;
    fc->n2[i] = e.n2[f.v[i]][f.v[next[i]]];
  }
}

bool collapsed(const FaceCorners& fc) {
  for (int i = 0; i < fc.n; ++i)
    if (fc.n2[i] == 0.0) return true;
  return false;
}

// The corners of a face with the smallest and the largest angle, picked by cosine.
struct FaceExtremes {
  int i_lo = 0, i_hi = 0;
  double cos_lo = -2.0, cos_hi = 2.0;  // cosine of the smallest / largest angle
};

FaceExtremes face_extremes(const FaceCorners& fc) {
  FaceExtremes x;
  const int* prev = kPrev[fc.n - 3];
  auto corner_cosine = [&](int i) { return cosine(fc.u[i], fc.n2[prev[i]], fc.w[i], fc.n2[i]); };
  if (fc.n == 3) {
    for (int i = 0; i < 3; ++i) {
      const double c = corner_cosine(i);
      if (c > x.cos_lo) x.cos_lo = c, x.i_lo = i;
      if (c < x.cos_hi) x.cos_hi = c, x.i_hi = i;
    }
    return x;
  }
  // A quad's two extreme corners by cosine_key, then their cosines: two square roots
  // instead of four (a triangle's three cosines cost less than three keys and two).
  double key_lo = -2.0, key_hi = 2.0;
  for (int i = 0; i < fc.n; ++i) {
    const double k = cosine_key(fc.u[i], fc.n2[prev[i]], fc.w[i], fc.n2[i]);
    if (k > key_lo) key_lo = k, x.i_lo = i;
    if (k < key_hi) key_hi = k, x.i_hi = i;
  }
  x.cos_lo = corner_cosine(x.i_lo);
  x.cos_hi = x.i_hi == x.i_lo ? x.cos_lo : corner_cosine(x.i_hi);
  return x;
}

// A face's skewness is the larger of two candidates: the largest angle's excess over
// the ideal and the smallest angle's deficit. Each is an increasing function of a
// cosine key (cos_lo for the smallest angle, -cos_hi for the largest) that grows at
// least 3/(2 pi) times as fast as the key: asin over 90 degrees for both candidates of
// a quad; over 120 and 60 degrees for a triangle's largest and smallest angle. A
// candidate whose key trails the best key of its kind by 1e-9 is therefore smaller by
// more than 4e-10, while the computed cosines and atan2 angles are within 1e-14 of
// those of the computed edge vectors when the edge lengths are moderate
// (EdgeLengths::moderate): it cannot be the cell's maximum, and leaving out its atan2
// leaves the result the same number. Floors of -inf keep every candidate.
struct SkewFloors {
  double quad = -std::numeric_limits<double>::infinity();
  double tri_lo = -std::numeric_limits<double>::infinity();
  double tri_hi = -std::numeric_limits<double>::infinity();
};

SkewFloors skew_floors(const FaceCorners* fc, const FaceExtremes* x, const int* faces, int n_faces) {
  constexpr double kKeyMargin = 1e-9;
  SkewFloors floors;
  for (int k = 0; k < n_faces; ++k) {
    const FaceExtremes& e = x[faces[k]];
    if (fc[faces[k]].n == 4) {
      floors.quad = std::max({floors.quad, e.cos_lo - kKeyMargin, -e.cos_hi - kKeyMargin});
    } else {
      floors.tri_lo = std::max(floors.tri_lo, e.cos_lo - kKeyMargin);
      floors.tri_hi = std::max(floors.tri_hi, -e.cos_hi - kKeyMargin);
    }
  }
  return floors;
}

// Equiangle skewness of a face from the angles at its extreme corners (atan2, accurate
// near 0 and 180), leaving out a candidate below its floor.
double face_skewness(const FaceCorners& fc, const FaceExtremes& x, const SkewFloors& floors) {
  const bool quad = fc.n == 4;
  const double ideal = quad ? 90.0 : 60.0;
  const auto degrees_at = [&fc](int i) { return angle_between(fc.u[i], fc.w[i]) * kRadToDeg; };
  // A left-out candidate stays -inf and loses std::max to the other (0 after the clamp
  // if both are left out).
  double deficit = -std::numeric_limits<double>::infinity(), excess = deficit;
  const bool want_lo = x.cos_lo >= (quad ? floors.quad : floors.tri_lo);
  const bool want_hi = -x.cos_hi >= (quad ? floors.quad : floors.tri_hi);
  const double lo = want_lo ? degrees_at(x.i_lo) : 0.0;
  if (want_lo) deficit = (ideal - lo) / ideal;
  if (want_hi) {
    // Equal cosines at every corner (a rectangle) pick the same corner twice.
    const double hi = want_lo && x.i_hi == x.i_lo ? lo : degrees_at(x.i_hi);
    excess = (hi - ideal) / (180.0 - ideal);
  }
  return std::clamp(std::max(excess, deficit), 0.0, 1.0);
}

// Largest skewness over the listed faces. A collapsed face (zero-length edge, never
// with moderate edges) scores 1, the largest value any face can have.
double cell_skewness(const FaceCorners* fc, const int* faces, int n_faces, bool moderate_edges) {
  if (!moderate_edges)
    for (int k = 0; k < n_faces; ++k)
      if (collapsed(fc[faces[k]])) return 1.0;
  FaceExtremes x[6];
  for (int k = 0; k < n_faces; ++k) x[faces[k]] = face_extremes(fc[faces[k]]);
  const SkewFloors floors = moderate_edges ? skew_floors(fc, x, faces, n_faces) : SkewFloors{};
  double skew = 0.0;
  for (int k = 0; k < n_faces; ++k) skew = std::max(skew, face_skewness(fc[faces[k]], x[faces[k]], floors));
  return skew;
}

// Tracks the largest angle over vector pairs by cosine (cosine_key); one atan2 at the
// end. A pair with a zero vector has no angle and is skipped. x_n2, y_n2: squared
// lengths.
struct LargestAngle {
  double key = 2.0;  // above every key: no pair yet
  Vec3 a{}, b{};
  void add(const Vec3& x, double x_n2, const Vec3& y, double y_n2) {
    if (x_n2 == 0.0 || y_n2 == 0.0) return;
    const double k = cosine_key(x, x_n2, y, y_n2);
    if (k < key) key = k, a = x, b = y;
  }
  void add(const Vec3& x, const Vec3& y) { add(x, norm2(x), y, norm2(y)); }
  double degrees() const { return key > 1.5 ? 0.0 : angle_between(a, b) * kRadToDeg; }
};

// Both diagonal splits of quad (a,b,c,d): the pairs of triangle normals. The face's
// corner vectors give b - a, d - a (corner a) and c - b, a - b (corner b).
void add_quad_warp(const Vec3* p, const detail::FaceDef& f, const FaceCorners& fc, LargestAngle* warp) {
  const Vec3 ca = p[f.v[2]] - p[f.v[0]];
  const Vec3 db = p[f.v[3]] - p[f.v[1]];
  warp->add(cross(fc.w[0], ca), cross(ca, fc.u[0]));
  warp->add(cross(fc.w[1], db), cross(db, fc.u[1]));
}

double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return triple(b - a, c - a, d - a) / 6.0;
}

// det J of the trilinear wedge map at triangle barycentre and height parameter z in
// [0,1]: the integrand is linear in the triangle coordinates and quadratic in z, so the
// centroid rule times two-point Gauss in z is exact.
double wedge_volume(const Vec3* p) {
  const double g = 0.5 / std::sqrt(3.0);
  double v = 0.0;
  for (double z : {0.5 - g, 0.5 + g}) {
    // Position x(r,s,z) = (1-z) * B(r,s) + z * T(r,s), B and T linear on the caps with
    // vertex 0 at (r,s) = (0,0), vertex 1 at (1,0), vertex 2 at (0,1).
    const Vec3 dr = (1.0 - z) * (p[1] - p[0]) + z * (p[4] - p[3]);
    const Vec3 ds = (1.0 - z) * (p[2] - p[0]) + z * (p[5] - p[3]);
    const Vec3 dz = ((p[3] + p[4] + p[5]) - (p[0] + p[1] + p[2])) / 3.0;
    // The VTK wedge's base winding points away from the top, so (dr, ds, dz) is
    // left-handed in a valid wedge: negate.
    v += -triple(dr, ds, dz) * 0.5 * 0.5;  // reference triangle area 1/2, Gauss weight 1/2
  }
  return v;
}

// Trilinear hex: det J has degree 2 in each coordinate, so 2x2x2 Gauss is exact.
double hex_volume(const Vec3* p) {
  const double g = 0.5 / std::sqrt(3.0);
  const double q[2] = {0.5 - g, 0.5 + g};
  double v = 0.0;
  for (double r : q)
    for (double s : q)
      for (double t : q) {
        // Nodes 0..3 on t = 0 counter-clockwise from (0,0), 4..7 above them.
        const Vec3 dr = (1 - s) * (1 - t) * (p[1] - p[0]) + s * (1 - t) * (p[2] - p[3]) +
                        (1 - s) * t * (p[5] - p[4]) + s * t * (p[6] - p[7]);
        const Vec3 ds = (1 - r) * (1 - t) * (p[3] - p[0]) + r * (1 - t) * (p[2] - p[1]) +
                        (1 - r) * t * (p[7] - p[4]) + r * t * (p[6] - p[5]);
        const Vec3 dt = (1 - r) * (1 - s) * (p[4] - p[0]) + r * (1 - s) * (p[5] - p[1]) +
                        r * s * (p[6] - p[2]) + (1 - r) * s * (p[7] - p[3]);
        v += triple(dr, ds, dt) / 8.0;
      }
  return v;
}

double pyramid_volume(const Vec3* p) {
  const double split02 = tet_volume(p[0], p[1], p[2], p[4]) + tet_volume(p[0], p[2], p[3], p[4]);
  const double split13 = tet_volume(p[0], p[1], p[3], p[4]) + tet_volume(p[1], p[2], p[3], p[4]);
  return 0.5 * (split02 + split13);
}

// Unit normal of a cap (3 or 4 nodes in the given order), right-hand rule.
Vec3 cap_normal(const Vec3* p, const int* v, int n) {
  if (n == 3) return normalized(cross(p[v[1]] - p[v[0]], p[v[2]] - p[v[0]]));
  return normalized(cross(p[v[2]] - p[v[0]], p[v[3]] - p[v[1]]));
}

// Column metrics shared by wedges (n = 3) and hexes (n = 4). bottom/top list the cap
// nodes so that column edge i runs from bottom[i] to top[i] and the right-hand normal
// of both lists points from the bottom cap to the top cap.
void column_metrics(const Vec3* p, const int* bottom, const int* top, int n, const EdgeLengths& e,
                    CellMetrics* m) {
  const Vec3 n_bottom = cap_normal(p, bottom, n);
  const Vec3 n_top = cap_normal(p, top, n);
  const double n_bottom_n2 = norm2(n_bottom), n_top_n2 = norm2(n_top);
  const int* next = kNext[n - 3];
  double cap_edges = 0.0, column_edges = 0.0;
  LargestAngle worst;
  for (int i = 0; i < n; ++i) {
    cap_edges += e.len[bottom[i]][bottom[next[i]]] + e.len[top[i]][top[next[i]]];
    const Vec3 col = p[top[i]] - p[bottom[i]];
    const double col_n2 = e.n2[bottom[i]][top[i]];
    column_edges += e.len[bottom[i]][top[i]];
    worst.add(col, col_n2, n_bottom, n_bottom_n2);
    worst.add(col, col_n2, n_top, n_top_n2);
  }
  const double cap_mean = cap_edges / (2 * n), column_mean = column_edges / n;
  m->aspect_ratio = column_mean > 0.0 ? cap_mean / column_mean : std::numeric_limits<double>::infinity();
  m->orthogonality_deg = worst.degrees();
}

// Longest over shortest edge (a NaN length is skipped, as std::min/max do).
template <std::size_t N>
double edge_ratio(const std::array<int, 2> (&edges)[N], const EdgeLengths& e) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const std::array<int, 2>& ab : edges) {
    const double l = e.len[ab[0]][ab[1]];
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  return lo > 0.0 ? hi / lo : std::numeric_limits<double>::infinity();
}

}  // namespace

double cell_volume(CellType type, const Vec3* p) {
  switch (type) {
    case CellType::kTet: return tet_volume(p[0], p[1], p[2], p[3]);
    case CellType::kPyramid: return pyramid_volume(p);
    case CellType::kWedge: return wedge_volume(p);
    case CellType::kHex: return hex_volume(p);
  }
  return 0.0;
}

CellMetrics compute_cell_metrics(CellType type, const Vec3* p) {
  EdgeLengths e;
  fill_edge_lengths(type, p, &e);
  CellMetrics m;
  m.scaled_jacobian = scaled_jacobian(type, p, e);
  m.volume = cell_volume(type, p);

  const detail::CellFaces& cf = detail::cell_faces(type);
  FaceCorners fc[6];
  int skew_faces[6], n_skew = 0;
  LargestAngle warp;
  for (int f = 0; f < cf.n_faces; ++f) {
    const detail::FaceDef& fd = cf.faces[f];
    fill_face_corners(p, fd, e, &fc[f]);
    const bool is_cap = f == cf.bottom_cap || f == cf.top_cap;
    if (type != CellType::kWedge || is_cap) skew_faces[n_skew++] = f;
    if (fd.n == 4) add_quad_warp(p, fd, fc[f], &warp);
  }
  m.skewness = cell_skewness(fc, skew_faces, n_skew, e.moderate);
  m.twist_deg = warp.degrees();

  if (type == CellType::kWedge) {
    // (0,2,1) and (3,5,4) both have right-hand normals pointing bottom to top.
    static constexpr int kBottom[3] = {0, 2, 1};
    static constexpr int kTop[3] = {3, 5, 4};
    column_metrics(p, kBottom, kTop, 3, e, &m);
  } else if (type == CellType::kHex) {
    static constexpr int kBottom[4] = {0, 1, 2, 3};
    static constexpr int kTop[4] = {4, 5, 6, 7};
    column_metrics(p, kBottom, kTop, 4, e, &m);
  } else {
    m.aspect_ratio = type == CellType::kTet ? edge_ratio(kTetEdges, e) : edge_ratio(kPyramidEdges, e);
    m.orthogonality_deg = kNaN;
  }
  return m;
}

}  // namespace blayer
