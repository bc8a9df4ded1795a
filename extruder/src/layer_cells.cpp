#include "blayer/extruder/layer_cells.h"


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

// Strip (q0 q1 q2 q3) whose first fan point (q0 q1) grows and whose second (q2 q3) is
// stopped.
void strip_closure(const std::array<std::int64_t, 4>& b, const std::array<std::int64_t, 4>& t, LayerCell* out) {
  if (b[0] == b[1]) {
    out->type = CellType::kTet;
    out->nodes = {b[0], t[0], t[1], b[2], 0, 0};
  } else {
    out->type = CellType::kWedge;
    out->nodes = {b[1], b[2], t[1], b[0], b[3], t[0]};
  }
}

}  // namespace

bool element_layer_cell(const LayerElement& e, const std::array<std::int64_t, 4>& bottom,
                        const std::array<std::int64_t, 4>& top, const std::array<bool, 4>& grows, LayerCell* out) {
  if (e.kind == ElementKind::kTriangle) {
    if (bottom[0] == bottom[1] && bottom[1] == bottom[2]) {
      if (!grows[0]) return false;
      out->type = CellType::kTet;
      out->nodes = {top[0], top[2], top[1], bottom[0], 0, 0};
      return true;
    }
    return layer_cell({bottom[0], bottom[1], bottom[2]}, {top[0], top[1], top[2]}, {grows[0], grows[1], grows[2]},
                      out);
  }
  const bool gx = grows[0], gy = grows[2];
  if (gx && gy) {
    if (bottom[0] == bottom[1]) {
      out->type = CellType::kWedge;
      out->nodes = {bottom[0], top[1], top[0], bottom[2], top[2], top[3]};
    } else {
      out->type = CellType::kHex;
      std::copy(bottom.begin(), bottom.end(), out->nodes.begin());
      out->nodes[4] = top[0];
      out->nodes[5] = top[1];
      out->nodes[6] = top[2];
      out->nodes[7] = top[3];
    }
    return true;
  }
  if (gx) {
    strip_closure(bottom, top, out);
    return true;
  }
  if (gy) {
    strip_closure({bottom[2], bottom[3], bottom[0], bottom[1]}, {top[2], top[3], top[0], top[1]}, out);
    return true;
  }
  return false;
}

}  // namespace blayer
