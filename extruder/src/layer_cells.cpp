#include "blayer/extruder/layer_cells.h"

#include <algorithm>
#include <limits>

namespace blayer {

bool layer_cell(const std::array<std::int64_t, 3>& bottom, const std::array<std::int64_t, 3>& top,
                const std::array<bool, 3>& grows, LayerCell* out) {
  const int n_grow = int(grows[0]) + int(grows[1]) + int(grows[2]);
  if (n_grow == 3) {
    out->type = CellType::kWedge;
    out->nodes = {bottom[0], bottom[2], bottom[1], top[0], top[2], top[1]};
    return true;
  }
  if (n_grow == 2) {
    const int x = !grows[0] ? 0 : (!grows[1] ? 1 : 2);
    const int y = (x + 1) % 3, z = (x + 2) % 3;
    out->type = CellType::kPyramid;
    out->nodes = {bottom[y], top[y], top[z], bottom[z], bottom[x], 0};
    return true;
  }
  if (n_grow == 1) {
    const int z = grows[0] ? 0 : (grows[1] ? 1 : 2);
    const int x = (z + 1) % 3, y = (z + 2) % 3;
    out->type = CellType::kTet;
    out->nodes = {bottom[x], bottom[y], bottom[z], top[z], 0, 0};
    return true;
  }
  return false;
}

namespace {

struct CornerEdges {
  int corner, e1, e2, e3;
};

// Right-handed edge triples per corner, derived from the VTK orientation conventions:
// tet (0,1,2) faces node 3; pyramid base (0,1,2,3) faces the apex; wedge cap (0,1,2)
// faces away from (3,4,5).
constexpr CornerEdges kTetCorners[] = {{0, 1, 2, 3}, {1, 2, 0, 3}, {2, 0, 1, 3}, {3, 0, 2, 1}};
constexpr CornerEdges kPyramidCorners[] = {{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}};
constexpr CornerEdges kWedgeCorners[] = {{0, 2, 1, 3}, {1, 0, 2, 4}, {2, 1, 0, 5},
                                         {3, 4, 5, 0}, {4, 5, 3, 1}, {5, 3, 4, 2}};

double corner_value(const Vec3* p, const CornerEdges& c) {
  const Vec3 a = p[c.e1] - p[c.corner], b = p[c.e2] - p[c.corner], d = p[c.e3] - p[c.corner];
  const double l = norm(a) * norm(b) * norm(d);
  if (!(l > 0.0)) return 0.0;
  return dot(cross(a, b), d) / l;
}

template <std::size_t N>
double min_over(const Vec3* p, const CornerEdges (&table)[N]) {
  double m = std::numeric_limits<double>::infinity();
  for (const CornerEdges& c : table) m = std::min(m, corner_value(p, c));
  return m;
}

}  // namespace

double min_corner_scaled_jacobian(CellType type, const Vec3* corners) {
  switch (type) {
    case CellType::kTet: return min_over(corners, kTetCorners);
    case CellType::kPyramid: return min_over(corners, kPyramidCorners);
    case CellType::kWedge: return min_over(corners, kWedgeCorners);
    case CellType::kHex: break;
  }
  return 0.0;
}

}  // namespace blayer
