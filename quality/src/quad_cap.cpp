#include "blayer/quality/quad_cap.h"

#include <algorithm>

#include "blayer/quality/cell_validity.h"

namespace blayer {

namespace {

// Heights of the apex over the quad's centre, in multiples of half its shortest edge,
// in the order tried: that height, then lower (every quad capped so far gets the apex
// it always got); then higher, for a twisted quad whose halves tilt apart (on a thin
// fan strip's top, 0.24e-3 wide at one end and 2.1e-3 at the other, half the shortest
// edge and lower were too low, the shortest edge enough).
constexpr double kCapHeights[] = {1, 0.5, 0.25, 0.125, 0.0625, 2, 4, 8, 16, 32};

}  // namespace

std::optional<Vec3> quad_cap_apex(const std::array<Vec3, 4>& q_in) {
  // Start at the lexicographically smallest corner: the same quad read from another
  // corner sums its centre and normal in the same order, to the same bits.
  const int first = static_cast<int>(std::min_element(q_in.begin(), q_in.end()) - q_in.begin());
  std::array<Vec3, 4> q;
  for (int i = 0; i < 4; ++i) q[i] = q_in[(first + i) % 4];
  Vec3 centre{0, 0, 0}, normal{0, 0, 0};
  double shortest = 1e300, longest = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Vec3& a = q[i];
    const Vec3& b = q[(i + 1) % 4];
    centre = centre + 0.25 * a;
    normal = normal + cross(a, b);  // Newell
    shortest = std::min(shortest, norm(b - a));
    longest = std::max(longest, norm(b - a));
  }
  normal = normalized(normal);
  for (const double m : kCapHeights) {
    const double d = m * 0.5 * shortest;
    if (d > longest) continue;
    const Vec3 apex = centre + d * normal;
    const Vec3 corners[5] = {q[0], q[1], q[2], q[3], apex};
    if (cell_is_valid(CellType::kPyramid, corners)) return apex;
  }
  return std::nullopt;
}

}  // namespace blayer
