#include "blayer/quality/cell_validity.h"

#include <algorithm>

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

Validity cell_validity(CellType type, const Vec3* corners) {
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
