#include "blayer/quality/cell_validity.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "blayer/quality/filtered_orient3d.h"

namespace blayer {

namespace {

constexpr std::array<int, 4> kTetTets[] = {{0, 1, 2, 3}};

constexpr std::array<int, 4> kPyramidTets[] = {
    {0, 1, 2, 4}, {0, 2, 3, 4}, {0, 1, 3, 4}, {1, 2, 3, 4}};

// Base node i of the wedge has the cap neighbours next (i+1) and prev (i+2); the base
// normal points away from the top, so (i, prev, next, i+3) is positive. The top cap has
// the same winding, its normal points toward the base: (3+i, 3+next, 3+prev, i).
// Cap-edge tets: base edge (i, next) with top nodes (i+3, prev+3) and (next+3, prev+3).
constexpr std::array<int, 4> kWedgeTets[] = {
    {0, 2, 1, 3}, {1, 0, 2, 4}, {2, 1, 0, 5},  // base corners
    {3, 4, 5, 0}, {4, 5, 3, 1}, {5, 3, 4, 2},  // top corners
    {0, 1, 3, 5}, {0, 1, 4, 5},                // base edge 0-1
    {1, 2, 4, 3}, {1, 2, 5, 3},                // base edge 1-2
    {2, 0, 5, 4}, {2, 0, 3, 4}};               // base edge 2-0

// Every tet spanned by four hex nodes that do not lie on one face or one diagonal
// plane of the reference cube, oriented positive in it: 58, the corner tets first
// (base node i: (i, next, prev, i+4); top node 4+i: (4+i, 4+prev, 4+next, i)), then the
// others in lexicographic order.
constexpr int kHexTetCount = 58;
std::array<std::array<int, 4>, kHexTetCount> make_hex_tets() {
  constexpr int cube[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  auto det = [&](const std::array<int, 4>& t) {
    int e[3][3];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) e[r][k] = cube[t[r + 1]][k] - cube[t[0]][k];
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  };
  std::array<std::array<int, 4>, kHexTetCount> out{};
  const std::array<std::array<int, 4>, 8> corners = {{{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                                       {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}}};
  int n = 0;
  for (const auto& c : corners) out[n++] = c;
  auto is_corner = [&](std::array<int, 4> t) {
    std::sort(t.begin(), t.end());
    for (std::array<int, 4> c : corners) {
      std::sort(c.begin(), c.end());
      if (c == t) return true;
    }
    return false;
  };
  for (int a = 0; a < 8; ++a)
    for (int b = a + 1; b < 8; ++b)
      for (int c = b + 1; c < 8; ++c)
        for (int d = c + 1; d < 8; ++d) {
          std::array<int, 4> t{a, b, c, d};
          const int v = det(t);
          if (v == 0 || is_corner(t)) continue;
          if (v < 0) std::swap(t[2], t[3]);
          out[n++] = t;
        }
  return out;
}
const std::array<std::array<int, 4>, kHexTetCount> kHexTets = make_hex_tets();

template <std::size_t N>
const std::array<int, 4>* with_count(const std::array<int, 4> (&tets)[N], std::size_t* count) {
  *count = N;
  return tets;
}

}  // namespace

const std::array<int, 4>* validity_tets(CellType type, std::size_t* count) {
  switch (type) {
    case CellType::kTet: return with_count(kTetTets, count);
    case CellType::kPyramid: return with_count(kPyramidTets, count);
    case CellType::kWedge: return with_count(kWedgeTets, count);
    case CellType::kHex:
      *count = kHexTets.size();
      return kHexTets.data();
  }
  *count = 0;
  return nullptr;
}

std::size_t corner_tet_count(CellType type) {
  switch (type) {
    case CellType::kTet: return 1;
    case CellType::kPyramid: return 4;
    case CellType::kWedge: return 6;
    case CellType::kHex: return 8;
  }
  return 0;
}

namespace {

// The validity tets as planes and points: det[b - a, c - a, q - a] for the several tets
// (a, b, c, q) on one plane shares its 2x2 minors, so a cell's determinants cost about
// half as much as separate orientations. A greedy cover takes the triangle held by the
// most tets not yet covered: the 58 hex tets need 17 planes, the 12 wedge tets 4, the 4
// pyramid tets 2.
struct TetOnPlane {
  int plane;      // index into the planes
  int a;          // the plane's first node (read per tet: one indirection less)
  int q;          // the tet's fourth node
  double parity;  // +1 or -1: the tet's orientation is parity * det[b - a, c - a, q - a]
};
struct PlaneCover {
  std::vector<std::array<int, 3>> planes;
  std::vector<TetOnPlane> tets;
};

bool holds(const std::array<int, 4>& t, int node) { return std::find(t.begin(), t.end(), node) != t.end(); }

bool holds_plane(const std::array<int, 4>& t, const std::array<int, 3>& plane) {
  return holds(t, plane[0]) && holds(t, plane[1]) && holds(t, plane[2]);
}

// The parity of the permutation taking tet t to (plane[0], plane[1], plane[2], q).
double permutation_parity(const std::array<int, 4>& t, const std::array<int, 3>& plane, int q) {
  const std::array<int, 4> to{plane[0], plane[1], plane[2], q};
  long pos[4];
  for (int i = 0; i < 4; ++i) pos[i] = std::find(t.begin(), t.end(), to[i]) - t.begin();
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) inversions += pos[i] > pos[j];
  return inversions % 2 ? -1.0 : 1.0;
}

PlaneCover cover_by_planes(CellType type) {
  std::size_t n = 0;
  const std::array<int, 4>* tets = validity_tets(type, &n);
  std::vector<bool> covered(n, false);
  PlaneCover cover;
  for (std::size_t left = n; left > 0;) {
    std::array<int, 3> best{};
    std::size_t best_count = 0;
    for (int a = 0; a < 8; ++a)
      for (int b = a + 1; b < 8; ++b)
        for (int c = b + 1; c < 8; ++c) {
          std::size_t count = 0;
          for (std::size_t i = 0; i < n; ++i) count += !covered[i] && holds_plane(tets[i], {a, b, c});
          if (count > best_count) best = {a, b, c}, best_count = count;
        }
    const int plane = static_cast<int>(cover.planes.size());
    cover.planes.push_back(best);
    for (std::size_t i = 0; i < n; ++i) {
      if (covered[i] || !holds_plane(tets[i], best)) continue;
      int q = 0;
      for (int node : tets[i])
        if (node != best[0] && node != best[1] && node != best[2]) q = node;
      cover.tets.push_back({plane, best[0], q, permutation_parity(tets[i], best, q)});
      covered[i] = true;
      --left;
    }
  }
  return cover;
}

const PlaneCover& plane_cover(CellType type) {
  static const PlaneCover kCovers[4] = {cover_by_planes(CellType::kTet), cover_by_planes(CellType::kPyramid),
                                        cover_by_planes(CellType::kWedge), cover_by_planes(CellType::kHex)};
  switch (type) {
    case CellType::kTet: return kCovers[0];
    case CellType::kPyramid: return kCovers[1];
    case CellType::kWedge: return kCovers[2];
    case CellType::kHex: break;
  }
  return kCovers[3];
}

// A threshold above the rounding error of every determinant certainly_valid evaluates,
// or -1 when the cell's extent is out of the range this argument covers. Each is
// det[b - a, c - a, q - a] evaluated as orient3d_sides does, whose rounding error is
// below kOrient3dErrBound times its computed permanent (filtered_orient3d.h). Rounding
// is monotone, so every rounded difference of two nodes along axis k is at most
// D_k = fl(max_k - min_k): the exact permanent of the rounded differences is at most
// 6 D_0 D_1 D_2 and the computed one at most (1 + eps)^4 times that. With every D_k in
// [1e-100, 1e100] no product here underflows, and the factor 1 + 1e-14 covers the
// (1 + eps)^7 of both roundings: U is above every computed permanent. The threshold
// then adds kUnderflowSlack for the determinants' own underflowing products, as the
// per-tet filter does.
double cell_threshold(const Vec3* p, int n_nodes) {
  Vec3 lo = p[0], hi = p[0];
  for (int i = 1; i < n_nodes; ++i)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[i][k]);
      hi[k] = std::max(hi[k], p[i][k]);
    }
  const Vec3 d = hi - lo;
  for (int k = 0; k < 3; ++k)
    if (!(d[k] >= 1e-100 && d[k] <= detail::kMaxDifference)) return -1.0;
  const double u = 6.0 * d[0] * d[1] * d[2] * (1.0 + 1e-14);
  if (!(u >= 1e-200 && u <= 1e200)) return -1.0;
  return detail::kOrient3dErrBound * u + detail::kUnderflowSlack;
}

