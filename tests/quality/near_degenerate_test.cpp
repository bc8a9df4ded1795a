// Near-degenerate prisms whose validity only exact arithmetic decides.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "blayer/quality/cell_validity.h"
#include "blayer/quality/orient3d.h"
#include "test_cells.h"

namespace blayer {
namespace {

using I128 = __int128;

// Exact sign of det[b-a, c-a, d-a] for integer-valued points whose differences stay
// below 2^42 (triple products below 2^126).
int exact_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  I128 u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    const auto ai = static_cast<std::int64_t>(a[i]);
    u[i] = static_cast<std::int64_t>(b[i]) - ai;
    v[i] = static_cast<std::int64_t>(c[i]) - ai;
    w[i] = static_cast<std::int64_t>(d[i]) - ai;
  }
  const I128 det = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                   u[2] * (v[0] * w[1] - v[1] * w[0]);
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

int double_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const double det = dot(b - a, cross(c - a, d - a));
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

// Classifies with a given sign function over the cell's validity tets: the corner tets
// decide inverted (one negative) and flat (one zero), the split tets twisted.
template <typename Sign>
Validity classify(const std::vector<Vec3>& p, Sign sign, CellType type = CellType::kWedge) {
  std::size_t n = 0;
  const std::array<int, 4>* tets = validity_tets(type, &n);
  const std::size_t n_corner = corner_tet_count(type);
  int corner_min = 1, split_min = 1;
  for (std::size_t i = 0; i < n; ++i) {
    const int s = sign(p[tets[i][0]], p[tets[i][1]], p[tets[i][2]], p[tets[i][3]]);
    int& m = i < n_corner ? corner_min : split_min;
    m = std::min(m, s);
  }
  if (corner_min < 0) return Validity::kInverted;
  if (corner_min == 0) return Validity::kFlat;
  return split_min <= 0 ? Validity::kTwisted : Validity::kValid;
}

// The reference cell of every type.
std::vector<std::pair<CellType, std::vector<Vec3>>> reference_cells() {
  return {{CellType::kTet, test::unit_tet()},
          {CellType::kPyramid, test::unit_pyramid()},
          {CellType::kWedge, test::right_prism()},
          {CellType::kHex, test::unit_hex()}};
}

// Both validity entry points give `expected` for the cell.
void expect_verdict(CellType type, const std::vector<Vec3>& cell, Validity expected, int trial) {
  ASSERT_EQ(cell_validity(type, cell.data()), expected) << "type " << static_cast<int>(type) << " trial " << trial;
  ASSERT_EQ(cell_is_valid(type, cell.data()), expected == Validity::kValid)
      << "type " << static_cast<int>(type) << " trial " << trial;
}

TEST(NearDegeneratePrism, RelativeHeightOneInTenToTheTwelveIsValidAndItsMirrorInverted) {
  // A tilted wall triangle far from the origin, extruded along its normal by 1e-12
  // times its edge length.
  const Vec3 o{1234.5678, -987.654321, 42.4242};
  const Vec3 a = o, b = o + Vec3{0.9, 0.3, 0.1}, c = o + Vec3{-0.2, 0.8, 0.4};
  const Vec3 n = normalized(cross(b - a, c - a));
  const Vec3 up = 1e-12 * norm(b - a) * n;
  const std::vector<Vec3> prism{a, c, b, a + up, c + up, b + up};
  ASSERT_NE(prism[3], prism[0]);  // the offset survives rounding at this magnitude
  EXPECT_EQ(cell_validity(CellType::kWedge, prism.data()), Validity::kValid);
  const std::vector<Vec3> down{a, c, b, a - up, c - up, b - up};
  EXPECT_EQ(cell_validity(CellType::kWedge, down.data()), Validity::kInverted);
}

// Random integers for lattice cells: base points up to 2^40 from the origin, edges and
// shears up to 2^20 and 2^19, single lattice steps.
struct LatticeDraws {
  explicit LatticeDraws(unsigned seed) : rng(seed) {}
  std::int64_t base() { return within(0, 40); }
  std::int64_t edge() { return within(-1, 20); }
  std::int64_t shear() { return within(-1, 19); }
  std::int64_t nudge() { return std::uniform_int_distribution<int>(-1, 1)(rng); }
  // Uniform in [lo * 2^bits, 2^bits] (lo is 0 or -1).
  std::int64_t within(int lo, int bits) {
    const std::int64_t m = std::int64_t{1} << bits;
    return std::uniform_int_distribution<std::int64_t>(lo * m, m)(rng);
  }
  std::mt19937_64 rng;
};

TEST(NearDegeneratePrism, ExactPredicatesClassifyLatticePrismsWhereDoublesFail) {
  // Caps of size ~2^20 sheared by ~2^39 along the wall plane and lifted off it by one
  // lattice step or not at all: relative heights near 1e-12 and below, with every
  // coordinate an exact integer so the true class is known from 128-bit arithmetic.
  LatticeDraws draw(2024);
  int double_wrong = 0;
  int by_class[4] = {0, 0, 0, 0};
  for (int trial = 0; trial < 3000; ++trial) {
    std::int64_t a[3], p[3], q[3];
    for (int i = 0; i < 3; ++i) a[i] = draw.base(), p[i] = draw.edge(), q[i] = draw.edge();
    const std::int64_t s = draw.shear(), t = draw.shear();
    std::int64_t lift[3];
    for (int i = 0; i < 3; ++i) lift[i] = s * p[i] + t * q[i];
    // Wall triangle (a, a+p, a+q) written (a, c, b) as VTK wants, top nodes the
    // lifted copies plus a random -1/0/+1 nudge per coordinate.
    const std::int64_t* offsets[3] = {nullptr, q, p};
    std::vector<Vec3> prism(6);
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) {
        const std::int64_t x = a[i] + (offsets[k] ? offsets[k][i] : 0);
        prism[k][i] = static_cast<double>(x);
        prism[k + 3][i] = static_cast<double>(x + lift[i] + draw.nudge());
      }
    const Validity exact = classify(prism, exact_sign);
    ASSERT_EQ(cell_validity(CellType::kWedge, prism.data()), exact) << "trial " << trial;
    ASSERT_EQ(prism_is_valid(prism.data()), exact == Validity::kValid) << "trial " << trial;
    ++by_class[static_cast<int>(exact)];
    if (classify(prism, double_sign) != exact) ++double_wrong;
  }
  // Meaningful only if all classes occur and plain doubles misclassify some prisms.
  EXPECT_GT(by_class[0], 0);
  EXPECT_GT(by_class[1], 0);
  EXPECT_GT(by_class[2], 0);
  EXPECT_GT(double_wrong, 0);
}

