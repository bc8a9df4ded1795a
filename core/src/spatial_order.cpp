#include "blayer/core/spatial_order.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace blayer {

namespace {

// Spreads the low 21 bits of v so that bit b lands on bit 3b (the usual magic-number
// interleave; a loop over the bits gives the same, in tests).
std::uint64_t spread_bits(std::uint32_t v) {
  std::uint64_t x = v & 0x1fffffu;
  x = (x | x << 32) & 0x001f00000000ffffull;
  x = (x | x << 16) & 0x001f0000ff0000ffull;
  x = (x | x << 8) & 0x100f00f00f00f00full;
  x = (x | x << 4) & 0x10c30c30c30c30c3ull;
  x = (x | x << 2) & 0x1249249249249249ull;
  return x;
}

}  // namespace

std::uint64_t morton_key(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  return spread_bits(x) | spread_bits(y) << 1 | spread_bits(z) << 2;
}

std::vector<int> morton_order(const std::vector<Vec3>& points) {
  const int n = static_cast<int>(points.size());
  if (points.empty()) return {};
  Vec3 lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  for (const Vec3& p : points)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  constexpr double kTopCell = (1u << kMortonBitsPerAxis) - 1;
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 0.0});
  const double scale = extent > 0.0 ? kTopCell / extent : 0.0;
  // Rounding can put (p - lo) * scale a hair above kTopCell at the top of the box: clamp.
  auto cell = [&](const Vec3& p, int a) {
    return static_cast<std::uint32_t>(std::min(kTopCell, (p[a] - lo[a]) * scale));
  };
  std::vector<std::pair<std::uint64_t, int>> keyed(n);
  for (int i = 0; i < n; ++i) keyed[i] = {morton_key(cell(points[i], 0), cell(points[i], 1), cell(points[i], 2)), i};
  std::sort(keyed.begin(), keyed.end());  // ties by index: the input order
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = keyed[i].second;
  return order;
}

}  // namespace blayer