// Whether every validity tet is positive by a margin that one bound for the whole cell
// certifies: a boundary-layer cell of relative height h has determinants near h times
// its extent cubed, many orders above the bound. False means "not certified": the
// per-tet filter and the exact predicate decide then.
bool certainly_valid(CellType type, const Vec3* p) {
  const double threshold = cell_threshold(p, corner_count(type));
  if (threshold < 0.0) return false;
  const PlaneCover& cover = plane_cover(type);
  // cross and dot evaluate the minors and the expansion in orient3d_sides' order.
  Vec3 minors[kHexTetCount];
  for (std::size_t i = 0; i < cover.planes.size(); ++i) {
    const Vec3& a = p[cover.planes[i][0]];
    minors[i] = cross(p[cover.planes[i][1]] - a, p[cover.planes[i][2]] - a);
  }
  double lowest = std::numeric_limits<double>::infinity();
  for (const TetOnPlane& t : cover.tets) lowest = std::min(lowest, t.parity * dot(p[t.q] - p[t.a], minors[t.plane]));
  return lowest > threshold;
}

}  // namespace

Validity cell_validity(CellType type, const Vec3* corners) {
  if (certainly_valid(type, corners)) return Validity::kValid;
  std::size_t n = 0;
  const std::array<int, 4>* tets = validity_tets(type, &n);
  const std::size_t n_corner = corner_tet_count(type);
  bool flat = false, split_fails = false;
  // The corner tets come first, so every corner is decided before any split tet.
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<int, 4>& t = tets[i];
    const int s = detail::orient3d_filtered(corners[t[0]], corners[t[1]], corners[t[2]], corners[t[3]]);
    if (i < n_corner) {
      if (s < 0) return Validity::kInverted;
      if (s == 0) flat = true;
    } else if (s <= 0) {
      split_fails = true;
    }
  }
  if (flat) return Validity::kFlat;
  return split_fails ? Validity::kTwisted : Validity::kValid;
}

bool cell_is_valid(CellType type, const Vec3* corners) {
  if (certainly_valid(type, corners)) return true;
  std::size_t n = 0;
  const std::array<int, 4>* tets = validity_tets(type, &n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<int, 4>& t = tets[i];
    if (detail::orient3d_filtered(corners[t[0]], corners[t[1]], corners[t[2]], corners[t[3]]) <= 0) return false;
  }
  return true;
}

bool prism_is_valid(const Vec3 corners[6]) { return cell_is_valid(CellType::kWedge, corners); }

}  // namespace blayer