TEST(NearDegenerateCells, LatticeCellsOfEveryTypeGetTheExactVerdict) {
  // Each reference cell mapped onto a lattice: its (x, y) on two random edges of size
  // ~2^21 on a base ~2^40 from the origin, its height z lifted along a shear inside
  // that plane (so the top lies in the wall plane), then moved off it by one lattice
  // step of -1, 0 or +1 per coordinate, shared by the upper nodes (an affine image of
  // the cell: valid, flat or inverted as a whole), in every other trial plus a step of
  // each node's own (twisted cells, mixed verdicts). Integer coordinates keep the
  // 128-bit oracle exact; the verdicts hang on single lattice steps.
  LatticeDraws draw(7);
  for (const auto& [type, ref] : reference_cells()) {
    int by_class[4] = {0, 0, 0, 0};
    for (int trial = 0; trial < 2000; ++trial) {
      std::int64_t a[3], p[3], q[3];
      // Even edges: the pyramid's apex at (1/2, 1/2) stays on the lattice.
      for (int i = 0; i < 3; ++i) a[i] = draw.base(), p[i] = 2 * draw.edge(), q[i] = 2 * draw.edge();
      const std::int64_t s = draw.shear(), t = draw.shear();
      const std::int64_t shared[3] = {draw.nudge(), draw.nudge(), draw.nudge()};
      std::vector<Vec3> cell(ref.size());
      for (std::size_t k = 0; k < ref.size(); ++k) {
        const Vec3& r = ref[k];
        for (int i = 0; i < 3; ++i) {
          const auto x = static_cast<std::int64_t>(r[0] * static_cast<double>(p[i]) + r[1] * static_cast<double>(q[i]));
          const std::int64_t own = trial % 2 ? draw.nudge() : 0;
          const std::int64_t up = r[2] > 0.0 ? s * p[i] + t * q[i] + shared[i] + own : 0;
          cell[k][i] = static_cast<double>(a[i] + x + up);
        }
      }
      const Validity exact = classify(cell, exact_sign, type);
      ASSERT_NO_FATAL_FAILURE(expect_verdict(type, cell, exact, trial));
      ++by_class[static_cast<int>(exact)];
    }
    // Meaningful only if the lattice steps produce valid, flat and inverted cells.
    EXPECT_GT(by_class[static_cast<int>(Validity::kValid)], 0) << static_cast<int>(type);
    EXPECT_GT(by_class[static_cast<int>(Validity::kFlat)], 0) << static_cast<int>(type);
    EXPECT_GT(by_class[static_cast<int>(Validity::kInverted)], 0) << static_cast<int>(type);
  }
}

TEST(NearDegenerateCells, DistortedCellsOfEveryTypeGetTheVerdictOfTheirTetSigns) {
  // Each reference cell scaled, moved far from the origin and squashed to a thin layer
  // cell, with every node moved at random by up to `spread` of the cell: small spreads
  // leave it valid (the cell-wide bound decides those), large ones twist, flatten and
  // invert it in every pattern of tet signs. The verdicts must be those of the validity
  // tets' exact signs taken one by one.
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const auto& [type, ref] : reference_cells()) {
    int by_class[4] = {0, 0, 0, 0};
    for (int trial = 0; trial < 20000; ++trial) {
      const double spread = std::pow(10.0, -6.0 + 6.0 * (trial % 100) / 100.0);
      const double height = std::pow(10.0, -4.0 * (trial % 7) / 6.0);
      const Vec3 origin{1e3 * unit(rng), 1e3 * unit(rng), 1e3 * unit(rng)};
      std::vector<Vec3> cell(ref.size());
      for (std::size_t k = 0; k < ref.size(); ++k) {
        const Vec3 r{ref[k][0], ref[k][1], ref[k][2] * height};
        cell[k] = origin + 0.1 * r + 0.1 * spread * Vec3{unit(rng), unit(rng), unit(rng)};
      }
      const Validity expected = classify(cell, orient3d_sign, type);
      ASSERT_NO_FATAL_FAILURE(expect_verdict(type, cell, expected, trial));
      ++by_class[static_cast<int>(expected)];
    }
    // Meaningful only if both valid cells and failing ones occur (a tet has no split to
    // twist, and flat cells need exact coincidences).
    EXPECT_GT(by_class[static_cast<int>(Validity::kValid)], 1000) << static_cast<int>(type);
    EXPECT_GT(by_class[static_cast<int>(Validity::kInverted)], 1000) << static_cast<int>(type);
    if (type == CellType::kWedge || type == CellType::kHex) {
      EXPECT_GT(by_class[static_cast<int>(Validity::kTwisted)], 100) << static_cast<int>(type);
    }
  }
}

}  // namespace
}  // namespace blayer
